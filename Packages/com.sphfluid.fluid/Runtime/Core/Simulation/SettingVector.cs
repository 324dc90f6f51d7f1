using System;
using System.Numerics;

namespace SphFluid.Simulation
{
    /// <summary>
    /// A vector setting in a form Unity serializes (a [Serializable] struct of public fields; System.Numerics.Vector3
    /// is not one), converting implicitly to and from <see cref="Vector3"/> for the solver.
    /// </summary>
    [Serializable]
    public struct SettingVector : IEquatable<SettingVector>
    {
        public float x;
        public float y;
        public float z;

        public SettingVector(float x, float y, float z)
        {
            this.x = x;
            this.y = y;
            this.z = z;
        }

        public float Length() => ((Vector3)this).Length();

        public static implicit operator Vector3(SettingVector v) => new Vector3(v.x, v.y, v.z);

        public static implicit operator SettingVector(Vector3 v) => new SettingVector(v.X, v.Y, v.Z);

        public bool Equals(SettingVector other) => x.Equals(other.x) && y.Equals(other.y) && z.Equals(other.z);

        public override bool Equals(object obj) => obj is SettingVector other && Equals(other);

        public override int GetHashCode() => ((Vector3)this).GetHashCode();

        public override string ToString() => ValidationRules.Format((Vector3)this);
    }
}
