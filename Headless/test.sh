#!/usr/bin/env bash
# Runs every test the project has outside the Unity Editor: the engine-free NUnit suite (the
# same files Unity's Test Runner runs), the Vulkan backend, the GPU primitives and SPH kernels
# on lavapipe, and the Unity asset-integrity checks. Installs what it needs first.
# Extra arguments go to `dotnet test` (e.g. --filter "FullyQualifiedName~Backend").
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
"$root/Headless/install-deps.sh"

# CI has no GPU: pin the loader to lavapipe unless the caller chose a driver.
if [ -z "${VK_DRIVER_FILES:-}${VK_ICD_FILENAMES:-}${VK_LOADER_DRIVERS_SELECT:-}" ]; then
    export VK_LOADER_DRIVERS_SELECT='*lvp*'
fi
export DOTNET_CLI_TELEMETRY_OPTOUT=1 DOTNET_NOLOGO=1 DOTNET_SKIP_FIRST_TIME_EXPERIENCE=1

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
