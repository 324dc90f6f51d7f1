#!/usr/bin/env bash
# Packs what a lent GPU machine (the device tool) needs to run sphfluid. That machine has an NVIDIA driver but no
# .NET, no glslang, no Vulkan loader and no network, and it receives only the working tree (64 MiB) and the ignored
# paths a call carries. So this builds, here, one archive .gpu/sphfluid-gpu.tar.xz (about 34 MB; .gpu/ is ignored by
# git) holding a self-contained linux-x64 build of sphfluid, glslangValidator and spirv-val (they compile the
# .compute kernels there, as here), the Vulkan loader and the charts' font. Headless/gpu-figures.sh unpacks it there
# and prints the GPU figures; a device call carries it with `carry: [".gpu"]`.
# It writes only .gpu/sphfluid-gpu.tar.xz (through a temporary name beside it) and a scratch folder it removes.
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/env.sh"

kit="$root/.gpu"
archive="$kit/sphfluid-gpu.tar.xz"
stage="$(mktemp -d)"
trap 'rm -rf "$stage"' EXIT
top="$stage/sphfluid-gpu"
mkdir -p "$top/bin" "$top/lib"

# A separate artifacts path keeps the runtime-specific restore out of the projects' own obj/ and bin/, which the
# tests and scripts build into.
dotnet publish "$root/Headless/SphFluid.Headless/SphFluid.Headless.csproj" -c Release -r linux-x64 --self-contained true \
    -p:DebugType=none --artifacts-path "$stage/artifacts" -o "$top/app" -nologo -v quiet -clp:ErrorsOnly >&2
cp "$(command -v glslangValidator)" "$(command -v spirv-val)" "$top/bin/"
loader="$(ldconfig -p | awk '/libvulkan\.so\.1 / && /x86-64/ { print $NF; exit }')"
[ -n "$loader" ] || { echo "gpu-kit: no x86-64 libvulkan.so.1 found by ldconfig" >&2; exit 1; }
cp -L "$loader" "$top/lib/libvulkan.so.1"
cp /usr/share/fonts/truetype/dejavu/DejaVuSans.ttf "$top/"
git -C "$root" describe --always --dirty >"$top/commit" 2>/dev/null || echo unknown >"$top/commit"

mkdir -p "$kit"
tar -C "$stage" -cf - sphfluid-gpu | xz -T0 -6 >"$archive.partial"
mv "$archive.partial" "$archive"
echo "gpu-kit: $(du -h "$archive" | cut -f1) in ${archive#"$root"/} (sphfluid at $(cat "$top/commit"))"
