#!/usr/bin/env bash
# Packs what a lent GPU machine (the device tool) needs to run sphfluid. That machine has an NVIDIA driver but no
# .NET, no glslang, no Vulkan loader and no network, and it receives only the working tree (64 MiB) and the ignored
# paths a call carries. So this builds, here, one archive .gpu/sphfluid-gpu.tar.xz (about 34 MB; .gpu/ is ignored by
# git) holding a self-contained linux-x64 build of sphfluid, glslangValidator and spirv-val (they compile the
# .compute kernels there, as here), the Vulkan loader and the charts' font. Headless/gpu-figures.sh unpacks it there
# and prints the GPU figures; a device call carries it with `carry: [".gpu"]`.
# Each experiment named in EXPERIMENTS (NAME:SOLVERS, a patch of Headless/experiments and the solvers to bench it
# under, or "study" for a change to the step; default below: the patches that apply to HEAD and that the H200 timed
# at d599ca0 and left out, so that a lent GPU can time them again beside the code of the day, the code before a
# change no GPU has timed (correction-reads-particles: the correction's neighbour reads before 6f1fc00), and changes
# lavapipe could not judge (sorted-positions-search, the two skips of the walls' rows: walls-in-reach-marks,
# walls-distance-skip, and cells stored brick by brick for the SMs' caches: brick-ordered-cells);
# cached-pair-gradients, timed there too, stopped applying when the neighbour search took lanes (947b6cd), and
# ExperimentPatchTests holds the default to HEAD) goes in as
# experiments/NAME: the files its patch changes, from a patched copy of the committed tree, and the assemblies built
# from that copy that differ from the kit's own. Headless/gpu-figures.sh's experiments stage runs each beside
# the kit's own build. EXPERIMENTS="" packs none.
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
# awk reads to the end: an early exit can close the pipe while ldconfig still writes, and pipefail then stops the
# script with SIGPIPE (exit 141, no message) on some runs.
loader="$(ldconfig -p | awk '!found && /libvulkan\.so\.1 / && /x86-64/ { print $NF; found = 1 }')"
[ -n "$loader" ] || { echo "gpu-kit: no x86-64 libvulkan.so.1 found by ldconfig" >&2; exit 1; }
cp -L "$loader" "$top/lib/libvulkan.so.1"
cp /usr/share/fonts/truetype/dejavu/DejaVuSans.ttf "$top/"
git -C "$root" describe --always --dirty >"$top/commit" 2>/dev/null || echo unknown >"$top/commit"

for entry in ${EXPERIMENTS-longer-dfsph-step:study correction-reads-particles:dfsph sorted-positions-search:wcsph,dfsph walls-in-reach-marks:wcsph,dfsph walls-distance-skip:wcsph,dfsph brick-ordered-cells:dfsph}; do
    name="${entry%%:*}" solvers="${entry#*:}"
    patch="$root/Headless/experiments/$name.patch"
    [ -f "$patch" ] || { echo "gpu-kit: EXPERIMENTS names $name, but $patch is missing" >&2; exit 2; }
    [ "$solvers" != "$entry" ] || { echo "gpu-kit: EXPERIMENTS entry '$entry' is NAME:SOLVERS (e.g. $name:wcsph,dfsph)" >&2; exit 2; }
    copy="$stage/copy-$name" into="$top/experiments/$name"
    mkdir -p "$copy" "$into/tree"
    git -C "$root" archive HEAD | tar -x -C "$copy"
    (cd "$copy" && git apply "$patch") || { echo "gpu-kit: $name.patch does not apply to HEAD" >&2; exit 1; }
    dotnet publish "$copy/Headless/SphFluid.Headless/SphFluid.Headless.csproj" -c Release -r linux-x64 --self-contained true \
        -p:DebugType=none --artifacts-path "$stage/artifacts-$name" -o "$stage/app-$name" -nologo -v quiet -clp:ErrorsOnly >&2
    for dll in "$stage/app-$name"/[Ss]ph[Ff]luid*.dll; do
        cmp -s "$dll" "$top/app/$(basename "$dll")" || cp "$dll" "$into/"
    done
    (cd "$copy" && sed -n 's|^diff --git a/.* b/||p' "$patch" | while read -r file; do
        if [ -f "$file" ]; then mkdir -p "$into/tree/$(dirname "$file")" && cp "$file" "$into/tree/$file"; fi
    done)
    echo "$solvers" | tr ',' ' ' >"$into/solvers"
    echo "gpu-kit: experiment $name ($(cd "$into" && ls *.dll 2>/dev/null | tr '\n' ' ')and $(find "$into/tree" -type f | wc -l) patched files) for $solvers" >&2
done

mkdir -p "$kit"
tar -C "$stage" -cf - sphfluid-gpu | xz -T0 -6 >"$archive.partial"
mv "$archive.partial" "$archive"
echo "gpu-kit: $(du -h "$archive" | cut -f1) in ${archive#"$root"/} (sphfluid at $(cat "$top/commit"))"
