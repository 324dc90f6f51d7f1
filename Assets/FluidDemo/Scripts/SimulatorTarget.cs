using SphFluid.Runtime;
using UnityEngine;

namespace SphFluid.Demo
{
    /// <summary>
    /// The simulator a control or readout acts on: the one assigned in its inspector, else the scene's.
    /// The scene is searched once, and again at most once a second while it has none: a search makes an array,
    /// and the callers ask every frame.
    /// </summary>
    internal sealed class SimulatorTarget
    {
        /// <summary>Real-time seconds between two searches while the scene has no simulator.</summary>
        const float SearchInterval = 1f;

        Fluid _found;
        float _nextSearch;

        public Fluid Resolve(Fluid assigned)
        {
            if (assigned != null) return assigned;
            if (_found == null && Time.unscaledTime >= _nextSearch)
            {
                _nextSearch = Time.unscaledTime + SearchInterval;
                _found = Object.FindFirstObjectByType<Fluid>();
            }
            return _found;
        }
    }
}
