using NVector3 = System.Numerics.Vector3;
using NVector4 = System.Numerics.Vector4;
using NQuaternion = System.Numerics.Quaternion;
using NMatrix4x4 = System.Numerics.Matrix4x4;
using SphFluid.Simulation;

namespace SphFluid.Runtime
{
    /// <summary>
    /// The engine-free core speaks System.Numerics, Unity speaks UnityEngine; these are the only crossings.
    /// Both quaternion types store (x, y, z, w) for the same rotation, so they copy component-wise.
    /// </summary>
    public static class NumericsConversion
    {
        public static NVector3 ToNumerics(this UnityEngine.Vector3 v) => new NVector3(v.x, v.y, v.z);

        public static NVector4 ToNumerics(this UnityEngine.Vector4 v) => new NVector4(v.x, v.y, v.z, v.w);

        public static NVector4 ToNumerics(this UnityEngine.Color c) => new NVector4(c.r, c.g, c.b, c.a);

        /// <summary>A colour as the inspector picks it (sRGB, like every UnityEngine.Color field) to the core's linear
        /// value: Unity's own transfer curve (Color.linear), alpha unchanged.</summary>
        public static SettingColor ToLinearSetting(this UnityEngine.Color srgb)
        {
            UnityEngine.Color linear = srgb.linear;
            return new SettingColor(linear.r, linear.g, linear.b, linear.a);
        }

        /// <summary>The core's linear colour as the inspector shows it (sRGB, Color.gamma), alpha unchanged.</summary>
        public static UnityEngine.Color ToInspectorColor(this SettingColor linear) =>
            new UnityEngine.Color(linear.r, linear.g, linear.b, linear.a).gamma;

        public static NQuaternion ToNumerics(this UnityEngine.Quaternion q) => new NQuaternion(q.x, q.y, q.z, q.w);

        public static UnityEngine.Vector3 ToUnity(this NVector3 v) => new UnityEngine.Vector3(v.X, v.Y, v.Z);

        public static UnityEngine.Vector4 ToUnity(this NVector4 v) => new UnityEngine.Vector4(v.X, v.Y, v.Z, v.W);

        public static UnityEngine.Quaternion ToUnity(this NQuaternion q) => new UnityEngine.Quaternion(q.X, q.Y, q.Z, q.W);

        /// <summary>
        /// The compute interface's rule is "managed M{r}{c} is HLSL m[r-1][c-1]". Unity uploads a Matrix4x4 so
        /// that HLSL m[r][c] is its m[r, c] (mul(m, float4(p, 1)) == m.MultiplyPoint(p)), so the copy is
        /// element-wise with no transpose.
        /// </summary>
        public static UnityEngine.Matrix4x4 ToUnity(this NMatrix4x4 m)
        {
            var u = new UnityEngine.Matrix4x4();
            u.m00 = m.M11; u.m01 = m.M12; u.m02 = m.M13; u.m03 = m.M14;
            u.m10 = m.M21; u.m11 = m.M22; u.m12 = m.M23; u.m13 = m.M24;
            u.m20 = m.M31; u.m21 = m.M32; u.m22 = m.M33; u.m23 = m.M34;
            u.m30 = m.M41; u.m31 = m.M42; u.m32 = m.M43; u.m33 = m.M44;
            return u;
        }
    }
}
