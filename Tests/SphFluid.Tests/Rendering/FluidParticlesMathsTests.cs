using System;
using System.Collections.Generic;
using System.Numerics;
using NUnit.Framework;
using SphFluid.Compute;

namespace SphFluid.Tests.Rendering
{
    /// <summary>
    /// The particle shader's maths includes, run on the headless device through Shaders/ImpostorMaths.compute and
    /// compared with double-precision geometry: the quad covers the sphere's silhouette exactly (rays through its
    /// edge midpoints graze the sphere), the ray-cast hit lies on the sphere facing the eye with the right chord,
    /// the depth mapping follows both clip-space conventions, and Fresnel and absorption have their defining values.
    /// </summary>
    public sealed class FluidParticlesMathsTests
    {
        const float Tolerance = 2e-5f;

        static Vector4[] Run(string kernelName, string inputName, Vector4[] input, string outputName, int outputCount, int caseCount, int threads)
        {
            var device = GpuTestDevice.Shared;
            var program = device.LoadProgram("ImpostorMaths");
            int kernel = program.FindKernel(kernelName);
            var output = new Vector4[outputCount];
            using (var inBuffer = device.CreateBuffer(inputName, input.Length, 16))
            using (var outBuffer = device.CreateBuffer(outputName, outputCount, 16))
            {
                inBuffer.SetData(input);
                device.SetBuffer(program, kernel, device.PropertyId(inputName), inBuffer);
                device.SetBuffer(program, kernel, device.PropertyId(outputName), outBuffer);
                device.SetInt(program, device.PropertyId("_CaseCount"), caseCount);
                device.DispatchThreads(program, kernel, threads);
                outBuffer.GetData(output);
            }
            return output;
        }

        static Vector3 Xyz(Vector4 v) => new Vector3(v.X, v.Y, v.Z);

        /// <summary>Distance from point c to the line through a and b.</summary>
        static double DistanceToLine(Vector3 c, Vector3 a, Vector3 b)
        {
            Vector3 d = Vector3.Normalize(b - a);
            Vector3 ac = c - a;
            return (ac - Vector3.Dot(ac, d) * d).Length();
        }

        [Test]
        public void Quad_faces_the_eye_and_its_edges_graze_the_sphere_silhouette()
        {
            var centre = new Vector3(0.3f, 0.2f, -0.1f);
            const float radius = 0.05f;
            Vector3 up = Vector3.UnitY, right = Vector3.UnitX;
            var eyes = new[] { new Vector3(0.3f, 0.2f, 1.9f), new Vector3(1.5f, 0.8f, -0.4f), new Vector3(0.3f, 0.262f, -0.1f), new Vector3(0.3f, 3f, -0.1f) };
            var input = new List<Vector4>();
            foreach (var eye in eyes)
                input.AddRange(new[] { new Vector4(centre, radius), new Vector4(eye, 0f), new Vector4(up, 0f), new Vector4(right, 0f) });
            // Orthographic (camera looking down -z: towardEye = +z) and an eye inside the sphere.
            input.AddRange(new[] { new Vector4(centre, radius), new Vector4(0f, 0f, 1f, 1f), new Vector4(up, 0f), new Vector4(right, 0f) });
            input.AddRange(new[] { new Vector4(centre, radius), new Vector4(centre + new Vector3(0.01f, 0f, 0f), 0f), new Vector4(up, 0f), new Vector4(right, 0f) });
            int cases = eyes.Length + 2;
            var vertices = Run("QuadVertices", "_QuadCases", input.ToArray(), "_QuadVertices", cases * 6, cases, cases * 6);

            for (int c = 0; c < cases; c++)
            {
                var v = new Vector3[6];
                for (int k = 0; k < 6; k++) v[k] = Xyz(vertices[c * 6 + k]);
                float halfSize = vertices[c * 6].W;
                string what = "case " + c;
                if (c == cases - 1)
                {
                    Assert.That(halfSize, Is.EqualTo(0f), what + ": an eye inside the sphere draws nothing");
                    foreach (var p in v) Assert.That((p - centre).Length(), Is.LessThan(1e-6f), what);
                    continue;
                }
                bool orthographic = c == cases - 2;
                Vector3 eye = orthographic ? Vector3.Zero : eyes[c];
                Vector3 towardEye = orthographic ? Vector3.UnitZ : Vector3.Normalize(eye - centre);
                double d = (eye - centre).Length();
                double expected = orthographic ? radius : radius * d / Math.Sqrt(d * d - radius * radius);
                Assert.That(halfSize, Is.EqualTo(expected).Within(expected * 1e-5), what + " half size");

                // Two triangles 0 1 2 / 0 2 3 of a square centred on the sphere, in the plane facing the eye.
                Assert.That((v[3] - v[0]).Length(), Is.LessThan(1e-6f), what);
                Assert.That((v[4] - v[2]).Length(), Is.LessThan(1e-6f), what);
                foreach (var p in v)
                {
                    Assert.That(Vector3.Dot(p - centre, towardEye), Is.EqualTo(0f).Within(1e-5f), what + ": vertex off the facing plane");
                    Assert.That((p - centre).Length(), Is.EqualTo(halfSize * Math.Sqrt(2)).Within(halfSize * 1e-4), what + ": not a square corner");
                }
                Assert.That(Vector3.Dot(v[1] - v[0], v[5] - v[0]), Is.EqualTo(0f).Within(1e-6f), what + ": corners not at right angles");

                // Each edge midpoint seen from the eye (or along the view direction) grazes the sphere: the quad is
                // exactly as large as the silhouette, so no pixel of the sphere is cut off and none is wasted.
                var corners = new[] { v[0], v[1], v[2], v[5] };
                for (int e = 0; e < 4; e++)
                {
                    Vector3 mid = 0.5f * (corners[e] + corners[(e + 1) % 4]);
                    Vector3 from = orthographic ? mid + towardEye : eye;
                    Assert.That(DistanceToLine(centre, from, mid), Is.EqualTo(radius).Within(radius * 1e-3), what + " edge " + e);
                }
            }
        }

        [Test]
        public void Ray_cast_hit_lies_on_the_sphere_facing_the_eye_with_the_chord_as_thickness()
        {
            var centre = new Vector3(-0.2f, 0.4f, 0.7f);
            const float radius = 0.03f;
            var direction = Vector3.Normalize(new Vector3(0.3f, -0.5f, -0.8f));
            Vector3 across = Vector3.Normalize(Vector3.Cross(direction, Vector3.UnitY));
            var offsets = new[] { 0f, 0.5f, 0.99f, 1.01f, 1.5f };
            var alongRay = new[] { 0f, 0.7f * radius, -2f * radius };
            var input = new List<Vector4>();
            var expectedOffset = new List<float>();
            foreach (float s in offsets)
                foreach (float t in alongRay)
                {
                    Vector3 point = centre + across * (s * radius) + direction * t;
                    input.AddRange(new[] { new Vector4(point, radius), new Vector4(direction, 1f), new Vector4(centre, 0f), new Vector4(0f, 0f, 0.5f, 1f) });
                    expectedOffset.Add(s);
                }
            int cases = expectedOffset.Count;
            var hits = Run("Intersect", "_RayCases", input.ToArray(), "_RayHits", cases * 3, cases, cases);

            for (int c = 0; c < cases; c++)
            {
                float s = expectedOffset[c];
                Vector3 position = Xyz(hits[c * 3]);
                float thickness = hits[c * 3].W;
                Vector3 normal = Xyz(hits[c * 3 + 1]);
                float covered = hits[c * 3 + 1].W;
                string what = "offset " + s + " R, case " + c;
                Assert.That(covered, Is.EqualTo(s < 1f ? 1f : 0f), what + ": covered");
                if (s >= 1f) continue;
                Assert.That((position - centre).Length(), Is.EqualTo(radius).Within(radius * 1e-4), what + ": hit off the sphere");
                Assert.That(normal.Length(), Is.EqualTo(1f).Within(1e-4f), what + ": normal not unit");
                Assert.That((normal - (position - centre) / radius).Length(), Is.LessThan(1e-4f), what + ": normal not radial");
                Assert.That(Vector3.Dot(normal, -direction), Is.GreaterThanOrEqualTo(-1e-5f), what + ": the back of the sphere was hit");
                double chord = 2.0 * radius * Math.Sqrt(1.0 - s * s);
                Assert.That(thickness, Is.EqualTo(chord).Within(radius * 1e-3), what + ": thickness");
            }
        }

        [Test]
        public void Depth_maps_clip_space_to_the_depth_buffer_range_of_both_conventions()
        {
            // [clip z, clip w, near clip value] -> expected stored depth
            var cases = new[]
            {
                (-2f, 2f, -1f, 0f), (0f, 3f, -1f, 0.5f), (4f, 4f, -1f, 1f),            // OpenGL: z/w in [-1, 1]
                (0.5f, 2f, 0f, 0.25f), (1f, 1f, 1f, 1f), (0f, 5f, 1f, 0f),             // D3D/Vulkan/Metal, reversed or not
                (1.2f, 1f, 1f, 1f), (-0.3f, 1f, 0f, 0f),                                // outside [0, 1]: clamped
            };
            var input = new List<Vector4>();
            foreach (var (z, w, near, _) in cases)
                input.AddRange(new[] { new Vector4(0f, 0f, 0f, 1f), new Vector4(0f, 0f, -1f, near), Vector4.Zero, new Vector4(0f, 0f, z, w) });
            var hits = Run("Intersect", "_RayCases", input.ToArray(), "_RayHits", cases.Length * 3, cases.Length, cases.Length);
            for (int c = 0; c < cases.Length; c++)
                Assert.That(hits[c * 3 + 2].X, Is.EqualTo(cases[c].Item4).Within(1e-6f), "case " + c);
        }

        [Test]
        public void Fresnel_and_absorption_have_their_defining_values()
        {
            var cases = new List<(Vector4 optics, Vector3 tint)>
            {
                (new Vector4(0.02f, 1f, 0f, 0f), new Vector3(0.2f, 0.6f, 0.8f)),      // normal incidence: F0; nothing absorbed
                (new Vector4(0.035f, 0f, 5f, 0.2f), new Vector3(0.9f, 0.6f, 0.1f)),   // grazing: F = 1; a L = 1: T = tint
                (new Vector4(0.02f, 0.5f, 8f, 0.5f), new Vector3(0.25f, 0.65f, 0.75f)),
                (new Vector4(0.02f, 0.3f, 10f, 1f), new Vector3(0f, 1f, 0.5f)),       // a black channel stays finite
            };
            var input = new List<Vector4>();
            foreach (var (optics, tint) in cases) input.AddRange(new[] { optics, new Vector4(tint, 0f) });
            var results = Run("Optics", "_OpticsCases", input.ToArray(), "_OpticsResults", cases.Count, cases.Count, cases.Count);

            for (int c = 0; c < cases.Count; c++)
            {
                var (optics, tint) = cases[c];
                double f0 = optics.X, cos = optics.Y, aL = (double)optics.Z * optics.W;
                double fresnel = f0 + (1 - f0) * Math.Pow(1 - cos, 5);
                Assert.That(results[c].W, Is.EqualTo(fresnel).Within(Tolerance), "case " + c + " Fresnel");
                var channels = new[] { tint.X, tint.Y, tint.Z };
                var got = new[] { results[c].X, results[c].Y, results[c].Z };
                for (int k = 0; k < 3; k++)
                {
                    double expected = Math.Pow(Math.Max(channels[k], 1e-3), aL);
                    Assert.That(got[k], Is.EqualTo(expected).Within(Math.Max(Tolerance, expected * 1e-4)), "case " + c + " channel " + k);
                }
            }
        }
    }
}
