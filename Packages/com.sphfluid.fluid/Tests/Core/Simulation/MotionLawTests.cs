using System.Numerics;
using NUnit.Framework;
using SphFluid.Simulation;

namespace SphFluid.Tests.Core.Simulation
{
    /// <summary>
    /// The motion laws give a frame's end placement with the velocity that brought the wall there, which the simulation
    /// sweeps back by to start the frame (FluidSimulation.UpdateContainer). The velocity is the mean over the frame, so
    /// the sweep starts exactly where the law put the wall at the frame's start, turns and start delays included.
    /// </summary>
    public sealed class MotionLawTests
    {
        const double Frame = 1.0 / 60.0;

        [TestCase(0.5)]   // before the start delay: at rest
        [TestCase(0.995)] // a frame that begins at rest and ends moving
        [TestCase(2.0)]
        [TestCase(3.0)]   // the far end, where it turns
        public void ADrivenSphereStartsTheFrameWhereTheLawPutIt(double end)
        {
            var drive = new DriveLaw { Travel = new Vector3(0.3f, 0.1f, 0f), Period = 4f, StartDelay = 1f };
            var rest = new RigidSphere(new Vector3(-0.2f, 0.05f, 0f), 0.04f, Vector3.Zero);
            RigidSphere moved = drive.Over(rest, end - Frame, end);
            Vector3 sweptBack = moved.Center - moved.Velocity * (float)Frame;
            Assert.That(Vector3.Distance(moved.Center, rest.Center + drive.Offset(end)), Is.LessThan(1e-6f));
            Assert.That(Vector3.Distance(sweptBack, rest.Center + drive.Offset(end - Frame)), Is.LessThan(1e-6f));
        }

        [Test]
        public void AFrameWithoutDurationTakesTheLawsVelocity()
        {
            var drive = new DriveLaw();
            RigidSphere moved = drive.Over(new RigidSphere(Vector3.Zero, 0.04f, Vector3.Zero), 2.0, 2.0);
            Assert.That(Vector3.Distance(moved.Velocity, drive.Velocity(2.0)), Is.LessThan(1e-6f));
        }

        [TestCase(0.5)]
        [TestCase(1.01)] // straddles the start delay: turning for 0.01 s of the frame's 0.0167
        [TestCase(2.5)]
        public void ASpinningContainerStartsTheFrameWhereTheLawTurnedIt(double end)
        {
            var spin = new SpinLaw { Axis = new Vector3(0f, 0f, 2f), AngularSpeed = 45f, StartDelay = 1f };
            var rest = new ContainerDescription { Position = new Vector3(0.1f, 0.2f, 0f), Size = new Vector3(0.4f, 0.3f, 0.2f) };
            var pivot = new Vector3(-0.1f, 0f, 0f); // off the container's centre, so the centre moves too
            ContainerDescription moved = spin.Over(rest, pivot, end - Frame, end);
            ContainerDescription start = spin.Over(rest, pivot, end - 2 * Frame, end - Frame);

            // What the simulation does with it: the centre back along its velocity, the frame turned back about it.
            Vector3 centreBack = moved.Position - moved.Velocity * (float)Frame;
            float angleBack = moved.AngularVelocity.Length() * (float)Frame;
            Quaternion turnedBack = angleBack > 0f
                ? Quaternion.Concatenate(moved.Rotation, Quaternion.CreateFromAxisAngle(Vector3.Normalize(moved.AngularVelocity), -angleBack))
                : moved.Rotation;
            Assert.That(Vector3.Distance(centreBack, start.Position), Is.LessThan(1e-6f));
            Assert.That(Quaternion.Dot(Quaternion.Normalize(turnedBack), start.Rotation), Is.GreaterThan(1f - 1e-6f));
        }

        [Test]
        public void AFrameWhollyAfterTheDelayTurnsAtTheLawsSpeed()
        {
            var spin = new SpinLaw { Axis = new Vector3(0f, 0f, 1f), AngularSpeed = 45f, StartDelay = 1f };
            ContainerDescription moved = spin.Over(new ContainerDescription(), Vector3.Zero, 2.0 - Frame, 2.0);
            Assert.That(moved.AngularVelocity.Z, Is.EqualTo(45f * System.MathF.PI / 180f).Within(1e-5f));
        }
    }
}
