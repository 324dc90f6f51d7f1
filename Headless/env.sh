# Sourced by the headless scripts: installs what is missing, then sets the environment they share.
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
"$root/Headless/install-deps.sh"

# No GPU needed: pin the Vulkan loader to lavapipe unless the caller chose a driver.
if [ -z "${VK_DRIVER_FILES:-}${VK_ICD_FILENAMES:-}${VK_LOADER_DRIVERS_SELECT:-}" ]; then
    export VK_LOADER_DRIVERS_SELECT='*lvp*'
fi
export DOTNET_CLI_TELEMETRY_OPTOUT=1 DOTNET_NOLOGO=1 DOTNET_SKIP_FIRST_TIME_EXPERIENCE=1
