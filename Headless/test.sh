#!/usr/bin/env bash
# Runs every test the project has outside the Unity Editor: the engine-free NUnit suite (the
# same files Unity's Test Runner runs, Tests/SphFluid.Tests.Core), then Tests/SphFluid.Tests: the
# Vulkan backend, the GPU primitives and SPH kernels on lavapipe, and the Unity asset-integrity
# checks. Installs what it needs first.
# Extra arguments go to each `dotnet test` (e.g. --filter "FullyQualifiedName~Backend").
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/env.sh"

core="$root/Tests/SphFluid.Tests.Core/SphFluid.Tests.Core.csproj"
gpu="$root/Tests/SphFluid.Tests/SphFluid.Tests.csproj"
results="$root/TestResults"
rm -rf "$results"
status=0

# One `dotnet test` writing $results/<trx name>; the first failure's code becomes the script's, and every run still runs.
run_tests() {
    local project=$1 trx=$2
    shift 2
    local code=0
    dotnet test "$project" -c Release --logger "trx;LogFileName=$trx" --logger "console;verbosity=normal" \
        --results-directory "$results" "$@" || code=$?
    if [ "$status" -eq 0 ]; then status=$code; fi
}

if [ $# -gt 0 ]; then
    run_tests "$core" results-core.trx "$@"
    run_tests "$gpu" results.trx "$@"
else
    run_tests "$core" results-core.trx
    # The GPU suite in two processes at once, each with its own Vulkan device and temp folder: the longest runs (the
    # category TestProcesses.LongRuns, chosen so that the two end together) and the rest. Each process gets one lavapipe
    # worker thread (LP_NUM_THREADS, unless the caller set it): with lavapipe's default of one per core, two processes kept
    # four workers and two submitting threads on the two cores, and the suite took 1272 s where it took 1165 s with one
    # worker each on the same day (README, the test command; Headless/tools/lavapipe-threads.sh). Each line of their
    # interleaved output starts with its half's name. Each writes the kernel variants its validated device and its
    # unvalidated one (the layering and physics runs) ran; every variant run unvalidated must have run validated too
    # (GpuTestDevice.VariantsFolderVariable).
    dotnet build "$gpu" -c Release
    scratch=$(mktemp -d)
    trap 'rm -rf "$scratch"' EXIT
    pids=()
    for half in long-runs rest; do
        if [ "$half" = long-runs ]; then filter="TestCategory=LongRuns"; else filter="TestCategory!=LongRuns"; fi
        mkdir "$scratch/$half"
        ( export TMPDIR="$scratch/$half" SPHFLUID_VARIANTS_DIR="$scratch/variants-$half" LP_NUM_THREADS="${LP_NUM_THREADS:-1}"
          code=0
          dotnet test "$gpu" -c Release --no-build --filter "$filter" --logger "trx;LogFileName=results-$half.trx" \
              --logger "console;verbosity=normal" --results-directory "$results" 2>&1 | sed -u "s/^/[$half] /" || code=$?
          echo "$SECONDS" > "$scratch/$half.ended"
          exit $code ) &
        pids+=($!)
    done
    for pid in "${pids[@]}"; do
        code=0
        wait "$pid" || code=$?
        if [ "$status" -eq 0 ]; then status=$code; fi
    done
    # When each process ended, so that a split that no longer ends together shows in the log (LongRuns).
    echo "test processes ended at $(cat "$scratch/long-runs.ended" 2>/dev/null || echo '?') s (long-runs) and" \
         "$(cat "$scratch/rest.ended" 2>/dev/null || echo '?') s (rest) of the script's time"
    unvalidated=$(comm -23 <(cat "$scratch"/variants-*/unvalidated.txt 2>/dev/null | sort -u) \
                           <(cat "$scratch"/variants-*/validated.txt 2>/dev/null | sort -u))
    if [ -n "$unvalidated" ]; then
        echo "kernel variants that ran only without the validation layer (give one of their scenes a short validated run):"
        echo "$unvalidated" | sed 's/^/  /'
        if [ "$status" -eq 0 ]; then status=1; fi
    fi
fi

# One plain closing line that any CI reader understands, summed over the runs that wrote results, with the script's
# wall time (installs and builds included): the README's CI times are this figure.
passed=0; failed=0; skipped=0; found=0
for trx in "$results"/*.trx; do
    [ -f "$trx" ] || continue
    found=1
    counters=$(grep -o '<Counters [^>]*>' "$trx" | head -n 1)
    get() { local n; n=$(echo "$counters" | sed -n "s/.* $1=\"\([0-9]*\)\".*/\1/p"); echo "${n:-0}"; }
    passed=$(( passed + $(get passed) )); failed=$(( failed + $(get failed) ))
    skipped=$(( skipped + $(get total) - $(get executed) ))
done
if [ "$found" -eq 1 ]; then
    echo "${passed} passed, ${failed} failed, ${skipped} skipped in ${SECONDS} s"
fi
exit $status
