using NUnit.Framework;
using SphFluid.Vulkan;

namespace SphFluid.Tests.Backend
{
    /// <summary>Which <c>const</c> declarations become settable globals, as in Unity, and which stay constants.</summary>
    public sealed class BackendConstGlobalTests
    {
        [TestCase("const uint numParticles;", "      uint numParticles;")]
        [TestCase("const float a, b;\nconst float3 c;", "      float a, b;\n      float3 c;")]
        [TestCase("uniform const float g;", "uniform       float g;")]
        [TestCase("#define N 4\nconst uint n; // count", "#define N 4\n      uint n; // count")]
        [TestCase("struct S { float x; };\nconst S s;", "struct S { float x; };\n      S s;")]
        [TestCase("void F() { }\nconst uint n;", "void F() { }\n      uint n;")]
        public void UninitialisedFileScopeConstsBecomeSettable(string source, string expected)
        {
            Assert.That(ConstGlobals.MakeSettable(source), Is.EqualTo(expected));
        }

        [TestCase("static const float pi = 3.14159;")]
        [TestCase("const float half = 0.5;")]
        [TestCase("static const uint count;")]
        [TestCase("const static uint count;")]
        [TestCase("float Twice(const float x) { const float k = 2.0; return k * x; }")]
        [TestCase("void F() { const float k; }")]
        [TestCase("cbuffer P { const float k; };")]
        [TestCase("// const uint commented;\n/* const uint blocked; */")]
        [TestCase("#define DECLARE const uint n;")]
        public void EverythingElseIsLeftAlone(string source)
        {
            Assert.That(ConstGlobals.MakeSettable(source), Is.EqualTo(source));
        }
    }
}
