using System;
using System.Collections.Generic;
using System.Numerics;
using NUnit.Framework;
using SphFluid.Simulation;

namespace SphFluid.Tests.Core.Simulation
{
    public sealed class HealthCheckTests
    {
        /// <summary>Eight water particles (a 2 x 2 x 2 lattice) at the bottom of the default 0.5 m tank:
        /// k = 50 000 Pa, gamma = 7, so c = sqrt(350) = 18.71 m/s; diagonal D = 0.866 m.</summary>
        static FluidSceneDescription Droplet()
        {
            var scene = SimulationTestScenes.SingleWater();
            scene.SpawnBoxes[0].Size = new Vector3(0.04f, 0.04f, 0.04f);
            scene.SpawnBoxes[0].Center = new Vector3(0f, -0.2f, 0f);
            return scene;
        }

        static DiagnosticsReport Report(double t, float maxSpeed, float meanCompression = 0f, float maxCompression = 0f,
            int nan = 0, int outside = 0, int count = 8) =>
            new DiagnosticsReport(1.0, 0.0, maxSpeed, nan, outside,
                new[] { new PhaseDiagnostics("Water", count, meanCompression, maxCompression) }, t);

        static Particle[] Particles(float speed, float height)
        {
            var particles = new Particle[8];
            for (int i = 0; i < 8; i++)
                particles[i] = new Particle(new Vector3(0.01f * i, height, 0f), new Vector3(speed, 0f, 0f), 0u, (uint)i);
            return particles;
        }

        [Test]
        public void SpeedBound_IsTwiceTheFreeFallOverTheDiagonalPlusOnePercentOfTheSpeedOfSound()
        {
            var check = new HealthCheck(Droplet());
            Assert.That(check.ContainerDiagonal, Is.EqualTo((float)Math.Sqrt(0.75)).Within(1e-5f));
            Assert.That(check.FreeFallSpeed, Is.EqualTo((float)Math.Sqrt(2 * 9.81 * Math.Sqrt(0.75))).Within(1e-4f)); // 4.122 m/s
            Assert.That(check.SpeedOfSound, Is.EqualTo((float)Math.Sqrt(350.0)).Within(1e-4f));
            Assert.That(check.SpeedBound, Is.EqualTo(2f * 4.1222f + 0.01f * 18.708f).Within(1e-3f)); // 8.431 m/s
        }

        [Test]
        public void SpawnSpeed_RaisesTheBound()
        {
            var scene = Droplet();
            scene.SpawnBoxes[0].InitialVelocity = new Vector3(0f, 0f, -3f);
            var check = new HealthCheck(scene);
            Assert.That(check.SpawnSpeed, Is.EqualTo(3f));
            Assert.That(check.SpeedBound, Is.EqualTo(2f * (4.1222f + 3f) + 0.18708f).Within(1e-3f));
        }

        /// <summary>The first state's largest compression, 5 %, released as sound moves the liquid at c x 0.05 = 0.935 m/s:
        /// it joins the speed bound under the margin, and a later, larger compression does not move it.</summary>
        [Test]
        public void TheFirstStatesCompression_AddsItsReleaseSpeedOnce()
        {
            var check = new HealthCheck(Droplet());
            float still = check.SpeedBound;
            Assert.That(check.ReleaseSpeed, Is.EqualTo(0f));

            Assert.That(check.Check(Report(0.0, 0f, 0.01f, 0.05f)), Is.Null);
            Assert.That(check.ReleaseSpeed, Is.EqualTo(0.05f * 18.708f).Within(1e-3f));
            Assert.That(check.SpeedBound, Is.EqualTo(still + 2f * 0.05f * 18.708f).Within(1e-3f));

            Assert.That(check.Check(Report(0.1, 1f, 0.02f, 0.2f)), Is.Null);
            Assert.That(check.ReleaseSpeed, Is.EqualTo(0.05f * 18.708f).Within(1e-3f));
        }

        /// <summary>Water's own tension on the droplet (0.04 m cube, s 0.02 m): the Taylor-Culick speed of a sheet one spacing
        /// thick, sqrt(2 x 0.072 / (1000 x 0.02)) = 0.0849 m/s, joins the speed bound, and the cube's surface energy,
        /// 0.072 x 6 x 0.04^2 = 6.91e-4 J, the energy bound.</summary>
        [Test]
        public void SurfaceTension_AddsTheCapillarySpeedAndTheSpawnsSurfaceEnergy()
        {
            var scene = Droplet();
            float still = new HealthCheck(scene).SpeedBound;
            double stillEnergy = new HealthCheck(scene).EnergyBound;
            scene.SpawnBoxes[0].Phase.SurfaceTension = 0.072f;
            var check = new HealthCheck(scene);
            Assert.That(check.CapillarySpeed, Is.EqualTo(0.08485f).Within(1e-4f));
            Assert.That(check.SpeedBound, Is.EqualTo(still + 2f * 0.08485f).Within(1e-4f));
            Assert.That(check.SurfaceEnergy, Is.EqualTo(6.912e-4).Within(1e-7));
            Assert.That(check.EnergyBound, Is.EqualTo(stillEnergy + 6.912e-4).Within(1e-7));
            Assert.That(check.Check(Report(0.0, 0f), Particles(0f, -0.2f)), Is.Null);
            Assert.That(check.Check(Report(0.1, 0f), Particles(0f, -0.2f)), Is.Null);
            Assert.That(new HealthCheck(Droplet()).CapillarySpeed, Is.EqualTo(0f), "no tension, no capillary speed");
        }

        [Test]
        public void MovingWallsAndSpheres_RaiseTheBoundToTheFastestSeen()
        {
            var scene = Droplet();
            var check = new HealthCheck(scene);
            float rest = check.SpeedBound;
            var spinning = scene.Container.Clone();
            spinning.AngularVelocity = new Vector3(0f, 0f, 2f * MathF.PI); // 360 deg/s
            check.ObserveDrivers(spinning, new[] { new RigidSphere(Vector3.Zero, 0.05f, new Vector3(1.5f, 0f, 0f)) });
            Assert.That(check.WallSpeed, Is.EqualTo(2f * MathF.PI * 0.5f * (float)Math.Sqrt(0.75)).Within(1e-4f)); // 2.72 m/s
            Assert.That(check.ObstacleSpeed, Is.EqualTo(1.5f));
            Assert.That(check.SpeedBound, Is.EqualTo(rest + 2f * (2f * 2.7207f + 2f * 1.5f)).Within(1e-3f));
            Assert.That(check.Driven, Is.True);
            check.ObserveDrivers(scene.Container, new RigidSphere[0]);
            Assert.That(check.WallSpeed, Is.EqualTo(2f * MathF.PI * 0.5f * (float)Math.Sqrt(0.75)).Within(1e-4f), "a slower driver later keeps the bound");
        }

        [Test]
        public void CompressionBounds_AreThoseOfAMach1Impact()
        {
            var check = new HealthCheck(Droplet());
            Assert.That(check.MeanCompressionBound, Is.EqualTo((float)(Math.Pow(4.5, 1.0 / 7.0) - 1.0)).Within(1e-6f)); // 0.2397
            Assert.That(check.MaxCompressionBound, Is.EqualTo(2f * check.MeanCompressionBound));
        }

        /// <summary>A spawn that crowds one particle to 60 % (a jitter of half a spacing) is the scene's own state, not an
        /// impact: the bound for one particle rises to it, and a later state past it is still caught.</summary>
        [Test]
        public void AFirstStateCrowdedPastTwiceTheMeanBound_RaisesTheOneParticleBoundToIt()
        {
            var check = new HealthCheck(Droplet());
            Assert.That(check.Check(Report(0.0, 0f, 0.05f, 0.6f)), Is.Null);
            Assert.That(check.FirstCompression, Is.EqualTo(0.6f));
            Assert.That(check.MaxCompressionBound, Is.EqualTo(0.6f));
            Assert.That(check.Check(Report(0.1, 0f, 0.05f, 0.55f)), Is.Null);
            var problem = check.Check(Report(0.2, 0f, 0.05f, 0.65f));
            Assert.That(problem, Is.Not.Null);
            Assert.That(problem.Figure, Is.EqualTo("max compression"));
        }

        [Test]
        public void AHealthyState_HasNoProblem()
        {
            var check = new HealthCheck(Droplet());
            Assert.That(check.Check(Report(0.0, 0f, 0.01f, 0.05f), Particles(0f, -0.2f)), Is.Null);
            Assert.That(check.Check(Report(0.5, 0.8f, 0.02f, 0.2f), Particles(0.8f, -0.24f)), Is.Null, "fell 4 cm (0.39 J/kg) and moves at 0.8 m/s (0.32 J/kg)");
        }

        [Test]
        public void TooFast_NamesTimePhaseFigureAndBound()
        {
            var check = new HealthCheck(Droplet());
            var problem = check.Check(Report(0.25, 702f), Particles(702f, -0.2f));
            Assert.That(problem, Is.Not.Null);
            Assert.That(problem.Time, Is.EqualTo(0.25));
            Assert.That(problem.Phase, Is.EqualTo("Water"));
            Assert.That(problem.Figure, Is.EqualTo("speed"));
            Assert.That(problem.Value, Is.EqualTo(702.0).Within(1e-3));
            Assert.That(problem.Message, Does.StartWith("unhealthy at t = 0.250 s, phase 'Water': speed 702 m/s exceeds the bound 8.431 m/s (2 x (free fall over the container 4.12"));
        }

        [Test]
        public void TooFast_WithoutParticles_UsesTheReportsMaximum()
        {
            var check = new HealthCheck(Droplet());
            var problem = check.Check(Report(1.0, 9f));
            Assert.That(problem.Phase, Is.EqualTo("all phases"));
            Assert.That(problem.Value, Is.EqualTo(9.0).Within(1e-6));
            Assert.That(check.Check(Report(1.0, 8f)), Is.Null);
        }

        [Test]
        public void OverCompressed_NamesThePhase()
        {
            var check = new HealthCheck(Droplet());
            var mean = check.Check(Report(0.1, 1f, meanCompression: 0.3f, maxCompression: 0.3f));
            Assert.That(mean.Figure, Is.EqualTo("mean compression"));
            Assert.That(mean.Phase, Is.EqualTo("Water"));
            var peak = check.Check(Report(0.1, 1f, meanCompression: 0.05f, maxCompression: 699.66f));
            Assert.That(peak.Figure, Is.EqualTo("max compression"));
            Assert.That(peak.Message, Does.Contain("max compression 699.7 exceeds the bound 0.4794"));
        }

        [Test]
        public void NonFiniteOutsideOrLost_ComeFirst()
        {
            var check = new HealthCheck(Droplet());
            Assert.That(check.Check(Report(0.1, float.NaN, nan: 3)).Figure, Is.EqualTo("non-finite particle count"));
            Assert.That(check.Check(Report(0.1, 1f, outside: 2)).Figure, Is.EqualTo("count of particles outside the container"));
            Assert.That(check.Check(Report(0.1, 1f, count: 7)).Message, Does.Contain("7 counted, 8 spawned"));
        }

        [Test]
        public void EnergyFromNowhere_IsCaught_UnlessADriverMoved()
        {
            var scene = Droplet();
            var check = new HealthCheck(scene);
            Assert.That(check.Check(Report(0.0, 0f, 0f, 0f), Particles(0f, -0.2f)), Is.Null);
            // Risen 20 cm at 1 m/s, with no moving wall: 8 m0 (9.81 * 0.2 + 0.5) J more than at start.
            var problem = check.Check(Report(0.5, 1f), Particles(1f, 0.0f));
            Assert.That(problem, Is.Not.Null);
            Assert.That(problem.Figure, Is.EqualTo("mechanical energy growth"));
            double mass = 8 * scene.BuildPhaseTable()[0].ParticleMass;
            Assert.That(problem.Value, Is.EqualTo(mass * (9.81 * 0.2 + 0.5)).Within(1e-3));
            Assert.That(check.EnergyGrowth, Is.EqualTo(problem.Value));
            Assert.That(problem.Bound, Is.EqualTo(mass * 0.05 * 9.81 * Math.Sqrt(0.75)).Within(1e-4));

            var driven = new HealthCheck(scene);
            Assert.That(driven.Check(Report(0.0, 0f), Particles(0f, -0.2f)), Is.Null);
            var moving = scene.Container.Clone();
            moving.Velocity = new Vector3(0.5f, 0f, 0f);
            driven.ObserveDrivers(moving, null);
            Assert.That(driven.Check(Report(0.5, 1f), Particles(1f, 0.0f)), Is.Null, "a moving wall may feed energy in");
        }

        [Test]
        public void FirstStateCompression_AllowsItsElasticEnergy()
        {
            var scene = Droplet();
            var check = new HealthCheck(scene);
            Assert.That(check.Check(Report(0.0, 0f, 0.1f, 0.2f), Particles(0f, -0.2f)), Is.Null);
            double mass = 8 * scene.BuildPhaseTable()[0].ParticleMass;
            double elastic = 18.708 * 0.2;
            Assert.That(check.EnergyBound, Is.EqualTo(mass * (0.05 * 9.81 * Math.Sqrt(0.75) + 0.5 * elastic * elastic)).Within(1e-3));
        }

        [Test]
        public void FluidEnergy_IsKineticPlusPotential()
        {
            var phases = new[] { new PhaseProperties { ParticleMass = 2f } };
            var particles = new List<Particle> { new Particle(new Vector3(0f, 3f, 0f), new Vector3(4f, 0f, 0f), 0u, 0u) };
            Assert.That(FluidEnergy.Mechanical(particles, phases, new Vector3(0f, -10f, 0f)), Is.EqualTo(2.0 * (0.5 * 16 + 30)).Within(1e-9));
        }
    }
}
