using System.Collections.Generic;

namespace SphFluid.Compute
{
    /// <summary>One <c>.compute</c> file: its kernels and keywords (Unity's <c>ComputeShader</c>).</summary>
    public interface IComputeProgram
    {
        /// <summary>The asset path the program was loaded from.</summary>
        string Name { get; }

        /// <summary>The kernel's index; throws <see cref="ComputeException"/> naming the kernel if absent.</summary>
        int FindKernel(string kernelName);

        bool HasKernel(string kernelName);

        /// <summary>The kernel's <c>[numthreads(x, y, z)]</c>.</summary>
        void GetKernelThreadGroupSizes(int kernel, out uint x, out uint y, out uint z);

        /// <summary>The <c>multi_compile</c> keywords the file declares.</summary>
        IReadOnlyList<string> Keywords { get; }
    }
}
