#!/usr/bin/env bash
# Simulates a Unity scene file headlessly (the README's first command). Without arguments: the default
# oil-and-water scene for its default duration, frames and diagnostics into Output/OilAndWater/.
# With arguments: they go to `sphfluid simulate` as they are (see --help), e.g.
#   Headless/simulate.sh Assets/SphFluid/Scenes/DamBreak.unity --seconds 2 --out Output/DamBreak
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
"$root/Headless/install-deps.sh"

# No GPU needed: pin the loader to lavapipe unless the caller chose a driver.
if [ -z "${VK_DRIVER_FILES:-}${VK_ICD_FILENAMES:-}${VK_LOADER_DRIVERS_SELECT:-}" ]; then
    export VK_LOADER_DRIVERS_SELECT='*lvp*'
fi
export DOTNET_CLI_TELEMETRY_OPTOUT=1 DOTNET_NOLOGO=1 DOTNET_SKIP_FIRST_TIME_EXPERIENCE=1

dotnet build "$root/Headless/SphFluid.Headless/SphFluid.Headless.csproj" -c Release -nologo -v quiet -clp:ErrorsOnly >&2
cli="$root/Headless/SphFluid.Headless/bin/Release/net10.0/sphfluid.dll"

if [ $# -eq 0 ]; then
    set -- "$root/Assets/SphFluid/Scenes/OilAndWater.unity" --out "$root/Output/OilAndWater"
fi
exec dotnet "$cli" simulate "$@"
