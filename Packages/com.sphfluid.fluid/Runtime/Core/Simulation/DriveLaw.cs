using System;
using System.Collections.Generic;
using System.Numerics;

namespace SphFluid.Simulation
{
    /// <summary>
    /// The law of a driven sphere, as a function of time: start + travel (1 - cos(2 pi t' / period)) / 2 with
    /// t' = t - startDelay, so the sphere starts and turns at rest; its velocity is the derivative. One law for the
    /// Unity SphereDriver and the headless runner; each field declared once (<see cref="SettingAttribute"/>).
    /// </summary>
    [Serializable]
    public sealed class DriveLaw
    {
        const string Group = "Drive";

        [Setting(Group, 0, 1000, "m", "From the start position to the far end of the path, world space.")]
        public SettingVector Travel = new Vector3(0.3f, 0f, 0f);

        [Setting(Group, 0.1, 3600, "s", "Time for one trip there and back.")]
        public float Period = 4f;

        [Setting(Group, 0, 3600, "s", "Time after start before moving, so the fluid can settle first.")]
        public float StartDelay = 1f;

        /// <summary>Offset from the start position at time <paramref name="t"/>, m.</summary>
        public Vector3 Offset(double t)
        {
            double phaseTime = t - StartDelay;
            if (phaseTime < 0 || !(Period >= 0.1f)) return Vector3.Zero;
            return (Vector3)Travel * (float)(0.5 - 0.5 * Math.Cos(2.0 * Math.PI / Period * phaseTime));
        }

        /// <summary>Velocity at time <paramref name="t"/>, m/s.</summary>
        public Vector3 Velocity(double t)
        {
            double phaseTime = t - StartDelay;
            if (phaseTime < 0 || !(Period >= 0.1f)) return Vector3.Zero;
            double w = 2.0 * Math.PI / Period;
            return (Vector3)Travel * (float)(0.5 * w * Math.Sin(w * phaseTime));
        }

        /// <summary>A sphere at rest moved to time <paramref name="to"/>, with the velocity that brought it there from
        /// time <paramref name="from"/> (a frame): what a Unity Transform moved by this law reads, and what
        /// FluidSimulation.UpdateObstacles takes. The mean velocity over the frame, not the law's at its end, so that the
        /// sphere starts the frame exactly where the frame before left it.</summary>
        public RigidSphere Over(RigidSphere rest, double from, double to)
        {
            var result = rest.Clone();
            result.Center = rest.Center + Offset(to);
            result.Velocity = to > from ? (Offset(to) - Offset(from)) / (float)(to - from) : Velocity(to);
            return result;
        }

        public DriveLaw Clone() => (DriveLaw)MemberwiseClone();

        public IReadOnlyList<ValidationError> Validate(string owner)
        {
            var errors = new List<ValidationError>();
            foreach (var declared in SettingRules.Declared(typeof(DriveLaw)))
                SettingRules.Validate(this, errors, owner, "", declared.Field.Name);
            return errors;
        }
    }
}
