using System;

namespace SphFluid.Compute
{
    /// <summary>A misuse of the compute interface (unknown kernel, unbound buffer, stride mismatch,
    /// shader compile error), with a message that names the culprit.</summary>
    public sealed class ComputeException : Exception
    {
        public ComputeException(string message) : base(message) { }
        public ComputeException(string message, Exception inner) : base(message, inner) { }
    }
}
