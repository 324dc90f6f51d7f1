namespace SphFluid.Simulation
{
    /// <summary>One refused value: the field it concerns and a message naming object, field, range and value.</summary>
    public sealed class ValidationError
    {
        /// <summary>Dotted path of the offending field, e.g. "SpawnBoxes[0].Phase.RestDensity".</summary>
        public string Field { get; }

        /// <summary>e.g. "SpawnBox 'Water': RestDensity must be in [1, 100000] kg/m^3 (was -3)".</summary>
        public string Message { get; }

        public ValidationError(string field, string message)
        {
            Field = field;
            Message = message;
        }

        public override string ToString() => Message;
    }
}
