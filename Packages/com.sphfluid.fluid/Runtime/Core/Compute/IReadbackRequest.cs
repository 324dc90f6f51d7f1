namespace SphFluid.Compute
{
    /// <summary>An asynchronous read-back in flight (Unity's <c>AsyncGPUReadbackRequest</c>).</summary>
    public interface IReadbackRequest
    {
        bool IsDone { get; }
        bool HasError { get; }

        /// <summary>Copies the read-back elements into <paramref name="destination"/>; only once <see cref="IsDone"/>.</summary>
        void GetData<T>(T[] destination) where T : struct;
    }
}
