using System;
using System.Globalization;
using SphFluid.Compute;

namespace SphFluid.Simulation
{
    /// <summary>
    /// Whether a device holds a scene's particles: every per-particle buffer of the fluid and of its walls must fit in the
    /// largest buffer the device binds (<see cref="IComputeDevice.MaxBufferBytes"/>). The widest are the particles
    /// themselves, <see cref="Particle"/> and <see cref="BoundaryParticle"/> at 32 bytes, so lavapipe's 128 MiB holds
    /// 4 194 304 of each. Checked before any buffer is made, so that a scene too large for the device is refused with the
    /// counts and the limit rather than stopped by whichever buffer the device refused first. The neighbour lists, larger
    /// still, are not part of it: past the limit the passes walk the grid instead (<see cref="NeighbourCapacity"/>).
    /// </summary>
    public static class DeviceCapacity
    {
        /// <summary>Bytes of the widest per-particle buffer element.</summary>
        public const int ParticleBytes = 32;

        /// <summary>The most fluid or wall particles a device whose largest buffer is <paramref name="maxBufferBytes"/> holds.</summary>
        public static long MostParticles(long maxBufferBytes) => Math.Max(0L, maxBufferBytes) / ParticleBytes;

        /// <summary>Why <paramref name="device"/> cannot hold <paramref name="fluid"/> fluid and <paramref name="walls"/> wall
        /// particles, or null when it can.</summary>
        public static string Problem(long fluid, long walls, IComputeDevice device)
        {
            if (device == null) throw new ArgumentNullException(nameof(device));
            return Problem(fluid, walls, device.MaxBufferBytes, device.DeviceName);
        }

        /// <summary>Why a device named <paramref name="deviceName"/> whose largest buffer is <paramref name="maxBufferBytes"/>
        /// cannot hold <paramref name="fluid"/> fluid and <paramref name="walls"/> wall particles, or null when it can.</summary>
        public static string Problem(long fluid, long walls, long maxBufferBytes, string deviceName)
        {
            long most = MostParticles(maxBufferBytes);
            if (fluid <= most && walls <= most) return null;
            bool fluidFails = fluid > most;
            long count = fluidFails ? fluid : walls;
            return string.Format(CultureInfo.InvariantCulture,
                "{0} {1} particles need a buffer of {2:G3} MiB ({3} bytes each), more than the {4:G3} MiB the device '{5}' binds in one buffer: " +
                "it holds at most {6} fluid and {6} wall particles",
                count, fluidFails ? "fluid" : "wall", count * (double)ParticleBytes / (1 << 20), ParticleBytes,
                maxBufferBytes / (double)(1 << 20), deviceName, most);
        }

        /// <summary><see cref="Problem(long, long, IComputeDevice)"/> for a scene as <see cref="FluidSimulation"/> would build
        /// it: its spawn boxes' particles and its walls' and obstacles'.</summary>
        public static string Problem(FluidSceneDescription scene, IComputeDevice device)
        {
            if (scene == null) throw new ArgumentNullException(nameof(scene));
            return Problem(SpawnLayout.TotalCount(scene), BoundarySampling.Sample(scene).Length, device);
        }
    }
}
