using SphFluid.Runtime;
using UnityEngine;
using UnityEngine.InputSystem;
using UnityEngine.SceneManagement;

namespace SphFluid.Demo
{
    /// <summary>Keyboard controls of the simulation: Space pause, period or N single step, R reset (respawn), Tab next scene.</summary>
    public sealed class FluidControls : MonoBehaviour
    {
        [SerializeField, Tooltip("The simulator controlled; empty = the scene's Fluid.")]
        Fluid simulator = null;

        InputAction _pause, _step, _reset, _nextScene;
        readonly SimulatorTarget _target = new SimulatorTarget();

        void OnEnable()
        {
            _pause = new InputAction("Pause", InputActionType.Button, "<Keyboard>/space");
            _step = new InputAction("Step", InputActionType.Button, "<Keyboard>/period");
            _step.AddBinding("<Keyboard>/n");
            _reset = new InputAction("Reset", InputActionType.Button, "<Keyboard>/r");
            _nextScene = new InputAction("NextScene", InputActionType.Button, "<Keyboard>/tab");
            _pause.Enable();
            _step.Enable();
            _reset.Enable();
            _nextScene.Enable();
        }

        void OnDisable()
        {
            _pause?.Dispose();
            _step?.Dispose();
            _reset?.Dispose();
            _nextScene?.Dispose();
            _pause = _step = _reset = _nextScene = null;
        }

        void Update()
        {
            if (_nextScene.WasPressedThisFrame())
            {
                LoadNextScene();
                return;
            }
            Fluid target = _target.Resolve(simulator);
            if (target == null) return;
            if (_pause.WasPressedThisFrame()) target.TogglePause();
            if (_step.WasPressedThisFrame()) target.StepOnce();
            if (_reset.WasPressedThisFrame()) target.ResetSimulation();
        }

        /// <summary>The next scene of the build settings, wrapping round (a scene not in the list goes to the first).</summary>
        public static void LoadNextScene()
        {
            int count = SceneManager.sceneCountInBuildSettings;
            if (count == 0)
            {
                Debug.LogWarning("FluidControls: no scenes in the build settings to switch to");
                return;
            }
            int current = SceneManager.GetActiveScene().buildIndex; // -1 when not in the list
            SceneManager.LoadScene((current + 1) % count);
        }
    }
}
