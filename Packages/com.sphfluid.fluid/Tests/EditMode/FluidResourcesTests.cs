using NUnit.Framework;
using SphFluid.Runtime;
using UnityEditor;
using UnityEngine;

namespace SphFluid.Tests.EditMode
{
    /// <summary>The package's resources asset loads as Resources.Load finds it in a player, with every field wired.</summary>
    public sealed class FluidResourcesTests
    {
        [Test]
        public void TheResourcesAssetLoadsWithEveryShaderAndTheMaterial()
        {
            FluidResources resources = FluidResources.Load();
            Assert.That(resources, Is.Not.Null, "Resources/" + FluidResources.ResourceName + ".asset");
            Assert.That(resources.MissingField(), Is.Null);
            string[] programs = { "FluidSolver", "FluidDiagnostics", "ParticleSort", "PrefixSum" };
            ComputeShader[] shaders = resources.ComputeShaders();
            for (int i = 0; i < programs.Length; i++)
                Assert.That(shaders[i].name, Is.EqualTo(programs[i]), "compute shader " + i);
            Assert.That(resources.UniversalParticleShader.name, Is.EqualTo("SphFluid/ParticlesUniversal"));
            Assert.That(AssetDatabase.GetAssetPath(resources.ParticleMaterial), Is.EqualTo("Packages/com.sphfluid.fluid/Materials/FluidParticles.mat"));
        }
    }
}
