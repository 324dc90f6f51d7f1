#!/usr/bin/env bash
# Installs what the headless side needs on a fresh Debian/Ubuntu machine, only when missing:
# Vulkan (Mesa's lavapipe), glslang's HLSL compiler, SPIRV-Tools, the validation layers and the charts' font; on
# Debian 12 it also upgrades lavapipe to bookworm-backports' Mesa 25 (below).
# The .NET SDK (10 or newer) must already be on PATH; NuGet packages come with `dotnet restore`.
set -euo pipefail

need=()
command -v glslangValidator >/dev/null 2>&1 || need+=(glslang-tools)
command -v spirv-val >/dev/null 2>&1 || need+=(spirv-tools)
# grep reads the whole list (no -q): with pipefail, grep -q's early exit fails ldconfig on SIGPIPE and reinstalls.
ldconfig -p 2>/dev/null | grep 'libvulkan.so.1 ' >/dev/null || need+=(libvulkan1)
# Debian 12's own lavapipe (Mesa 22.3) runs a DFSPH sub-step three times slower than bookworm-backports' Mesa 25 does
# (README, the test command; the suite's longest runs are DFSPH's), so there the driver comes from backports, unless
# SPHFLUID_SYSTEM_LAVAPIPE=1 keeps the release's.
case "${SPHFLUID_SYSTEM_LAVAPIPE:-0}" in
    0|1) ;;
    # "yes" or "true" read as 0 here and went to backports, the opposite of what the caller asked.
    *) echo "install-deps: SPHFLUID_SYSTEM_LAVAPIPE must be 0 (take Mesa 25 from bookworm-backports on Debian 12) or 1 (keep" \
            "the release's lavapipe), or unset (was '${SPHFLUID_SYSTEM_LAVAPIPE}')" >&2
       exit 2 ;;
esac
backports=""
if [ "${SPHFLUID_SYSTEM_LAVAPIPE:-0}" != 1 ] && [ "$(. /etc/os-release 2>/dev/null; echo "${VERSION_CODENAME:-}")" = bookworm ] \
    && ! dpkg --compare-versions "$(dpkg-query -W -f '${Version}' mesa-vulkan-drivers 2>/dev/null || echo 0)" ge 25; then
    backports=bookworm-backports
elif ! ls /usr/share/vulkan/icd.d/lvp_icd*.json >/dev/null 2>&1; then
    need+=(mesa-vulkan-drivers)
fi
ls /usr/share/vulkan/explicit_layer.d/VkLayer_khronos_validation.json >/dev/null 2>&1 || need+=(vulkan-validationlayers)
# The charts (ScottPlot on SkiaSharp without native dependencies) load this font file by path: no fontconfig lookup.
[ -f /usr/share/fonts/truetype/dejavu/DejaVuSans.ttf ] || need+=(fonts-dejavu-core)

sudo=""; [ "$(id -u)" -eq 0 ] || sudo="sudo"
export DEBIAN_FRONTEND=noninteractive
if [ ${#need[@]} -gt 0 ]; then
    echo "install-deps: installing ${need[*]}" >&2
    $sudo apt-get update -qq
    $sudo apt-get install -y -qq --no-install-recommends "${need[@]}" >/dev/null
fi
# Every step may fail (no network, no sudo): the suite then runs on the release's driver, as it did before.
install_backports_lavapipe() {
    # Backports are pinned below the release, so the suite added here upgrades nothing that is not asked for by name.
    local list=/etc/apt/sources.list.d/sphfluid-$backports.list
    if [ ! -f "$list" ]; then
        echo "deb http://deb.debian.org/debian $backports main" | $sudo tee "$list" >/dev/null || return 1
    fi
    if ! { $sudo apt-get update -qq && $sudo apt-get install -y -qq --no-install-recommends -t "$backports" mesa-vulkan-drivers >/dev/null; }; then
        $sudo rm -f "$list"
        return 1
    fi
}
if [ -n "$backports" ]; then
    echo "install-deps: installing mesa-vulkan-drivers (lavapipe) from $backports" >&2
    if ! install_backports_lavapipe; then
        echo "install-deps: $backports could not be reached or written to; Debian 12's lavapipe runs the suite about" \
            "three times slower (SPHFLUID_SYSTEM_LAVAPIPE=1 stops this attempt)" >&2
        ls /usr/share/vulkan/icd.d/lvp_icd*.json >/dev/null 2>&1 \
            || $sudo apt-get install -y -qq --no-install-recommends mesa-vulkan-drivers >/dev/null
    fi
fi

if ! command -v dotnet >/dev/null 2>&1; then
    echo "install-deps: the .NET SDK (10.0 or newer) is required: https://dot.net (dotnet-sdk-10.0)" >&2
    exit 1
fi
