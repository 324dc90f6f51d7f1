using System;
using System.Numerics;

namespace SphFluid.Headless.Output;

/// <summary>
/// Which particles have company: cells of the given radius, sorted by cell key, answer "how many other
/// particles lie within the radius of this one" in O(log N). The surge front and the back-wall column use it
/// to skip isolated particles (spray and single splashes), which would otherwise decide both figures.
/// </summary>
public sealed class ParticleNeighbourhood
{
    readonly Vector3[] _positions;
    readonly float _radius;
    readonly long[] _keys;
    readonly int[] _order;

    /// <param name="positions">Particle positions (any frame; distances are all that matter). Non-finite ones never count.</param>
    /// <param name="radius">Neighbour distance, m (&gt; 0).</param>
    public ParticleNeighbourhood(Vector3[] positions, float radius)
    {
        if (!(radius > 0) || !float.IsFinite(radius))
            throw new ArgumentOutOfRangeException(nameof(radius), radius, "ParticleNeighbourhood: radius must be a positive length");
        _positions = positions ?? throw new ArgumentNullException(nameof(positions));
        _radius = radius;
        _keys = new long[positions.Length];
        _order = new int[positions.Length];
        for (int i = 0; i < positions.Length; i++)
        {
            _order[i] = i;
            _keys[i] = Finite(positions[i]) ? Key(Cell(positions[i], 0), Cell(positions[i], 1), Cell(positions[i], 2)) : long.MaxValue;
        }
        Array.Sort(_keys, _order);
    }

    /// <summary>Whether fewer than <paramref name="company"/> other particles lie within the radius of particle <paramref name="i"/>.</summary>
    public bool IsIsolated(int i, int company)
    {
        var p = _positions[i];
        if (!Finite(p)) return true;
        if (company <= 0) return false;
        float r2 = _radius * _radius;
        int cx = Cell(p, 0), cy = Cell(p, 1), cz = Cell(p, 2), found = 0;
        for (int dz = -1; dz <= 1; dz++)
            for (int dy = -1; dy <= 1; dy++)
                for (int dx = -1; dx <= 1; dx++)
                {
                    long key = Key(cx + dx, cy + dy, cz + dz);
                    int s = Array.BinarySearch(_keys, key);
                    if (s < 0) continue;
                    while (s > 0 && _keys[s - 1] == key) s--;
                    for (; s < _keys.Length && _keys[s] == key; s++)
                    {
                        int j = _order[s];
                        if (j != i && Vector3.DistanceSquared(p, _positions[j]) <= r2 && ++found >= company) return false;
                    }
                }
        return true;
    }

    int Cell(Vector3 p, int axis) => (int)Math.Floor((axis == 0 ? p.X : axis == 1 ? p.Y : p.Z) / _radius);

    // 21 bits a cell coordinate: a 2M-cell span per axis, far beyond any container the runner simulates.
    static long Key(int x, int y, int z) => ((long)(x & 0x1FFFFF) << 42) | ((long)(y & 0x1FFFFF) << 21) | (long)(z & 0x1FFFFF);

    static bool Finite(Vector3 p) => float.IsFinite(p.X) && float.IsFinite(p.Y) && float.IsFinite(p.Z);
}
