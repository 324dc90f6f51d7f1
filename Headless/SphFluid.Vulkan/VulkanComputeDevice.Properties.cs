using System;
using System.Collections.Generic;
using SphFluid.Compute;

namespace SphFluid.Vulkan;

/// <summary>Shader property ids: one process-wide registry, as Unity's Shader.PropertyToID.</summary>
public sealed unsafe partial class VulkanComputeDevice
{
    static readonly object PropertyLock = new();
    static readonly Dictionary<string, int> PropertyIds = new(StringComparer.Ordinal);
    static readonly List<string> PropertyNames = new();

    public int PropertyId(string name) => PropertyIdOf(name);

    /// <summary>The process-wide id of a shader property name.</summary>
    public static int PropertyIdOf(string name)
    {
        if (name == null) throw new ArgumentNullException(nameof(name));
        lock (PropertyLock)
        {
            if (PropertyIds.TryGetValue(name, out int id)) return id;
            id = PropertyNames.Count;
            PropertyNames.Add(name);
            PropertyIds[name] = id;
            return id;
        }
    }

    /// <summary>The name behind a property id.</summary>
    public static string PropertyName(int id)
    {
        lock (PropertyLock)
        {
            if (id < 0 || id >= PropertyNames.Count) throw new ComputeException($"Property id {id} was not made by PropertyId");
            return PropertyNames[id];
        }
    }
}
