#ifndef SPHFLUID_PREFIX_SUM_BLOCK_INCLUDED
#define SPHFLUID_PREFIX_SUM_BLOCK_INCLUDED

// Block geometry of the multi-block exclusive scan in PrefixSum.compute (Blelloch 1990; GPU form
// after Harris, Sengupta & Owens, GPU Gems 3 ch. 39). C# mirrors these numbers in
// SphFluid.Sorting.PrefixSum (ThreadsPerGroup, ElementsPerGroup): change both together.
#define SCAN_THREADS 256u
#define SCAN_THREADS_LOG2 8u
#define SCAN_PER_THREAD 8u
#define SCAN_BLOCK 2048u // SCAN_THREADS * SCAN_PER_THREAD

// A scan short enough for one group (ScanSmall): each thread reads its SCAN_SMALL_PER_THREAD consecutive elements
// straight from the buffer, twice, instead of through groupshared memory, so one group covers eight blocks within
// D3D11's 32 KB of groupshared memory.
#define SCAN_SMALL_PER_THREAD 64u
#define SCAN_SMALL_LENGTH 16384u // SCAN_THREADS * SCAN_SMALL_PER_THREAD

// One padding word per 32 elements (Harris et al.'s CONFLICT_FREE_OFFSET with 32 banks): a thread
// reading its SCAN_PER_THREAD consecutive elements then lands in a bank no other lane of its warp uses.
#define SCAN_PADDED_BLOCK (SCAN_BLOCK + SCAN_BLOCK / 32u)

uint ScanPaddedIndex(uint i)
{
    return i + (i >> 5);
}

#endif
