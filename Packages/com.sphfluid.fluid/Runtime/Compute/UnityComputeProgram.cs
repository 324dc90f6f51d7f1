using System.Collections.Generic;
using SphFluid.Compute;
using UnityEngine;
using UnityEngine.Rendering;

namespace SphFluid.Runtime
{
    /// <summary>A <see cref="ComputeShader"/> asset seen through <see cref="IComputeProgram"/>.</summary>
    public sealed class UnityComputeProgram : IComputeProgram
    {
        readonly Dictionary<string, LocalKeyword> _keywords = new Dictionary<string, LocalKeyword>();
        readonly string[] _keywordNames;

        public UnityComputeProgram(ComputeShader shader)
        {
            Shader = shader;
            Name = shader.name;
            _keywordNames = shader.keywordSpace.keywordNames;
        }

        public ComputeShader Shader { get; }

        public string Name { get; }

        public IReadOnlyList<string> Keywords => _keywordNames;

        public bool HasKernel(string kernelName) => Shader.HasKernel(kernelName);

        public int FindKernel(string kernelName)
        {
            // ComputeShader.FindKernel logs an error and throws for a missing kernel; name the program too.
            if (!Shader.HasKernel(kernelName))
                throw new ComputeException($"Compute shader '{Name}' has no kernel '{kernelName}'");
            return Shader.FindKernel(kernelName);
        }

        public void GetKernelThreadGroupSizes(int kernel, out uint x, out uint y, out uint z)
        {
            Shader.GetKernelThreadGroupSizes(kernel, out x, out y, out z);
        }

        /// <summary>The local keyword of this shader, looked up once; throws naming the shader if it declares none such.</summary>
        public LocalKeyword Keyword(string keyword)
        {
            if (_keywords.TryGetValue(keyword, out LocalKeyword found)) return found;
            LocalKeyword local = Shader.keywordSpace.FindKeyword(keyword);
            if (!local.isValid)
                throw new ComputeException($"Compute shader '{Name}' declares no keyword '{keyword}' (multi_compile_local)");
            _keywords.Add(keyword, local);
            return local;
        }

        public override string ToString() => Name;
    }
}
