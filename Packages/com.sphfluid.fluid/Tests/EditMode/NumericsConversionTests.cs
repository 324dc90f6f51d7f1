using NUnit.Framework;
using SphFluid.Runtime;
using UnityEngine;
using NMatrix4x4 = System.Numerics.Matrix4x4;
using NVector3 = System.Numerics.Vector3;

namespace SphFluid.Tests.EditMode
{
    /// <summary>The crossings between System.Numerics and UnityEngine keep the compute interface's conventions.</summary>
    public sealed class NumericsConversionTests
    {
        [Test]
        public void MatrixElementRcBecomesUnityRowColumnSoTranslationStaysInTheLastColumn()
        {
            // The interface's transforms are for column vectors: translation in M14, M24, M34.
            var m = NMatrix4x4.Identity;
            m.M14 = 1f;
            m.M24 = 2f;
            m.M34 = 3f;
            m.M12 = 0.5f;
            Matrix4x4 u = m.ToUnity();
            Assert.That(u.m03, Is.EqualTo(1f));
            Assert.That(u.m13, Is.EqualTo(2f));
            Assert.That(u.m23, Is.EqualTo(3f));
            Assert.That(u.m01, Is.EqualTo(0.5f));
            Vector3 p = u.MultiplyPoint(new Vector3(0f, 2f, 0f));
            Assert.That(p.x, Is.EqualTo(2f).Within(1e-6f), "row 0: x + 0.5 y + 1");
            Assert.That(p.y, Is.EqualTo(4f).Within(1e-6f));
            Assert.That(p.z, Is.EqualTo(3f).Within(1e-6f));
        }

        [Test]
        public void QuaternionsRotateAlike()
        {
            Quaternion q = Quaternion.Euler(30f, 60f, -20f);
            Vector3 unity = q * new Vector3(0.3f, -0.2f, 1f);
            NVector3 numerics = NVector3.Transform(new NVector3(0.3f, -0.2f, 1f), q.ToNumerics());
            Assert.That(numerics.X, Is.EqualTo(unity.x).Within(1e-5f));
            Assert.That(numerics.Y, Is.EqualTo(unity.y).Within(1e-5f));
            Assert.That(numerics.Z, Is.EqualTo(unity.z).Within(1e-5f));
            Assert.That(q.ToNumerics().ToUnity() == q, Is.True);
        }
    }
}
