#!/usr/bin/env bash
# Prints the GPU figures issue #8 asks for, on a lent GPU machine (the device tool), from the repository root, with
# the kit of Headless/gpu-kit.sh carried:  run(command: "bash Headless/gpu-figures.sh", carry: [".gpu"], timeout_s: 600)
#
#   realtime  OilAndWater at about 100k, 250k, 1M and 2M particles (REALTIME_SCALES, default 24 60 240 481), WCSPH at
#             the scene's stiffness and DFSPH at 0.1 % with each of ITERATIONS (the Jacobi and the Chebyshev solve), 1
#             simulated second each: density error, wall ms per simulated second and the real-time factor (sphfluid
#             study, one per size, so that a size that outruns its limit costs only its own rows; the rows' observable
#             error is against the finest run of their own size, so read the other columns). DIVERGENCE_TOLERANCES
#             (%/s, e.g. "10 30") runs DFSPH at each of them, a row each; unset, at the scene's own.
#   bench     bench at 1M particles for each solver (DFSPH with each of BENCH_ITERATIONS): the per-pass and per-kernel
#             milliseconds that show where the time goes, and (WCSPH) the planner's savings.
#   pareto    the accuracy-for-time matrix at 100k and 250k: WCSPH x1 and x4 stiffness, DFSPH at 1, 0.1 and 0.01 % with
#             each of ITERATIONS, the scene's CFL number; its table, CSV and Pareto chart. With 1M (PARETO_SCALES="24 60 240") it outran
#             300 s on an H200: each DFSPH row at 1M spends 100 iterations a sub-step until it turns unhealthy.
#   scenes    60 Hz sizing: bench of every shipped demo scene at its own particle count and at 1/4 to 64 times it
#             (--particles-scales), each under its own solver and OilAndWater under DFSPH too, GPU ms per 60 Hz frame
#             and the largest count whose frame fits half of 16.7 ms, here and on GPUs SLOWER_GPUS times slower per
#             particle: 3 (a GeForce RTX 4060 Ti's 22 FP32 TFLOPS against an H100's or H200's 67) and 16.7 (its 288 GB/s
#             against an H200's 4.8 TB/s of memory bandwidth, an upper bound: an H100 costs what an H200 does).
#   layering  OilAndWater at its own size for 6.5 simulated seconds under WCSPH and under DFSPH with each of ITERATIONS,
#             diagnostics every 0.5 s: the interface's tilt and the layering of issue #5, at a speed lavapipe cannot give
#             (sphfluid simulate).
#   experiments  each experiment the kit carries (gpu-kit.sh's EXPERIMENTS), or those of EXPERIMENT_NAMES: bench at
#             BENCH_PARTICLES under each of its solvers (DFSPH with EXPERIMENT_ITERATION, default chebyshev), once with
#             the kit's own build on this tree and once with the experiment's assemblies on a copy of the tree with its
#             patched files, no savings: the per-pass and per-kernel milliseconds a GPU gives each, side by side. An
#             experiment whose solver is "study" (a change to the step, which a bench's sub-steps do not show) runs the
#             study of the realtime stage instead, DFSPH only, at EXPERIMENT_SCALE (240) and each of
#             EXPERIMENT_DIVERGENCE_TOLERANCES (10 36 %/s): wall time per simulated second and the real-time factor.
# What the stages took on an H200 at 8e65ea2 (Headless/figures/gpu-h200-half-support-cells.txt), to size a call to
# the device time left (a machine's start costs a minute or more besides): realtime at 24 60 240 with the Chebyshev
# solve and two divergence-free tolerances 141 s (99 of them at 1M), the 2M size alone (two rows) 164 s, scenes 84 s,
# bench 56 s (the DFSPH bench 11 s, WCSPH's with the savings 45 s), pareto with the Chebyshev solve 74 s, layering with
# it 15 s, and the Jacobi solve's realtime at 24 60 54 s with its 1M bench 18 s.
# The stages are named as arguments, run in the order given (default: realtime bench pareto). Each step has a time
# limit, so a slow step costs only itself. The environment can change the sizes, the solvers the bench stage times and
# each step's limit in seconds: REALTIME_SCALES, PARETO_SCALES, ITERATIONS ("jacobi chebyshev"), BENCH_PARTICLES,
# BENCH_SOLVERS ("dfsph wcsph"), BENCH_ITERATIONS (ITERATIONS), RUN_SECONDS, REALTIME_LIMIT (150 a size up to 1M,
# in proportion beyond), BENCH_LIMIT (120 each), PARETO_LIMIT (300), SCENE_SCALES, SLOWER_GPUS,
# SCENES (the demo scenes the scenes stage benches), SCENES_LIMIT (90 each), LAYERING_SECONDS (6.5), LAYERING_LIMIT
# (150 each, one per solve).
#
# Writes into $OUT (the device tool's folder that comes back; else Output/gpu): gpu-figures.log (everything printed),
# realtime.md/.csv, pareto.md/.csv/.png/.svg and layering-wcsph.csv/-dfsph-jacobi.csv/-dfsph-chebyshev.csv: ten files
# with every stage, over the tool's eight, so one call runs at most two of realtime, pareto and layering (scenes and
# bench print to the log only).
# Unpacks the kit into a temporary folder it removes, and copies the charts' font to /usr/share/fonts/truetype/dejavu/ only where none is there.
# The sizes can be made small to try the script on lavapipe here (Headless/gpu-kit.sh first):
#   REALTIME_SCALES="0.25 0.5" PARETO_SCALES="0.25" BENCH_PARTICLES=2000 RUN_SECONDS=0.1 OUT=/tmp/gpu bash Headless/gpu-figures.sh
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
stages=("$@")
[ ${#stages[@]} -gt 0 ] || stages=(realtime bench pareto)
for stage in "${stages[@]}"; do
    case "$stage" in realtime|bench|pareto|scenes|layering|experiments) ;; *) echo "gpu-figures: a stage is realtime, bench, pareto, scenes, layering or experiments, not '$stage'" >&2; exit 2 ;; esac
done
realtime_scales="${REALTIME_SCALES:-24 60 240 481}"
pareto_scales="${PARETO_SCALES:-24 60}"
bench_particles="${BENCH_PARTICLES:-1000000}"
bench_solvers="${BENCH_SOLVERS:-dfsph wcsph}"
iterations="${ITERATIONS:-jacobi chebyshev}"
divergence_tolerances=()
for tolerance in ${DIVERGENCE_TOLERANCES:-}; do divergence_tolerances+=("$tolerance"); done
[ ${#divergence_tolerances[@]} -eq 0 ] || divergence_tolerances=(--divergence-tolerances "${divergence_tolerances[@]}")
bench_iterations="${BENCH_ITERATIONS:-$iterations}"
realtime_limit="${REALTIME_LIMIT:-150}"
# A size's limit: REALTIME_LIMIT up to the 1M size (scale 240), and in proportion to the particles beyond it, since a
# study's rows cost about their particle count in wall time (2M ran out of 150 s after WCSPH's row, at b653f9f and at
# d599ca0 alike).
size_limit() { awk -v limit="$realtime_limit" -v scale="$1" 'BEGIN { f = scale / 240; if (f < 1) f = 1; printf "%d", limit * f + 0.5 }'; }
bench_limit="${BENCH_LIMIT:-120}"
pareto_limit="${PARETO_LIMIT:-300}"
seconds="${RUN_SECONDS:-1}"
scene_names="${SCENES:-OilAndWater DamBreak Splash RotatingContainer SphereWake RestingTank}"
scene_scales="${SCENE_SCALES:-0.25 0.5 1 2 4 8 16 32 64}"
slower_gpus="${SLOWER_GPUS:-3 16.7}"
scenes_limit="${SCENES_LIMIT:-90}"
layering_seconds="${LAYERING_SECONDS:-6.5}"
layering_limit="${LAYERING_LIMIT:-150}"
experiment_iteration="${EXPERIMENT_ITERATION:-chebyshev}"
experiment_names="${EXPERIMENT_NAMES:-}"
experiment_scale="${EXPERIMENT_SCALE:-240}"
experiment_divergence="${EXPERIMENT_DIVERGENCE_TOLERANCES:-10 36}"
scene="Assets/FluidDemo/Scenes/OilAndWater.unity"
cfl="$(awk '/^    CflNumber:/ { print $2; exit }' "$root/$scene")" # the scene's own, so the study runs one CFL number

kit="$root/.gpu/sphfluid-gpu.tar.xz"
[ -f "$kit" ] || { echo "gpu-figures: $kit is missing: run Headless/gpu-kit.sh here and carry .gpu" >&2; exit 2; }
out="${OUT:-$root/Output/gpu}"
mkdir -p "$out"
log="$out/gpu-figures.log"
: >"$log"
say() { echo "$*" | tee -a "$log"; }
# The kit's experiment folders that EXPERIMENT_NAMES picks (all when it is empty).
experiment_dirs() {
    for dir in "$home"/experiments/*/; do
        [ -d "$dir" ] || continue
        if [ -z "$experiment_names" ] || [[ " $experiment_names " == *" $(basename "$dir") "* ]]; then echo "${dir%/}"; fi
    done
}

unpacked="$(mktemp -d)"
trap 'rm -rf "$unpacked"' EXIT
tar -C "$unpacked" -xJf "$kit"
home="$unpacked/sphfluid-gpu"
export PATH="$home/bin:$PATH" LD_LIBRARY_PATH="$home/lib${LD_LIBRARY_PATH:+:$LD_LIBRARY_PATH}"
# No ICU on that machine is assumed; sphfluid formats with the invariant culture throughout.
export DOTNET_SYSTEM_GLOBALIZATION_INVARIANT=1 DOTNET_CLI_TELEMETRY_OPTOUT=1 SPHFLUID_SHADER_CACHE="$unpacked/spirv"
# The driver's own manifest names libGLX_nvidia.so.0, from which the loader got no vkCreateInstance without an X server
# (an H200 on 2026-11-29: "Found no drivers"); its EGL library carries the same Vulkan driver and needs no display.
nvidia_egl=/usr/local/nvidia/lib64/libEGL_nvidia.so.0
nvidia_icd=/usr/local/nvidia/share/vulkan/icd.d/nvidia_icd.json
if [ -z "${VK_DRIVER_FILES:-}${VK_ICD_FILENAMES:-}" ]; then
    if [ -f "$nvidia_egl" ]; then
        printf '{"file_format_version": "1.0.1", "ICD": {"library_path": "%s", "api_version": "1.3.0"}}\n' "$nvidia_egl" >"$unpacked/nvidia_egl_icd.json"
        export VK_DRIVER_FILES="$unpacked/nvidia_egl_icd.json"
    elif [ -f "$nvidia_icd" ]; then
        export VK_DRIVER_FILES="$nvidia_icd"
    fi
fi
font=/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf
if [ ! -f "$font" ]; then mkdir -p "$(dirname "$font")" && cp "$home/DejaVuSans.ttf" "$font"; fi

say "gpu-figures: sphfluid at $(cat "$home/commit"), stages ${stages[*]}, $(date -u +%FT%TZ)"
# The device tool stops a command after 600 s; say so up front when the chosen stages' limits add up past that, so a
# call is not spent finding out (the default three stages can: 300 + 2 x 120 + 300 s).
budget=0
for stage in "${stages[@]}"; do
    case "$stage" in
    realtime) for scale in $realtime_scales; do budget=$((budget + $(size_limit "$scale"))); done ;;
    bench)
        for solver in $bench_solvers; do
            if [ "$solver" = dfsph ]; then budget=$((budget + bench_limit * $(echo "$bench_iterations" | wc -w))); else budget=$((budget + bench_limit)); fi
        done
        ;;
    pareto) budget=$((budget + pareto_limit)) ;;
    scenes) budget=$((budget + scenes_limit * ($(echo "$scene_names" | wc -w) + 1))) ;;
    layering) budget=$((budget + (1 + $(echo "$iterations" | wc -w)) * layering_limit)) ;;
    experiments)
        # a bench (or study) of each experiment under each of its solvers, and one of the kit's own build under each
        runs="$(for dir in $(experiment_dirs); do cat "$dir/solvers"; done | tr ' ' '\n' | grep . || true)"
        for solver in $runs $(echo "$runs" | sort -u); do
            if [ "$solver" = study ]; then budget=$((budget + realtime_limit)); else budget=$((budget + bench_limit)); fi
        done
        ;;
    esac
done
if [ "$budget" -gt 600 ]; then
    say "gpu-figures: warning: the stages' limits add up to $budget s, past the device tool's 600 s a call; the last may be cut off (set *_LIMIT or run fewer stages)"
fi
command -v nvidia-smi >/dev/null && nvidia-smi -L | tee -a "$log" || true

step() { # seconds allowed, then sphfluid's arguments; SPHFLUID_APP names another build's folder
    local limit=$1; shift
    local app="${SPHFLUID_APP:-$home/app}"
    say "\$ ${app#"$unpacked"/}/sphfluid $*"
    local code=0 started=$SECONDS
    timeout --kill-after=10 "$limit" "$app/sphfluid" "$@" >>"$log" 2>&1 || code=$?
    # the seconds each step took, so that the next call's stages and limits can be sized to the device time left
    say "exit $code after $((SECONDS - started)) s of $limit"
}

# bench at BENCH_PARTICLES of the scene under $2 (wcsph or dfsph) in the tree rooted at $1, into $scratch/$3; or, for
# "study", DFSPH's real time at EXPERIMENT_SCALE and each of EXPERIMENT_DIVERGENCE_TOLERANCES
experiment_bench() {
    if [ "$2" = study ]; then
        # shellcheck disable=SC2086 # a word list
        step "$realtime_limit" study "$1/$scene" --solvers dfsph --particles-scales "$experiment_scale" --density-tolerances 0.1 \
            --divergence-tolerances $experiment_divergence --solver-iterations "$experiment_iteration" --cfl "$cfl" \
            --seconds "$seconds" --out "$scratch/$3" # its table goes to the log with the rest of its output
        return
    fi
    local solve=(--solver "$2")
    if [ "$2" = dfsph ]; then solve+=(--solver-iteration "$experiment_iteration"); fi
    step "$bench_limit" bench "$1/$scene" --particles "$bench_particles" "${solve[@]}" --skip-savings --out "$scratch/$3"
}

scratch="$unpacked/runs"
for stage in "${stages[@]}"; do
    case "$stage" in
    realtime)
        : >"$out/realtime.csv"
        : >"$out/realtime.md"
        for scale in $realtime_scales; do
            # shellcheck disable=SC2086 # a word list
            step "$(size_limit "$scale")" study "$scene" --particles-scales "$scale" --stiffness-factors 1 --density-tolerances 0.1 \
                --solver-iterations $iterations ${divergence_tolerances[@]+"${divergence_tolerances[@]}"} --cfl "$cfl" --seconds "$seconds" \
                --out "$scratch/realtime-$scale"
            csv="$scratch/realtime-$scale/study.csv"
            if [ -f "$csv" ]; then
                if [ -s "$out/realtime.csv" ]; then tail -n +2 "$csv" >>"$out/realtime.csv"; else cat "$csv" >>"$out/realtime.csv"; fi
                cat "$scratch/realtime-$scale/study.md" >>"$out/realtime.md"
            fi
        done
        ;;
    bench)
        for solver in $bench_solvers; do
            if [ "$solver" = dfsph ]; then
                for iteration in $bench_iterations; do
                    step "$bench_limit" bench "$scene" --particles "$bench_particles" --solver dfsph --solver-iteration "$iteration" \
                        --skip-savings --out "$scratch/bench-dfsph-$iteration"
                done
            else
                # The planner's savings are timed once, with the scene's own solver's plan.
                step "$bench_limit" bench "$scene" --particles "$bench_particles" --solver "$solver" --out "$scratch/bench-$solver"
            fi
        done
        ;;
    pareto)
        # shellcheck disable=SC2086
        step "$pareto_limit" study "$scene" --particles-scales $pareto_scales --stiffness-factors 1 4 --density-tolerances 1 0.1 0.01 \
            --solver-iterations $iterations --cfl "$cfl" --seconds "$seconds" --out "$scratch/pareto"
        for f in study.md study.csv study-pareto.png study-pareto.svg; do
            name="${f/study-pareto/study}" # study-pareto.png -> pareto.png
            if [ -f "$scratch/pareto/$f" ]; then cp "$scratch/pareto/$f" "$out/pareto${name#study}"; fi
        done
        ;;
    scenes)
        for name in $scene_names; do
            # shellcheck disable=SC2086 # the scale and ratio lists are word lists
            step "$scenes_limit" bench "Assets/FluidDemo/Scenes/$name.unity" --particles-scales $scene_scales --skip-savings \
                --slower-gpus $slower_gpus --out "$scratch/scenes-$name"
        done
        # shellcheck disable=SC2086
        step "$scenes_limit" bench "$scene" --solver dfsph --particles-scales $scene_scales --skip-savings \
            --slower-gpus $slower_gpus --out "$scratch/scenes-OilAndWater-dfsph"
        ;;
    layering)
        for run in wcsph $(for i in $iterations; do echo "dfsph-$i"; done); do
            solve=(--solver wcsph)
            if [ "$run" != wcsph ]; then solve=(--solver dfsph --solver-iteration "${run#dfsph-}"); fi
            step "$layering_limit" simulate "$scene" "${solve[@]}" --seconds "$layering_seconds" --diagnostics-every 0.5 \
                --out "$scratch/layering-$run"
            if [ -f "$scratch/layering-$run/diagnostics.csv" ]; then cp "$scratch/layering-$run/diagnostics.csv" "$out/layering-$run.csv"; fi
        done
        ;;
    experiments)
        [ -n "$(experiment_dirs)" ] || { say "gpu-figures: the kit carries no experiments${experiment_names:+ named $experiment_names} (gpu-kit.sh's EXPERIMENTS)"; continue; }
        benched=" "
        for dir in $(experiment_dirs); do
            name="$(basename "$dir")"
            tree="$scratch/tree-$name" app="$scratch/app-$name"
            mkdir -p "$tree"
            cp -r "$root/Assets" "$root/Packages" "$root/ProjectSettings" "$tree/"
            cp -r "$dir/tree/." "$tree/"
            cp -r "$home/app" "$app"
            for dll in "$dir"/*.dll; do if [ -f "$dll" ]; then cp "$dll" "$app/"; fi; done
            for solver in $(cat "$dir/solvers"); do
                if [[ "$benched" != *" $solver "* ]]; then
                    say "gpu-figures: the kit's own build, $solver"
                    experiment_bench "$root" "$solver" "experiment-baseline-$solver"
                    benched="$benched$solver "
                fi
                say "gpu-figures: experiment $name, $solver"
                SPHFLUID_APP="$app" experiment_bench "$tree" "$solver" "experiment-$name-$solver"
            done
        done
        ;;
    esac
done
say "gpu-figures: done, $(date -u +%FT%TZ); files in $out: $(cd "$out" && ls | tr '\n' ' ')"
