using SphFluid.Simulation;
using UnityEngine;

namespace SphFluid.Runtime
{
    /// <summary>Spins its Transform (the rotating-container scene's box) by the core's <see cref="ContainerSpin"/> law,
    /// the same law the headless runner applies, about a world axis through its own position.</summary>
    public sealed class ContainerSpinner : MonoBehaviour
    {
        [SerializeField, Tooltip("The spin: axis, angular speed and start delay, each declared once in ContainerSpin.")]
        ContainerSpin spin = new ContainerSpin();

        Quaternion _restRotation;
        double _elapsed;

        /// <summary>The law, for scripts; a change applies from the next frame.</summary>
        public ContainerSpin Spin => spin;

        void OnEnable()
        {
            _restRotation = transform.rotation;
            _elapsed = 0.0;
        }

        void Update()
        {
            _elapsed += Time.deltaTime;
            transform.rotation = spin.Turn(_elapsed).ToUnity() * _restRotation;
        }

        void OnValidate() => ComponentValidation.Log(spin.Validate($"ContainerSpinner '{name}'"), this);
    }
}
