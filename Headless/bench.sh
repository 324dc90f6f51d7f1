#!/usr/bin/env bash
# Times the SPH pipeline per sub-step, per pass and per kernel on whatever Vulkan device is found
# (lavapipe unless the caller chose a driver). Without arguments: the default oil-and-water scene at
# its own size and at 8k and 32k particles. With arguments: they go to `sphfluid bench` as they are, e.g.
#   Headless/bench.sh Assets/FluidDemo/Scenes/DamBreak.unity --particles 4000 16000 --steps 20
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/env.sh"

dotnet build "$root/Headless/SphFluid.Headless/SphFluid.Headless.csproj" -c Release -nologo -v quiet -clp:ErrorsOnly >&2
cli="$root/Headless/SphFluid.Headless/bin/Release/net10.0/sphfluid.dll"

if [ $# -eq 0 ]; then
    set -- "$root/Assets/FluidDemo/Scenes/OilAndWater.unity" --particles 2000 8000 32000 --steps 10 --warmup 3
fi
exec dotnet "$cli" bench "$@"
