#!/usr/bin/env bash
# What lavapipe's worker threads (LP_NUM_THREADS) do for the test script's two processes at once: the DFSPH benchmark of
# OilAndWater (4 160 particles) alone with one worker and with two (lavapipe's default here, one per core), then two of
# it at once with two workers each and with one each. Prints each run's milliseconds per sub-step. Output folders go
# under a temporary folder, removed at the end. About 3 minutes on 2 cores.
#   Headless/tools/lavapipe-threads.sh [STEPS]     (timed sub-steps per run, default 30)
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/../env.sh"
steps=${1:-30}
[[ "$steps" =~ ^[1-9][0-9]*$ ]] || { echo "lavapipe-threads: STEPS must be a whole number, 1 or more (was '$steps')" >&2; exit 2; }

dotnet build "$root/Headless/SphFluid.Headless/SphFluid.Headless.csproj" -c Release -nologo -v quiet -clp:ErrorsOnly >&2
cli="$root/Headless/SphFluid.Headless/bin/Release/net10.0/sphfluid.dll"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

# One benchmark with $1 workers, labelled $2; a run that fails prints its exit code and last lines instead of a timing.
bench() {
    local log="$work/$2.log" code=0
    LP_NUM_THREADS=$1 dotnet "$cli" bench "$root/Assets/FluidDemo/Scenes/OilAndWater.unity" --solver dfsph --steps "$steps" \
        --skip-savings --out "$work/$2" > "$log" 2>&1 || code=$?
    if [ "$code" -ne 0 ]; then
        echo "$2: the benchmark failed (exit code $code); its last lines:"; tail -n 5 "$log"
        return 0
    fi
    grep -m1 "ms/sub-step" "$log" | sed "s/^bench: /$2: /"
}

bench 1 "alone, 1 worker"
bench 2 "alone, 2 workers"
for workers in 2 1; do
    bench "$workers" "two at once, $workers workers each (first)" &
    bench "$workers" "two at once, $workers workers each (second)" &
    wait
done
