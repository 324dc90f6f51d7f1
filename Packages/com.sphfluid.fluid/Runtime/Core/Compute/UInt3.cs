using System.Runtime.InteropServices;

namespace SphFluid.Compute
{
    /// <summary>HLSL's <c>uint3</c> in a constant buffer: three 4-byte words, as <see cref="System.Numerics.Vector3"/> is
    /// its <c>float3</c>.</summary>
    [StructLayout(LayoutKind.Sequential)]
    public struct UInt3
    {
        public uint X, Y, Z;

        public UInt3(uint x, uint y, uint z)
        {
            X = x;
            Y = y;
            Z = z;
        }
    }
}
