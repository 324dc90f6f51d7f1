using System;
using System.Collections.Generic;
using Silk.NET.Vulkan;

namespace SphFluid.Vulkan;

/// <summary>Query pools a frame records into (timestamps, invocation counts), grown on first use and read once its fence has signalled.</summary>
public sealed unsafe partial class VulkanComputeDevice
{
    /// <summary>One type of query a frame records, in pools of <see cref="QueriesPerPool"/>; each pool is reset in the
    /// command buffer before its first query of the submit.</summary>
    sealed class QuerySet
    {
        public readonly QueryType Type;
        public readonly QueryPipelineStatisticFlags Statistics;
        public readonly List<QueryPool> Pools = new();
        public uint Used;

        public QuerySet(QueryType type, QueryPipelineStatisticFlags statistics = 0)
        {
            Type = type;
            Statistics = statistics;
        }
    }

    /// <summary>The first of <paramref name="count"/> consecutive queries of <paramref name="set"/>, all in one pool.</summary>
    uint AllocateQuery(Frame f, QuerySet set, uint count)
    {
        uint inPool = set.Used % QueriesPerPool;
        if (inPool + count > QueriesPerPool) set.Used += QueriesPerPool - inPool;
        uint first = set.Used;
        for (uint q = first; q < first + count; q++)
        {
            if (q % QueriesPerPool != 0) continue;
            int poolIndex = (int)(q / QueriesPerPool);
            if (poolIndex == set.Pools.Count)
            {
                var info = new QueryPoolCreateInfo
                {
                    SType = StructureType.QueryPoolCreateInfo, QueryType = set.Type, QueryCount = QueriesPerPool, PipelineStatistics = set.Statistics,
                };
                Check(_vk.CreateQueryPool(_device, &info, null, out var pool), "vkCreateQueryPool");
                set.Pools.Add(pool);
            }
            _vk.CmdResetQueryPool(f.Cmd, set.Pools[poolIndex], 0, QueriesPerPool);
        }
        set.Used = first + count;
        return first;
    }

    (QueryPool Pool, uint Index) Slot(QuerySet set, uint query) => (set.Pools[(int)(query / QueriesPerPool)], query % QueriesPerPool);

    /// <summary>Every query of the set's last submit as one 64-bit value (a timestamp, or the one statistic asked for),
    /// indexed by query; a slot skipped to keep a pair in one pool reads zero.</summary>
    ulong[] ReadQueries(QuerySet set)
    {
        var values = new ulong[set.Used];
        fixed (ulong* dst = values)
        {
            for (int i = 0; i < set.Pools.Count; i++)
            {
                uint first = (uint)i * QueriesPerPool;
                if (first >= set.Used) break;
                uint n = Math.Min(QueriesPerPool, set.Used - first);
                // Skipped slots were reset but never written: without the wait bit, read what is available.
                _vk.GetQueryPoolResults(_device, set.Pools[i], 0, n, (nuint)(n * 8), dst + first, 8, QueryResultFlags.Result64Bit);
            }
        }
        return values;
    }
}
