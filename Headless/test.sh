#!/usr/bin/env bash
# Runs every test the project has outside the Unity Editor: the engine-free NUnit suite (the
# same files Unity's Test Runner runs), the Vulkan backend, the GPU primitives and SPH kernels
# on lavapipe, and the Unity asset-integrity checks. Installs what it needs first.
# Extra arguments go to `dotnet test` (e.g. --filter "FullyQualifiedName~Backend").
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/env.sh"

results="$root/TestResults"
rm -rf "$results"
set +e
dotnet test "$root/Tests/SphFluid.Tests/SphFluid.Tests.csproj" -c Release \
    --logger "trx;LogFileName=results.trx" --logger "console;verbosity=normal" \
    --results-directory "$results" "$@"
status=$?
set -e

# One plain closing line that any CI reader understands.
trx="$results/results.trx"
if [ -f "$trx" ]; then
    counters=$(grep -o '<Counters [^>]*>' "$trx" | head -n 1)
    get() { echo "$counters" | sed -n "s/.* $1=\"\([0-9]*\)\".*/\1/p"; }
    passed=$(get passed); failed=$(get failed); total=$(get total); executed=$(get executed)
    skipped=$(( ${total:-0} - ${executed:-0} ))
    echo "${passed:-0} passed, ${failed:-0} failed, ${skipped} skipped"
fi
exit $status
