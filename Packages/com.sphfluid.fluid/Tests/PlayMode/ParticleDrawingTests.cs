using System.Collections;
using NUnit.Framework;
using SphFluid.Runtime;
using UnityEngine;
using UnityEngine.TestTools;

namespace SphFluid.Tests.PlayMode
{
    /// <summary>
    /// Each camera draws the particles as it renders, not the fluid's Update: a camera that renders with no Update
    /// since the fluid started, as a paused editor's Scene and Game views do, still shows the fluid, and a disabled
    /// fluid is no longer drawn and no longer subscribed to the cameras' callback (Camera.onPreCull, the one of the two
    /// a test can count). Skipped (inconclusive) where there are no compute shaders.
    /// </summary>
    public sealed class ParticleDrawingTests
    {
        const int Pixels = 64;

        readonly TestTank _tank = new TestTank();
        GameObject _eye;
        RenderTexture _target;
        Texture2D _readBack;

        [TearDown]
        public void DestroyObjects()
        {
            _tank.Destroy();
            if (_eye != null) Object.DestroyImmediate(_eye);
            if (_target != null)
            {
                _target.Release();
                Object.DestroyImmediate(_target);
            }
            if (_readBack != null) Object.DestroyImmediate(_readBack);
        }

        [UnityTest]
        public IEnumerator ACameraDrawsTheFluidBeforeItsFirstUpdate()
        {
            TestTank.RequireGpu();
            int callbacks = PreCullCallbacks();
            Fluid simulator = _tank.CreateFluid(false);
            Assert.That(simulator.IsRunning, Is.True, simulator.FailureReason);
            Assert.That(simulator.SimulatedTime, Is.EqualTo(0.0), "no Update has stepped the fluid yet");
            Assert.That(PreCullCallbacks(), Is.EqualTo(callbacks + 1), "a running fluid draws from Camera.onPreCull");

            // The water cube (0.12 m) fills about a quarter of the view; the corner shows the background.
            Color32[] drawn = Render();
            Assert.That(PixelsUnlike(drawn, drawn[0]), Is.GreaterThan(Pixels * Pixels / 20),
                "pixels of the camera's image that show the fluid, rendered before the fluid's first Update");

            simulator.enabled = false;
            Color32[] undrawn = Render();
            Assert.That(PixelsUnlike(undrawn, undrawn[0]), Is.EqualTo(0), "a disabled fluid is still drawn");
            Assert.That(PreCullCallbacks(), Is.EqualTo(callbacks), "a disabled fluid still holds its Camera.onPreCull callback");
            yield return null;
        }

        /// <summary>One image of the tank's water from 0.45 m in front of it, from a camera rendered by hand.</summary>
        Color32[] Render()
        {
            if (_eye == null)
            {
                _eye = new GameObject("Eye");
                _eye.transform.position = new Vector3(0f, 0.1f, -0.45f); // looking along +z at the water
                _target = new RenderTexture(Pixels, Pixels, 24);
                _readBack = new Texture2D(Pixels, Pixels, TextureFormat.RGBA32, false);
                Camera made = _eye.AddComponent<Camera>();
                made.enabled = false; // renders only when asked
                made.clearFlags = CameraClearFlags.SolidColor;
                made.backgroundColor = new Color(0.5f, 0f, 0.5f);
                made.fieldOfView = 30f;
                made.nearClipPlane = 0.01f;
                made.targetTexture = _target;
            }
            Camera camera = _eye.GetComponent<Camera>();
            camera.Render();
            RenderTexture previous = RenderTexture.active;
            RenderTexture.active = _target;
            _readBack.ReadPixels(new Rect(0, 0, Pixels, Pixels), 0, 0);
            _readBack.Apply();
            RenderTexture.active = previous;
            return _readBack.GetPixels32();
        }

        static int PreCullCallbacks() => Camera.onPreCull?.GetInvocationList().Length ?? 0;

        static int PixelsUnlike(Color32[] image, Color32 background)
        {
            int count = 0;
            foreach (Color32 c in image)
                if (c.r != background.r || c.g != background.g || c.b != background.b) count++;
            return count;
        }
    }
}
