using System;
using System.Collections.Generic;
using Silk.NET.Vulkan;
using SphFluid.Compute;

namespace SphFluid.Vulkan;

/// <summary>
/// How many compute invocations each dispatch ran, counted by the device (a pipeline-statistics query around the dispatch).
/// An indirect dispatch whose arguments a kernel set to zero groups records like any other, and its timing alone cannot
/// tell it from a short one that ran; its count of invocations can.
/// </summary>
public sealed unsafe partial class VulkanComputeDevice
{
    bool _countInvocations;
    IReadOnlyList<(string Kernel, ulong Invocations)> _lastDispatchInvocations = Array.Empty<(string, ulong)>();
    ulong _lastDispatchInvocationsSerial;

    /// <summary>Whether the device has Vulkan's <c>pipelineStatisticsQuery</c> feature, which <see cref="CountInvocations"/> needs.</summary>
    public bool CanCountInvocations { get; private set; }

    /// <summary>When true, every dispatch recorded from now on counts the invocations it ran
    /// (<see cref="LastDispatchInvocations"/>). Off by default: a query around every dispatch is work a run does not need.</summary>
    public bool CountInvocations
    {
        get => _countInvocations;
        set
        {
            ThrowIfDisposed();
            if (value && !CanCountInvocations)
                throw new ComputeException($"{DeviceName} cannot count a dispatch's invocations: it lacks Vulkan's pipelineStatisticsQuery feature");
            _countInvocations = value;
        }
    }

    /// <summary>The compute invocations of every counted dispatch of the last submit that counted any, in order
    /// (waits for it); a dispatch of zero groups counts zero.</summary>
    public IReadOnlyList<(string Kernel, ulong Invocations)> LastDispatchInvocations
    {
        get
        {
            ThrowIfDisposed();
            WaitForSerial(_submittedSerial);
            return _lastDispatchInvocations;
        }
    }

    uint BeginInvocationCount(Frame f)
    {
        uint query = AllocateQuery(f, f.Invocations, 1);
        var (pool, index) = Slot(f.Invocations, query);
        _vk.CmdBeginQuery(f.Cmd, pool, index, 0);
        return query;
    }

    void EndInvocationCount(Frame f, string kernel, uint query)
    {
        var (pool, index) = Slot(f.Invocations, query);
        _vk.CmdEndQuery(f.Cmd, pool, index);
        f.InvocationQueries.Add((kernel, query));
    }

    void HarvestInvocations(Frame f)
    {
        if (f.InvocationQueries.Count == 0 || f.Serial < _lastDispatchInvocationsSerial) return;
        var values = ReadQueries(f.Invocations);
        var counts = new (string, ulong)[f.InvocationQueries.Count];
        for (int i = 0; i < counts.Length; i++) counts[i] = (f.InvocationQueries[i].Kernel, values[f.InvocationQueries[i].Query]);
        _lastDispatchInvocations = counts;
        _lastDispatchInvocationsSerial = f.Serial;
    }
}
