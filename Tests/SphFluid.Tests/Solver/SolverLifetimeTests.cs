using System;
using System.Collections.Generic;
using System.Numerics;
using NUnit.Framework;
using SphFluid.Compute;
using SphFluid.Simulation;

namespace SphFluid.Tests.Solver
{
    /// <summary>FluidSimulation releases every buffer it (and its sorter) created, Dispose is safe twice,
    /// Reset respawns, and an invalid scene is refused before anything is allocated.</summary>
    public sealed class SolverLifetimeTests
    {
        static FluidSceneDescription SmallScene()
        {
            var settings = SolverScenes.Coarse(0.04f);
            return SolverScenes.Scene(settings, new Vector3(0.24f, 0.24f, 0.16f),
                SolverScenes.Box("Water", SolverScenes.Water(), new Vector3(0f, -0.06f, 0f), new Vector3(0.24f, 0.12f, 0.16f)));
        }

        [Test]
        public void Dispose_ReleasesEveryBuffer_AndIsSafeTwice()
        {
            var device = new CountingDevice(GpuTestDevice.Shared);
            var sim = new FluidSimulation(device, SmallScene());
            sim.Step(1f / 60f);
            sim.RequestDiagnostics();
            Assert.That(device.Live, Is.GreaterThan(10));
            sim.Dispose();
            Assert.That(device.Live, Is.EqualTo(0), "buffers still alive: " + string.Join(", ", device.LiveNames()));
            sim.Dispose();
            Assert.That(() => sim.Step(1f / 60f), Throws.TypeOf<ObjectDisposedException>());
        }

        [Test]
        public void InvalidScene_IsRefusedBeforeAllocating()
        {
            var device = new CountingDevice(GpuTestDevice.Shared);
            var scene = SmallScene();
            scene.SpawnBoxes[0].Phase.RestDensity = -3f;
            Assert.That(() => new FluidSimulation(device, scene),
                Throws.ArgumentException.With.Message.Contains("SpawnBox 'Water': RestDensity must be in [1, 100000] kg/m^3 (was -3)"));
            Assert.That(device.Created, Is.EqualTo(0));
        }

        /// <summary>A device binds buffers up to a size (IComputeDevice.MaxBufferBytes, 128 MiB on lavapipe): fluid that does not fit
        /// is refused with its count and the limit before any buffer is made (DeviceCapacity), not by whichever buffer the
        /// device would refuse first.</summary>
        [Test]
        public void FluidLargerThanTheDevicesBuffers_IsRefusedBeforeAllocating()
        {
            var scene = SmallScene();
            int fluid = SpawnLayout.TotalCount(scene);
            var device = new CountingDevice(GpuTestDevice.Shared) { BufferLimit = 32L * (fluid - 1) };
            Assert.That(() => new FluidSimulation(device, scene), Throws.ArgumentException.With.Message.StartsWith(
                $"FluidSimulation: {fluid} fluid particles need a buffer of").And.Message.Contains($"it holds at most {fluid - 1} fluid"));
            Assert.That(device.Created, Is.EqualTo(0));
        }

        /// <summary>Walls that do not fit are found once the fluid's buffers exist: refused, and every buffer made so far released.</summary>
        [Test]
        public void WallsLargerThanTheDevicesBuffers_AreRefused_AndNothingLeaks()
        {
            var scene = SmallScene();
            int fluid = SpawnLayout.TotalCount(scene), walls = BoundarySampling.Sample(scene).Length;
            Assume.That(walls, Is.GreaterThan(fluid));
            var device = new CountingDevice(GpuTestDevice.Shared) { BufferLimit = 32L * (walls - 1) };
            Assert.That(() => new FluidSimulation(device, scene), Throws.ArgumentException.With.Message.StartsWith(
                $"FluidSimulation: {walls} wall particles need a buffer of"));
            Assert.That(device.Created, Is.GreaterThan(0));
            Assert.That(device.Live, Is.EqualTo(0), "buffers still alive: " + string.Join(", ", device.LiveNames()));
        }

        /// <summary>A container resized in play (the inspector, a script) whose walls the device would not hold is refused before
        /// the old one is replaced: the simulation goes on in the container it had.</summary>
        [Test]
        public void AResizedContainerWhoseWallsDoNotFit_IsRefused_AndTheOldOneStays()
        {
            var scene = SmallScene();
            int fluid = SpawnLayout.TotalCount(scene), walls = BoundarySampling.Sample(scene).Length;
            var device = new CountingDevice(GpuTestDevice.Shared) { BufferLimit = 32L * Math.Max(fluid, walls) };
            using var sim = new FluidSimulation(device, scene);
            var larger = scene.Container.Clone();
            larger.Size = 2f * scene.Container.Size;

            Assert.That(() => sim.UpdateContainer(larger), Throws.ArgumentException.With.Message.StartsWith("Container: Size (0.48, 0.48, 0.32) m: its ")
                .And.Message.Contains(" wall particles need a buffer of"));

            sim.Step(1f / 60f);
            var report = sim.ReadDiagnostics();
            Assert.That(report.ParticleCount, Is.EqualTo(fluid));
            Assert.That(report.OutsideCount + report.NanCount, Is.EqualTo(0));
            Assert.That(sim.Grid.Size, Is.EqualTo(scene.Container.Size), "the old container's grid");
        }

        /// <summary>Neighbour lists larger than the device's largest buffer are not made: the passes walk the grid, as past
        /// NeighbourCapacity.MaxListBytes. lavapipe refused OilAndWater's lists at 214 600 particles (219 MB against its
        /// 128 MiB) and the run stopped with "unexpected failure"; it now runs.</summary>
        [Test]
        public void ListsLargerThanTheDevicesLargestBuffer_LeaveThePassesToTheGridWalk()
        {
            var scene = SmallScene();
            int owners = SpawnLayout.TotalCount(scene) + BoundarySampling.Sample(scene).Length;
            long lists = 4L * owners * NeighbourCapacity.For(scene.Settings, owners, long.MaxValue);
            using (var listed = new FluidSimulation(GpuTestDevice.Shared, scene))
                Assert.That(listed.ReadsNeighbourLists, Is.True, "the lists fit the real device");
            var device = new CountingDevice(GpuTestDevice.Shared) { BufferLimit = lists - 4 };
            Assume.That(DeviceCapacity.Problem(scene, device), Is.Null, "the particles fit");
            using (var sim = new FluidSimulation(device, scene))
            {
                Assert.That(sim.ReadsNeighbourLists, Is.False);
                for (int i = 0; i < 3; i++) sim.Step(1f / 60f);
                var particles = new Particle[sim.ParticleCount];
                sim.Particles.GetData(particles);
                Assert.That(Array.TrueForAll(particles, p => float.IsFinite(p.Position.X + p.Position.Y + p.Position.Z)), Is.True);
            }
        }

        [Test]
        public void Reset_RespawnsTheSameParticles()
        {
            using (var sim = new FluidSimulation(GpuTestDevice.Shared, SmallScene()))
            {
                var first = Sorted(sim);
                for (int i = 0; i < 5; i++) sim.Step(1f / 60f);
                Assert.That(sim.SimulatedTime, Is.GreaterThan(0.05));
                sim.Reset();
                Assert.That(sim.SimulatedTime, Is.EqualTo(0.0));
                Assert.That(Sorted(sim), Is.EqualTo(first));
            }
        }

        [Test]
        public void LatestDiagnostics_ArriveAfterARequest()
        {
            using (var sim = new FluidSimulation(GpuTestDevice.Shared, SmallScene()))
            {
                Assert.That(sim.LatestDiagnostics, Is.Null);
                sim.Step(1f / 60f);
                sim.RequestDiagnostics();
                sim.Step(1f / 60f);
                var report = sim.LatestDiagnostics;
                Assert.That(report, Is.Not.Null);
                Assert.That(report.ParticleCount, Is.EqualTo(sim.ParticleCount));
                Assert.That(report.SimulatedTime, Is.EqualTo(1.0 / 60.0).Within(1e-4));
                Assert.That(sim.LastStep.Substeps, Is.GreaterThan(0));
                Assert.That(GpuTestDevice.Shared.TryGetSampleMilliseconds(PassNames.Forces, out double ms), Is.True);
                Assert.That(ms, Is.GreaterThan(0.0));
            }
        }

        static Particle[] Sorted(FluidSimulation sim)
        {
            var particles = new Particle[sim.ParticleCount];
            sim.Particles.GetData(particles);
            var byId = new Particle[particles.Length];
            foreach (var p in particles) byId[p.Id] = p;
            return byId;
        }

        /// <summary>Forwards to a real device and counts the buffers created and not yet disposed.</summary>
        sealed class CountingDevice : ForwardingDevice
        {
            readonly HashSet<CountingBuffer> _live = new HashSet<CountingBuffer>();

            public CountingDevice(IComputeDevice inner) : base(inner) { }

            /// <summary>The largest buffer the device says it binds (default: the real device's).</summary>
            public long? BufferLimit { get; init; }

            public override long MaxBufferBytes => BufferLimit ?? Inner.MaxBufferBytes;

            public int Live => _live.Count;
            public int Created { get; private set; }
            public IEnumerable<string> LiveNames() { foreach (var b in _live) yield return b.Name; }

            public override IComputeBuffer CreateBuffer(string name, int count, int stride)
            {
                var buffer = new CountingBuffer(this, Inner.CreateBuffer(name, count, stride));
                _live.Add(buffer);
                Created++;
                return buffer;
            }

            internal void Released(CountingBuffer buffer) => _live.Remove(buffer);

            protected override IComputeBuffer Unwrap(IComputeBuffer b) => b is CountingBuffer c ? c.Inner : b;
        }

        sealed class CountingBuffer : IComputeBuffer
        {
            readonly CountingDevice _owner;
            public IComputeBuffer Inner { get; }
            public CountingBuffer(CountingDevice owner, IComputeBuffer inner) { _owner = owner; Inner = inner; }
            public string Name => Inner.Name;
            public int Count => Inner.Count;
            public int Stride => Inner.Stride;
            public void SetData<T>(T[] data) where T : struct => Inner.SetData(data);
            public void SetData<T>(T[] data, int sourceIndex, int bufferIndex, int count) where T : struct => Inner.SetData(data, sourceIndex, bufferIndex, count);
            public void GetData<T>(T[] data) where T : struct => Inner.GetData(data);
            public void Dispose()
            {
                Inner.Dispose();
                _owner.Released(this);
            }
        }
    }
}
