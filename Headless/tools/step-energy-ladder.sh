#!/usr/bin/env bash
# Whose kinetic energy follows DFSPH's step in OilAndWater: for each SCALE:STEP (particle scale, MaxTimeStep in s) the
# scene and its still copy, the oil at the water's rest density so that nothing should move, each run under DFSPH for
# SECONDS (default 0.1). Prints per pair the sub-step, the particles, both kinetic energies and their difference, the
# exchange's own part (Headless/docs/physics.md, "Whose energy follows the step"). --no-jitter spawns both boxes on
# the plain lattice; --density-tolerance passes on to the runs. Output folders go under a temporary folder, removed at
# the end. On lavapipe a pair takes 20 s at 1:0.005 and 12 minutes at 1:0.0000390625 or 8:0.0003125.
#   Headless/tools/step-energy-ladder.sh [--seconds S] [--no-jitter] [--density-tolerance PCT] SCALE:STEP ...
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/../env.sh"
seconds=0.1
jitter=keep
tolerance=()
while [ $# -gt 0 ]; do
    case "$1" in
        --seconds) seconds=$2; shift 2 ;;
        --no-jitter) jitter=none; shift ;;
        --density-tolerance) tolerance=(--density-tolerance "$2"); shift 2 ;;
        *) break ;;
    esac
done
[ $# -gt 0 ] || set -- 1:0.005 1:0.00125 1:0.0003125
# A number above zero, else the ladder stops before it builds anything (the CLI would refuse each run in turn).
positive() { [[ "$1" =~ ^[0-9]+(\.[0-9]+)?$ ]] && awk -v x="$1" 'BEGIN { exit !(x > 0) }'; }
positive "$seconds" || { echo "step-energy-ladder: --seconds must be a number above 0 (was '$seconds')" >&2; exit 2; }
for rung in "$@"; do
    [[ "$rung" == *:* ]] && positive "${rung%%:*}" && positive "${rung##*:}" \
        || { echo "step-energy-ladder: each rung must be SCALE:STEP, two numbers above 0 (was '$rung')" >&2; exit 2; }
done

scene="$root/Assets/FluidDemo/Scenes/OilAndWater.unity"
# The edits below match the scene's text; a scene that no longer holds it would run unedited, so say so instead.
for text in "MaxTimeStep: 0.005" "RestDensity: 900" "Jitter: 0.05"; do
    grep -q "$text" "$scene" || { echo "step-energy-ladder: $scene no longer holds '$text'" >&2; exit 3; }
done

dotnet build "$root/Headless/SphFluid.Headless/SphFluid.Headless.csproj" -c Release -nologo -v quiet -clp:ErrorsOnly >&2
cli="$root/Headless/SphFluid.Headless/bin/Release/net10.0/sphfluid.dll"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

# The particle count, the sub-step (ms) and the kinetic energy (mJ) of a run's last diagnostics row.
last_row() {
    awk -F, 'NR == 1 { for (i = 1; i <= NF; i++) col[$i] = i; next }
             { n = $col["particles"]; dt = $col["dt_s"]; ke = $col["kinetic_energy_J"] }
             END { printf "%s %.4g %.3f\n", n, dt * 1000, ke * 1000 }' "$1/diagnostics.csv"
}

printf '%-6s %-12s %10s %12s %12s %16s\n' scale "sub-step ms" particles "scene mJ" "still mJ" "difference mJ"
for rung in "$@"; do
    scale=${rung%%:*} step=${rung##*:}
    for kind in scene still; do
        edits=(-e "s/MaxTimeStep: 0.005/MaxTimeStep: $step/")
        [ "$kind" = still ] && edits+=(-e "s/RestDensity: 900/RestDensity: 1000/")
        [ "$jitter" = none ] && edits+=(-e "s/Jitter: 0.05/Jitter: 0/")
        sed "${edits[@]}" "$scene" > "$work/$kind.unity"
        if ! dotnet "$cli" simulate "$work/$kind.unity" --solver dfsph "${tolerance[@]}" --particles-scale "$scale" \
                --seconds "$seconds" --diagnostics-every "$seconds" --frames-every 100 --out "$work/$kind" --quiet > "$work/$kind.log" 2>&1; then
            echo "step-energy-ladder: the $kind run at $rung failed:" >&2
            tail -5 "$work/$kind.log" >&2
            exit 4
        fi
    done
    read -r particles substep scene_ke < <(last_row "$work/scene")
    read -r _ _ still_ke < <(last_row "$work/still")
    awk -v s="$scale" -v dt="$substep" -v n="$particles" -v a="$scene_ke" -v b="$still_ke" \
        'BEGIN { printf "%-6s %-12s %10d %12.3f %12.3f %16.3f\n", s, dt, n, a, b, a - b }'
done
