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
# project file, then the name of its trx file under $results
projects=(
    "Tests/SphFluid.Tests.Core/SphFluid.Tests.Core.csproj" results-core.trx
    "Tests/SphFluid.Tests/SphFluid.Tests.csproj" results.trx
)
status=0
for ((i = 0; i < ${#projects[@]}; i += 2)); do
    set +e
    dotnet test "$root/${projects[i]}" -c Release \
        --logger "trx;LogFileName=${projects[i + 1]}" --logger "console;verbosity=normal" \
        --results-directory "$results" "$@"
    code=$?
    set -e
    # Both projects run even when the first fails; the first failure's code is the script's.
    if [ "$status" -eq 0 ]; then status=$code; fi
done

# One plain closing line that any CI reader understands, summed over the projects that wrote results, with the script's
# wall time (installs and builds included): the README's CI times are this figure.
passed=0; failed=0; skipped=0; found=0
for ((i = 1; i < ${#projects[@]}; i += 2)); do
    trx="$results/${projects[i]}"
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
