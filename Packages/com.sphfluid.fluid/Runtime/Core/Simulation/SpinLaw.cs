using System;
using System.Collections.Generic;
using System.Numerics;

namespace SphFluid.Simulation
{
    /// <summary>
    /// The law of a spinning container, as a function of time: after <see cref="StartDelay"/> its frame turns about a
    /// world axis through a pivot at a steady speed. One law for the Unity ContainerSpinner and the headless runner;
    /// each field declared once (<see cref="SettingAttribute"/>), serialized by Unity inside the component.
    /// </summary>
    [Serializable]
    public sealed class SpinLaw
    {
        const string Group = "Spin";

        [Setting(Group, 0, 1e6, "", "Axis of rotation, world space (need not be normalised; must not be zero).", MinExclusive = true)]
        public SettingVector Axis = new Vector3(0f, 0f, 1f);

        [Setting(Group, -360, 360, "deg/s", "Angular speed; negative turns the other way.")]
        public float AngularSpeed = 30f;

        [Setting(Group, 0, 3600, "s", "Time after start before spinning, so the fluid can settle first.")]
        public float StartDelay = 1f;

        public float RadiansPerSecond => AngularSpeed * MathF.PI / 180f;

        /// <summary>The turn applied at time <paramref name="t"/>, s after start (identity before the delay).</summary>
        public Quaternion Turn(double t)
        {
            if (Axis.Length() < 1e-6f) return Quaternion.Identity;
            double turning = Math.Max(0.0, t - StartDelay);
            return Quaternion.CreateFromAxisAngle(Vector3.Normalize(Axis), (float)(turning * RadiansPerSecond));
        }

        /// <summary>Angular velocity at time <paramref name="t"/>, rad/s, world space.</summary>
        public Vector3 AngularVelocity(double t) =>
            t >= StartDelay && Axis.Length() >= 1e-6f ? Vector3.Normalize(Axis) * RadiansPerSecond : Vector3.Zero;

        /// <summary>A container at rest turned about <paramref name="pivot"/> to time <paramref name="to"/>, with the
        /// velocities that brought it there from time <paramref name="from"/> (a frame): what a Unity Transform turned by
        /// this law reads, and what FluidSimulation.UpdateContainer takes. Mean velocities over the frame (the turn's
        /// angle and the centre's chord over its time), so that the walls start the frame exactly where the frame before
        /// left them.</summary>
        public ContainerDescription Over(ContainerDescription rest, Vector3 pivot, double from, double to)
        {
            var result = Placed(rest, pivot, to);
            if (!(to > from))
            {
                result.AngularVelocity = AngularVelocity(to);
                result.Velocity = Vector3.Cross(result.AngularVelocity, result.Position - pivot);
                return result;
            }
            float seconds = (float)(to - from);
            double turned = Math.Max(0.0, to - StartDelay) - Math.Max(0.0, from - StartDelay);
            result.AngularVelocity = Axis.Length() < 1e-6f ? Vector3.Zero : Vector3.Normalize(Axis) * (float)(turned * RadiansPerSecond / seconds);
            result.Velocity = (result.Position - Placed(rest, pivot, from).Position) / seconds;
            return result;
        }

        ContainerDescription Placed(ContainerDescription rest, Vector3 pivot, double t)
        {
            var result = rest.Clone();
            var turn = Turn(t);
            result.Position = pivot + Vector3.Transform(rest.Position - pivot, turn);
            result.Rotation = Quaternion.Normalize(turn * rest.Rotation);
            return result;
        }

        public SpinLaw Clone() => (SpinLaw)MemberwiseClone();

        public IReadOnlyList<ValidationError> Validate(string owner)
        {
            var errors = new List<ValidationError>();
            foreach (var declared in SettingRules.Declared(typeof(SpinLaw)))
                SettingRules.Validate(this, errors, owner, "", declared.Field.Name);
            return errors;
        }
    }
}
