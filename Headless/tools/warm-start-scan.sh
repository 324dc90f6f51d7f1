#!/usr/bin/env bash
# Measures what DFSPH's warm start (DENSITY_WARM_START and DIVERGENCE_WARM_START in DivergenceFreeSolver.hlsl) costs and
# saves: for each fraction given (default 0.5 0.75 0.9 1), the DFSPH resting tank's line after 1 s
# (DivergenceFreeTankTests) and the last diagnostics line of OilAndWater at 6 times its particles (25 900) over 0.3 s.
# A fraction F sets both solves' warm start; D,V sets the constant-density solve's to D and the divergence-free
# solve's to V. The fractions are constants of the shader, not settings, so each runs in a copy of the committed tree
# under a temporary folder, which is removed at the end; the checkout is not touched. About 3 minutes a fraction on 2
# cores. With --solver-iteration chebyshev both runs take the Chebyshev-accelerated solve (SolverIteration) instead of
# Jacobi's; with --deep each fraction also runs DeepColumnProbe, the 80-spacing column of the 1M case (20 s more).
#   Headless/tools/warm-start-scan.sh [--solver-iteration jacobi|chebyshev] [--deep] [FRACTION | D,V ...]
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/../env.sh"
iteration=jacobi deep=0
while [ $# -gt 0 ]; do
    case "$1" in
        --solver-iteration) iteration=${2:-}; shift 2 ;;
        --deep) deep=1; shift ;;
        *) break ;;
    esac
done
case "$iteration" in jacobi) fixture=Jacobi ;; chebyshev) fixture=Chebyshev ;;
    *) echo "warm-start-scan: --solver-iteration must be jacobi or chebyshev (was '$iteration')" >&2; exit 2 ;; esac
[ $# -gt 0 ] || set -- 0.5 0.75 0.9 1
fraction='(0(\.[0-9]+)?|1(\.0+)?)'
for w in "$@"; do
    [[ "$w" =~ ^$fraction(,$fraction)?$ ]] ||
        { echo "warm-start-scan: a fraction must be a number in [0, 1], or two joined by a comma (was '$w')" >&2; exit 2; }
done

source "$(dirname "${BASH_SOURCE[0]}")/committed-copy.sh"
source "$(dirname "${BASH_SOURCE[0]}")/scan-report.sh"
solver="$work/Packages/com.sphfluid.fluid/Shaders/Include/DivergenceFreeSolver.hlsl"
grep -q '^#define DENSITY_WARM_START ' "$solver"
grep -q '^#define DIVERGENCE_WARM_START ' "$solver"
dotnet build "$work/Tests/SphFluid.Tests/SphFluid.Tests.csproj" -c Release -nologo -v quiet -clp:ErrorsOnly >&2
dotnet build "$work/Headless/SphFluid.Headless/SphFluid.Headless.csproj" -c Release -nologo -v quiet -clp:ErrorsOnly >&2

for w in "$@"; do
    density=${w%,*} divergence=${w#*,}
    sed -i "s/^#define DENSITY_WARM_START .*/#define DENSITY_WARM_START $density/;
            s/^#define DIVERGENCE_WARM_START .*/#define DIVERGENCE_WARM_START $divergence/" "$solver"
    scan_report "warm start $w, tank: " "DFSPH resting tank \\($fixture\\)" first "$work" dotnet test Tests/SphFluid.Tests/SphFluid.Tests.csproj \
        -c Release --no-build --filter "FullyQualifiedName~DivergenceFreeTankTests\\($fixture\\)" --logger "console;verbosity=detailed" |
        sed 's/ | .*//'
    scan_report "warm start $w, OilAndWater x6: " "^t=|^done|^FAILED|unhealthy" 2 "$work" \
        dotnet Headless/SphFluid.Headless/bin/Release/net10.0/sphfluid.dll simulate Assets/FluidDemo/Scenes/OilAndWater.unity \
        --solver dfsph --solver-iteration "$iteration" --particles-scale 6 --seconds 0.3 --diagnostics-every 0.05 --frames-every 100 \
        --out "$work/out-$w" --quiet
    if [ "$deep" = 1 ]; then
        scan_report "warm start $w, deep column: " "a column of" first "$work" dotnet test Tests/SphFluid.Tests/SphFluid.Tests.csproj \
            -c Release --no-build --filter "FullyQualifiedName~DeepColumnProbe\\($fixture,6,80\\)" --logger "console;verbosity=detailed"
    fi
done
