#!/usr/bin/env bash
# Estimates DFSPH's GPU time per simulated second at a sub-step and iteration counts measured elsewhere (a slice
# probe on lavapipe, say), from the per-kernel table a GPU printed for `sphfluid bench --solver dfsph` (of FILE's DFSPH
# "Per kernel" tables, the first at the most particles; FILE a log of Headless/gpu-figures.sh). It reads no GPU
# itself, so it answers what a sub-step at those iterations would cost on the GPU that printed FILE, with what every
# pass cost there.
#
# A sub-step records (FluidSimulation.Solve) each solve's warm start as one ApplyStiffness, then rounds of error pass
# and BoundarySolveError, whose last group folds the round's errors (a SolveFinal dispatch of its own in tables printed
# before that, counted in the round when the table has it), each but the last followed by an ApplyStiffness: n
# corrections cost n + 1 error rounds and n corrections. Every other kernel of the table runs a fixed number of times
# a sub-step whatever the iterations (the sort, FindNeighbours, DensityFactor, NonPressureForces, the drift): the fixed
# part. A solve makes
# two corrections at the least (the fold), so 2 and 2 at the longest sub-step is the cheapest a sub-step gets. Each
# kernel's cost a dispatch is its milliseconds over the dispatches that ran groups (the table's "ran" column): the
# rounds a solve records beyond its convergence dispatch no groups, and counting them would cheapen a round. A table
# printed before that column (the committed H200 profiles) has only all dispatches to divide by, which understates a
# round by the share of its rounds that were empty; the estimate says which it read. Prints the split, the GPU seconds
# per simulated second and the real-time factor (simulated over GPU seconds; a bound, as the wall adds the host's time).
#   Headless/tools/realtime-estimate.sh FILE SUBSTEP_MS DENSITY_ITERATIONS DIVERGENCE_ITERATIONS
# e.g. the 1M slice (LockExchangeSliceProbe) on the H200's profile:
#   Headless/tools/realtime-estimate.sh Headless/figures/gpu-h200-realtime.txt 1.3889 7.3 6.2
set -euo pipefail
usage="usage: realtime-estimate.sh FILE SUBSTEP_MS DENSITY_ITERATIONS DIVERGENCE_ITERATIONS"
[ $# -eq 4 ] || { echo "realtime-estimate: $usage" >&2; exit 2; }
file=$1 step=$2 density=$3 divergence=$4
[ -f "$file" ] || { echo "realtime-estimate: FILE '$file' is not a file" >&2; exit 2; }
number='^([0-9]+(\.[0-9]*)?|\.[0-9]+)$'
[[ "$step" =~ $number ]] && awk -v s="$step" 'BEGIN { exit !(s > 0) }' ||
    { echo "realtime-estimate: SUBSTEP_MS must be a number of milliseconds above 0 (was '$step')" >&2; exit 2; }
for pair in "DENSITY_ITERATIONS:$density" "DIVERGENCE_ITERATIONS:$divergence"; do
    [[ "${pair#*:}" =~ $number ]] && awk -v n="${pair#*:}" 'BEGIN { exit !(n >= 2) }' ||
        { echo "realtime-estimate: ${pair%%:*} must be a number of corrections a sub-step, 2 or more (a solve stops after two at the least) (was '${pair#*:}')" >&2; exit 2; }
done

awk -v file="$file" -v step="$step" -v nd="$density" -v nv="$divergence" '
    /^solver: DFSPH/ { dfsph = 1 }
    /^solver: / && !/^solver: DFSPH/ { dfsph = 0 }
    # The table of the most particles (the first of them): a log of gpu-figures.sh can hold the smaller DFSPH rows of
    # its scenes stage before the 1M bench that the estimate is about.
    dfsph && /^Per kernel at / {
        inTable = ($4 + 0 > particles + 0)
        if (inTable) { particles = $4; kernels = 0; split("", order); split("", calls); split("", ms) }
        next
    }
    inTable && $2 == "kernel" { ranColumn = ($6 == "ran"); next }
    inTable && /^\| [A-Za-z]/ {
        name = $2; order[++kernels] = name
        if (ranColumn) { calls[name] = $6; ms[name] = $8 } else { calls[name] = $4; ms[name] = $6 }
        next
    }
    inTable && /^$/ && kernels > 0 { inTable = 0 }
    END {
        if (kernels == 0) { printf "realtime-estimate: %s holds no DFSPH per-kernel table (sphfluid bench --solver dfsph)\n", file > "/dev/stderr"; exit 2 }
        split("ApplyStiffness DensitySolveError DivergenceSolveError BoundarySolveError", needed, " ")
        for (k in needed) if (!(needed[k] in calls) || calls[needed[k]] <= 0) {
            printf "realtime-estimate: the DFSPH table of %s has no %s row\n", file, needed[k] > "/dev/stderr"; exit 2 }
        apply = ms["ApplyStiffness"] / calls["ApplyStiffness"]
        wallError = ms["BoundarySolveError"] / calls["BoundarySolveError"]
        final = ("SolveFinal" in calls && calls["SolveFinal"] > 0) ? ms["SolveFinal"] / calls["SolveFinal"] : 0
        densityRound = ms["DensitySolveError"] / calls["DensitySolveError"] + wallError + final
        divergenceRound = ms["DivergenceSolveError"] / calls["DivergenceSolveError"] + wallError + final
        fixed = 0
        for (k = 1; k <= kernels; k++) {
            n = order[k]
            if (n != "ApplyStiffness" && n != "DensitySolveError" && n != "DivergenceSolveError" && n != "BoundarySolveError" && n != "SolveFinal") {
                fixed += ms[n]; list = list sprintf("%s%s %.3f", (list == "" ? "" : ", "), n, ms[n])
            }
        }
        warm = 2 * apply
        densitySolve = (nd + 1) * densityRound + nd * apply
        divergenceSolve = (nv + 1) * divergenceRound + nv * apply
        substep = fixed + warm + densitySolve + divergenceSolve
        perSecond = 1000 / step
        printf "profile: %s, DFSPH at %s particles; %s\n", file, particles, ranColumn ? "each kernel'"'"'s cost over the dispatches that ran groups" \
            : "a table without the ran column: each kernel'"'"'s cost over all its dispatches, a converged solve'"'"'s empty rounds among them"
        printf "fixed a sub-step: %.3f ms (%s)\n", fixed, list
        printf "warm starts: %.3f ms (2 x ApplyStiffness %.3f)\n", warm, apply
        printf "a correction: constant density %.3f ms (DensitySolveError + BoundarySolveError%s %.3f, ApplyStiffness %.3f), divergence-free %.3f ms (%.3f + %.3f)\n", densityRound + apply, ("SolveFinal" in calls ? " + SolveFinal" : ""), densityRound, apply, divergenceRound + apply, divergenceRound, apply
        printf "sub-step of %s ms at %s + %s corrections: %.3f ms GPU = %.3f fixed + %.3f warm starts + %.3f constant density + %.3f divergence-free\n", step, nd, nv, substep, fixed, warm, densitySolve, divergenceSolve
        printf "per simulated second: %.1f sub-steps, %.2f s GPU (%.2f s fixed and warm starts, %.2f s solves); real-time factor at most %.3fx\n", perSecond, perSecond * substep / 1000, perSecond * (fixed + warm) / 1000, perSecond * (densitySolve + divergenceSolve) / 1000, 1000 / (perSecond * substep)
    }' "$file"
