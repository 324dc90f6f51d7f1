using System;
using System.Collections.Generic;
using NUnit.Framework;
using SphFluid.Runtime;
using UnityEngine;

namespace SphFluid.Tests.EditMode
{
    /// <summary>Every component the package ships sits under one Add Component folder, so a user finds the fluid's
    /// parts together rather than under the namespace Unity would otherwise file them by.</summary>
    public sealed class ComponentMenuTests
    {
        const string Folder = "SPH Fluid/";

        [Test]
        public void EveryPackageComponentIsInTheSphFluidFolder()
        {
            var components = new List<Type>();
            foreach (Type type in typeof(Fluid).Assembly.GetTypes())
                if (typeof(MonoBehaviour).IsAssignableFrom(type) && !type.IsAbstract) components.Add(type);
            Assert.That(components, Is.Not.Empty);
            foreach (Type type in components)
            {
                var menu = (AddComponentMenu)Attribute.GetCustomAttribute(type, typeof(AddComponentMenu));
                Assert.That(menu, Is.Not.Null, type.Name + " has no [AddComponentMenu]");
                Assert.That(menu.componentMenu, Does.StartWith(Folder), type.Name);
            }
        }
    }
}
