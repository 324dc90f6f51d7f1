namespace SphFluid.Simulation
{
    /// <summary>One refused value: the field it concerns, the object it belongs to and the rule it breaks.</summary>
    public sealed class ValidationError
    {
        /// <summary>Dotted path of the offending field, e.g. "SpawnBoxes[0].Phase.RestDensity".</summary>
        public string Field { get; }

        /// <summary>The object the field belongs to, as a user knows it, e.g. "SpawnBox 'Water'" or "FluidSettings".</summary>
        public string Owner { get; }

        /// <summary>The rule, the range and the value, without the owner: "RestDensity must be in [1, 100000] kg/m^3
        /// (was -3)". A reader that names the object itself (a scene file's GameObject and line) prints this.</summary>
        public string Rule { get; }

        /// <summary>e.g. "SpawnBox 'Water': RestDensity must be in [1, 100000] kg/m^3 (was -3)".</summary>
        public string Message => Owner + ": " + Rule;

        public ValidationError(string field, string owner, string rule)
        {
            Field = field;
            Owner = owner;
            Rule = rule;
        }

        public override string ToString() => Message;
    }
}
