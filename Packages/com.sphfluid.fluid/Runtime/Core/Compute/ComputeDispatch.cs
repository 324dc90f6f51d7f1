using System;

namespace SphFluid.Compute
{
    /// <summary>Thread-group arithmetic shared by every dispatch.</summary>
    public static class ComputeDispatch
    {
        /// <summary>Groups needed so that <paramref name="groupSize"/>-wide groups cover <paramref name="threads"/> threads.</summary>
        public static int GroupsFor(int threads, uint groupSize)
        {
            if (threads < 0) throw new ArgumentOutOfRangeException(nameof(threads), threads, "must be >= 0");
            if (groupSize == 0) throw new ArgumentOutOfRangeException(nameof(groupSize), "must be > 0");
            return (int)((threads + groupSize - 1) / groupSize);
        }

        /// <summary>Dispatches one thread per item along x for a 1-D kernel.</summary>
        public static void DispatchThreads(this IComputeDevice device, IComputeProgram program, int kernel, int threads)
        {
            program.GetKernelThreadGroupSizes(kernel, out uint x, out _, out _);
            int groups = GroupsFor(threads, x);
            if (groups > 0) device.Dispatch(program, kernel, groups, 1, 1);
        }
    }
}
