#!/usr/bin/env bash
# How DFSPH's iterations grow with resolution under each SolverIteration: OilAndWater under DFSPH at each particle
# scale given (default 1 and 6: 4 160 and 25 900 particles) for SECONDS (default 0.3), with the Jacobi and the
# Chebyshev-accelerated solve; prints each run's last diagnostics line (iterations, compression, expansion, energies)
# and its summary. Output folders go under a temporary folder, removed at the end. About 8 minutes on 2 cores for the
# defaults (lavapipe); a scale of 24 (102 000 particles) takes the Jacobi solve to its cap of 100 iterations.
#   Headless/tools/solver-iteration-scan.sh [--seconds S] [SCALE ...]
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/../env.sh"
seconds=0.3
if [ "${1:-}" = "--seconds" ]; then seconds=$2; shift 2; fi
# A number above zero, else the scan stops before it builds anything (the CLI would refuse each run in turn).
positive() { [[ "$1" =~ ^[0-9]+(\.[0-9]+)?$ ]] && awk -v x="$1" 'BEGIN { exit !(x > 0) }'; }
positive "$seconds" || { echo "solver-iteration-scan: --seconds must be a number above 0 (was '$seconds')" >&2; exit 2; }
[ $# -gt 0 ] || set -- 1 6
for scale in "$@"; do
    positive "$scale" || { echo "solver-iteration-scan: a scale must be a number above 0 (was '$scale')" >&2; exit 2; }
done

dotnet build "$root/Headless/SphFluid.Headless/SphFluid.Headless.csproj" -c Release -nologo -v quiet -clp:ErrorsOnly >&2
cli="$root/Headless/SphFluid.Headless/bin/Release/net10.0/sphfluid.dll"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
source "$(dirname "${BASH_SOURCE[0]}")/scan-report.sh"

for scale in "$@"; do
    for iteration in jacobi chebyshev; do
        scan_report "$iteration x$scale: " "^t=|^done|^FAILED|unhealthy" 2 "$root" \
            dotnet "$cli" simulate "$root/Assets/FluidDemo/Scenes/OilAndWater.unity" --solver dfsph --solver-iteration "$iteration" \
            --particles-scale "$scale" --seconds "$seconds" --diagnostics-every 0.05 --frames-every 100 \
            --out "$work/$iteration-$scale" --quiet
    done
done
