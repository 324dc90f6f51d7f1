namespace SphFluid.Headless.Output;

/// <summary>
/// Where one phase sits and how far its density strays from rest, at one instant.
/// Heights are world heights (along -gravity from the container's lowest corner, m): the mean, the lowest
/// particle (<see cref="Bottom"/>) and the highest (<see cref="Top"/>). <see cref="FloorShare"/> and
/// <see cref="WallShare"/> are the phase's fraction of the particles in the floor layer and in the wall layers
/// (within one spacing of the container-local floor, of any of the four walls): 1 means the phase alone wets
/// them. Compression is max(0, rho / rho0 - 1) and expansion max(0, 1 - rho / rho0), each averaged over the
/// phase and at its worst particle; keeping them apart shows the under-density next to walls and at the free
/// surface that a signed or compression-only error hides. NaN where the phase has no particle (or the layer none).
/// </summary>
public sealed record PhaseMeasures(int Count, double MeanHeight, double Bottom, double Top, double FloorShare, double WallShare,
    double CompressionAverage, double CompressionMax, double ExpansionAverage, double ExpansionMax);
