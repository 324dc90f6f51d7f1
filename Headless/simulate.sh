#!/usr/bin/env bash
# Simulates a Unity scene file headlessly (the README's first command). Without arguments: the default
# oil-and-water scene for its default duration, frames and diagnostics into Output/OilAndWater/, at half the
# particles when the Vulkan device is a CPU (lavapipe), so that it finishes in under 3 minutes on 2 cores (the
# run prints the scale it used).
# With arguments: they go to `sphfluid simulate` as they are (see --help), e.g.
#   Headless/simulate.sh Assets/FluidDemo/Scenes/DamBreak.unity --seconds 2 --out Output/DamBreak
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/env.sh"

dotnet build "$root/Headless/SphFluid.Headless/SphFluid.Headless.csproj" -c Release -nologo -v quiet -clp:ErrorsOnly >&2
cli="$root/Headless/SphFluid.Headless/bin/Release/net10.0/sphfluid.dll"

if [ $# -eq 0 ]; then
    set -- "$root/Assets/FluidDemo/Scenes/OilAndWater.unity" --out "$root/Output/OilAndWater" --cpu-particles-scale 0.5
fi
exec dotnet "$cli" simulate "$@"
