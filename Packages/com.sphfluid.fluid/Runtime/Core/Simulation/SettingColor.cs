using System;
using System.Numerics;

namespace SphFluid.Simulation
{
    /// <summary>
    /// A colour setting in a form Unity serializes (a [Serializable] struct of public fields; System.Numerics.Vector4
    /// is not one), converting implicitly to and from <see cref="Vector4"/> (r, g, b, a = X, Y, Z, W) for the phase
    /// table. The core keeps colours linear, as the shaders blend them; the Unity inspector shows and picks them as sRGB
    /// and converts at its edge (the package's colour drawer), so a stored value is never a mix of the two.
    /// </summary>
    [Serializable]
    public struct SettingColor : IEquatable<SettingColor>
    {
        public float r;
        public float g;
        public float b;
        public float a;

        public SettingColor(float r, float g, float b, float a)
        {
            this.r = r;
            this.g = g;
            this.b = b;
            this.a = a;
        }

        public static implicit operator Vector4(SettingColor c) => new Vector4(c.r, c.g, c.b, c.a);

        public static implicit operator SettingColor(Vector4 v) => new SettingColor(v.X, v.Y, v.Z, v.W);

        public bool Equals(SettingColor other) => r.Equals(other.r) && g.Equals(other.g) && b.Equals(other.b) && a.Equals(other.a);

        public override bool Equals(object obj) => obj is SettingColor other && Equals(other);

        public override int GetHashCode() => ((Vector4)this).GetHashCode();

        public override string ToString() =>
            $"({ValidationRules.Format(r)}, {ValidationRules.Format(g)}, {ValidationRules.Format(b)}, {ValidationRules.Format(a)})";
    }
}
