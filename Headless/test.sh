#!/usr/bin/env bash
# Runs every test the project has outside the Unity Editor: the engine-free NUnit suite (the
# same files Unity's Test Runner runs, Tests/SphFluid.Tests.Core), then Tests/SphFluid.Tests: the
# Vulkan backend, the GPU primitives and SPH kernels on lavapipe, and the Unity asset-integrity
# checks. Installs what it needs first.
# Extra arguments go to each `dotnet test` (e.g. --filter "FullyQualifiedName~Backend").
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/env.sh"

results="$root/TestResults"
rm -rf "$results"
core="Tests/SphFluid.Tests.Core/SphFluid.Tests.Core.csproj"
gpu="Tests/SphFluid.Tests/SphFluid.Tests.csproj"
status=0
# Every project runs even when one fails; the first failure's code is the script's.
record() { if [ "$status" -eq 0 ]; then status=$1; fi; }

# dotnet test of project $1 writing $results/$2, with the rest of the arguments.
run_tests() {
    local project=$1 trx=$2
    shift 2
    dotnet test "$root/$project" -c Release \
        --logger "trx;LogFileName=$trx" --logger "console;verbosity=normal" \
        --results-directory "$results" "$@"
}

set +e
run_tests "$core" results-core.trx "$@"
record $?
set -e

if [ $# -gt 0 ]; then
    # A chosen subset (a --filter, say): one process.
    trxs=(results-core.trx results.trx)
    set +e
    run_tests "$gpu" results.trx "$@"
    record $?
    set -e
else
    # The whole GPU suite, CI's run, as two processes at once. Lavapipe keeps only about one and a half of CI's two
    # cores busy, and four fixtures hold half the suite's time: the long layering runs of SeparationTests and the
    # resolutions, sphere and turning container of the next three. They run in one process and every other test in the
    # second; the two filters are complements, so each test runs exactly once. Each process has its own device and its
    # own temp folder, so that a test that checks the temp folder sees only its own process's files.
    trxs=(results-core.trx results-long.trx results-rest.trx)
    long="FullyQualifiedName~SphFluid.Tests.Physics.SeparationTests|FullyQualifiedName~SphFluid.Tests.Physics.DamBreakConvergenceTests"
    long+="|FullyQualifiedName~SphFluid.Tests.Physics.SphereThroughPoolTests|FullyQualifiedName~SphFluid.Tests.Physics.RotatingContainerTests"
    rest=$(echo "$long" | sed 's/FullyQualifiedName~/FullyQualifiedName!~/g; s/|/\&/g')
    dotnet build "$root/$gpu" -c Release
    scratch=$(mktemp -d)
    mkdir -p "$scratch/long" "$scratch/rest"
    set +e
    TMPDIR="$scratch/long" run_tests "$gpu" results-long.trx --no-build --filter "$long" 2>&1 | sed -u 's/^/[long] /' &
    long_pid=$!
    TMPDIR="$scratch/rest" run_tests "$gpu" results-rest.trx --no-build --filter "$rest" 2>&1 | sed -u 's/^/[rest] /'
    record "${PIPESTATUS[0]}"
    wait "$long_pid"
    record $?
    set -e
    rm -rf "$scratch"
fi

# One plain closing line that any CI reader understands, summed over the projects that wrote results.
passed=0; failed=0; skipped=0; found=0
for name in "${trxs[@]}"; do
    trx="$results/$name"
    [ -f "$trx" ] || continue
    found=1
    counters=$(grep -o '<Counters [^>]*>' "$trx" | head -n 1)
    get() { local n; n=$(echo "$counters" | sed -n "s/.* $1=\"\([0-9]*\)\".*/\1/p"); echo "${n:-0}"; }
    passed=$(( passed + $(get passed) )); failed=$(( failed + $(get failed) ))
    skipped=$(( skipped + $(get total) - $(get executed) ))
done
if [ "$found" -eq 1 ]; then
    echo "${passed} passed, ${failed} failed, ${skipped} skipped"
fi
exit $status
