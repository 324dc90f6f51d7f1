#!/usr/bin/env bash
# Measures how the depth the Chebyshev solve is tuned for (ChebyshevBounds.TunedDepth: the interval's bottom is the
# quarter wave of the fluid's depth, or of that many spacings if the fluid is deeper) sets its iterations: for each
# depth given in spacings (default 40 60 1000; 1000 tunes any fluid here to its whole depth), under Chebyshev:
# DeepColumnProbe's water columns at rest, 80 spacings on 6 by 6 and on 12 by 12 (the 1M case's depth) and 120 on 12 by
# 12; and LockExchangeSliceProbe's moving slices of OilAndWater at the spacing of 250k and 1M particles (50 and 80
# spacings deep). A fluid no deeper than the tuned depth is not changed by it. TunedDepth is a constant, not a setting,
# so each value runs in a copy of the committed tree under a temporary folder, which is removed at the end; the
# checkout is not touched. About 15 minutes a value on 2 cores, most of it the 1M slice.
# With --oil-and-water it runs, instead of the probes, the moving fluid a bound below its depth costs: OilAndWater under
# the Chebyshev solve at 25 900 particles (24.4 spacings deep) for 0.3 s, printing the last diagnostics line (its
# iterations a sub-step); about a minute a value.
#   Headless/tools/chebyshev-depth-scan.sh [--oil-and-water] [SPACINGS ...]
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/../env.sh"
oil_and_water=0
if [ "${1:-}" = "--oil-and-water" ]; then oil_and_water=1; shift; fi
[ $# -gt 0 ] || set -- 40 60 1000
for d in "$@"; do
    [[ "$d" =~ ^[1-9][0-9]*$ ]] || { echo "chebyshev-depth-scan: a depth must be a whole number of spacings, 1 or more (was '$d')" >&2; exit 2; }
done

source "$(dirname "${BASH_SOURCE[0]}")/committed-copy.sh"
source "$(dirname "${BASH_SOURCE[0]}")/scan-report.sh"
bounds="$work/Packages/com.sphfluid.fluid/Runtime/Core/Simulation/ChebyshevBounds.cs"
grep -q '^        public const int TunedDepth = [0-9]*;$' "$bounds"

for d in "$@"; do
    sed -i "s/^        public const int TunedDepth = [0-9]*;\$/        public const int TunedDepth = $d;/" "$bounds"
    if [ "$oil_and_water" -eq 1 ]; then
        dotnet build "$work/Headless/SphFluid.Headless/SphFluid.Headless.csproj" -c Release -nologo -v quiet -clp:ErrorsOnly >&2
        scan_report "tuned to $d spacings: OilAndWater x6: " "^t=|unhealthy" 1 "$work" \
            dotnet Headless/SphFluid.Headless/bin/Release/net10.0/sphfluid.dll simulate Assets/FluidDemo/Scenes/OilAndWater.unity \
            --solver dfsph --solver-iteration chebyshev --particles-scale 6 --seconds 0.3 --diagnostics-every 0.05 --frames-every 100 \
            --out "$work/Output/oil-and-water-$d" --quiet
        continue
    fi
    dotnet build "$work/Tests/SphFluid.Tests/SphFluid.Tests.csproj" -c Release -nologo -v quiet -clp:ErrorsOnly >&2
    for column in 6,80 12,80 12,120; do
        scan_report "tuned to $d spacings: " "a column of" first "$work" dotnet test Tests/SphFluid.Tests/SphFluid.Tests.csproj \
            -c Release --no-build --filter "FullyQualifiedName~DeepColumnProbe\\(Chebyshev,$column\\)" --logger "console;verbosity=detailed"
    done
    for scale in 60 240; do
        scan_report "tuned to $d spacings: " "sliced" first "$work" dotnet test Tests/SphFluid.Tests/SphFluid.Tests.csproj \
            -c Release --no-build --filter "FullyQualifiedName~LockExchangeSliceProbe\\(Chebyshev,$scale\\)" --logger "console;verbosity=detailed"
    done
done
