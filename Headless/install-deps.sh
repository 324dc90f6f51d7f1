#!/usr/bin/env bash
# Installs what the headless side needs on a fresh Debian/Ubuntu machine, only when missing:
# Vulkan (Mesa's lavapipe), glslang's HLSL compiler, SPIRV-Tools, the validation layers and the charts' font.
# The .NET SDK (10 or newer) must already be on PATH; NuGet packages come with `dotnet restore`.
set -euo pipefail

need=()
command -v glslangValidator >/dev/null 2>&1 || need+=(glslang-tools)
command -v spirv-val >/dev/null 2>&1 || need+=(spirv-tools)
# grep reads the whole list (no -q): with pipefail, grep -q's early exit fails ldconfig on SIGPIPE and reinstalls.
ldconfig -p 2>/dev/null | grep 'libvulkan.so.1 ' >/dev/null || need+=(libvulkan1)
ls /usr/share/vulkan/icd.d/lvp_icd.*.json >/dev/null 2>&1 || need+=(mesa-vulkan-drivers)
ls /usr/share/vulkan/explicit_layer.d/VkLayer_khronos_validation.json >/dev/null 2>&1 || need+=(vulkan-validationlayers)
# The charts (ScottPlot on SkiaSharp without native dependencies) load this font file by path: no fontconfig lookup.
[ -f /usr/share/fonts/truetype/dejavu/DejaVuSans.ttf ] || need+=(fonts-dejavu-core)

if [ ${#need[@]} -gt 0 ]; then
    echo "install-deps: installing ${need[*]}" >&2
    sudo=""; [ "$(id -u)" -eq 0 ] || sudo="sudo"
    export DEBIAN_FRONTEND=noninteractive
    $sudo apt-get update -qq
    $sudo apt-get install -y -qq --no-install-recommends "${need[@]}" >/dev/null
fi

if ! command -v dotnet >/dev/null 2>&1; then
    echo "install-deps: the .NET SDK (10.0 or newer) is required: https://dot.net (dotnet-sdk-10.0)" >&2
    exit 1
fi
