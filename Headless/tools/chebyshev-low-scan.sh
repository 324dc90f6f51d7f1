#!/usr/bin/env bash
# Measures how the low end of the Chebyshev solve's eigenvalue interval (ChebyshevBounds.For's Low, the quarter wave
# over the spawned fluid's depth) sets its iterations: for each factor given (default 1 2 4 8), Low times that factor,
# then the DFSPH resting tank's line after 1 s (DivergenceFreeTankTests, 12 spacings deep) and DeepColumnProbe's
# 80-spacing columns on 6 by 6 and 12 by 12 spacings (the 1M case's depth). Low is computed, not a setting, so each
# factor runs in a copy of the committed tree under a temporary folder, which is removed at the end; the checkout is
# not touched. About 2 minutes a factor on 2 cores.
#   Headless/tools/chebyshev-low-scan.sh [FACTOR ...]
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/../env.sh"
[ $# -gt 0 ] || set -- 1 2 4 8
for f in "$@"; do
    [[ "$f" =~ ^[0-9]+(\.[0-9]+)?$ ]] && [ "$f" != 0 ] ||
        { echo "chebyshev-low-scan: a factor must be a positive number (was '$f')" >&2; exit 2; }
done

source "$(dirname "${BASH_SOURCE[0]}")/committed-copy.sh"
bounds="$work/Packages/com.sphfluid.fluid/Runtime/Core/Simulation/ChebyshevBounds.cs"
grep -q '^            return (low, high);$' "$bounds"
cp "$bounds" "$work/ChebyshevBounds.cs.committed"

for f in "$@"; do
    cp "$work/ChebyshevBounds.cs.committed" "$bounds"
    sed -i "s/^            return (low, high);\$/            return ($f * low, high);/" "$bounds"
    dotnet build "$work/Tests/SphFluid.Tests/SphFluid.Tests.csproj" -c Release -nologo -v quiet -clp:ErrorsOnly >&2
    (cd "$work" && dotnet test Tests/SphFluid.Tests/SphFluid.Tests.csproj -c Release --no-build \
        --filter "FullyQualifiedName~DivergenceFreeTankTests\\(Chebyshev\\)" --logger "console;verbosity=detailed" 2>&1 |
        grep -m1 "DFSPH resting tank (Chebyshev)" | sed "s/ | .*//; s/^ */low x$f, tank: /" || true)
    for footprint in 6 12; do
        (cd "$work" && dotnet test Tests/SphFluid.Tests/SphFluid.Tests.csproj -c Release --no-build \
            --filter "FullyQualifiedName~DeepColumnProbe\\(Chebyshev,$footprint\\)" --logger "console;verbosity=detailed" 2>&1 |
            grep -m1 "a column of" | sed "s/^ */low x$f, deep column: /" || true)
    done
done
