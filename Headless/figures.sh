#!/usr/bin/env bash
# Makes every picture the README shows: simulates each shipped scene headlessly (lavapipe unless a
# driver is chosen) and copies one chosen frame of each, plus the oil-and-water layering figure and
# run summaries and the dam-break accuracy-for-time study, into Headless/figures/. About 10 minutes on 2 CPU cores.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
# Scenes by their path in the repository, which the summaries record, so that they read the same on any machine.
cd "$root"
scenes="Assets/FluidDemo/Scenes"
out="$root/Output"
figures="$root/Headless/figures"
mkdir -p "$figures"

run() { # scene, frame to keep, simulate arguments...
    local scene=$1 frame=$2; shift 2
    "$root/Headless/simulate.sh" "$scenes/$scene.unity" --out "$out/$scene" "$@" >"$out/$scene.log" 2>&1 \
        || { echo "figures: $scene failed, see $out/$scene.log" >&2; exit 1; }
    cp "$out/$scene/frame_$frame.png" "$figures/$scene.png"
    cp "$out/$scene/summary.txt" "$figures/$scene-summary.txt"
    echo "figures: $scene -> Headless/figures/$scene.png"
}

mkdir -p "$out"
run OilAndWater 0012
cp "$out/OilAndWater/frame_0000.png" "$figures/OilAndWater-start.png"
cp "$out/OilAndWater/layering.png" "$figures/OilAndWater-layering.png"
run DamBreak 0005 --seconds 1.5 --frames-every 0.1
run Splash 0003 --seconds 1.2 --frames-every 0.1
run RotatingContainer 0012 --seconds 3
run SphereWake 0010 --seconds 4

# The accuracy-for-time study of the dam break (README "What accuracy costs in time"): both solvers, two
# resolutions, two WCSPH stiffnesses, three DFSPH tolerances, 0.5 s each.
dotnet "$root/Headless/SphFluid.Headless/bin/Release/net10.0/sphfluid.dll" study "$scenes/DamBreak.unity" \
    --seconds 0.5 --particles-scales 0.5 1 --cfl 0.3 --out "$out/DamBreak-study" >"$out/DamBreak-study.log" 2>&1 \
    || { echo "figures: study failed, see $out/DamBreak-study.log" >&2; exit 1; }
cp "$out/DamBreak-study/study.md" "$figures/DamBreak-study.md"
cp "$out/DamBreak-study/study-pareto.png" "$figures/DamBreak-study-pareto.png"
echo "figures: study -> Headless/figures/DamBreak-study.md, DamBreak-study-pareto.png"
