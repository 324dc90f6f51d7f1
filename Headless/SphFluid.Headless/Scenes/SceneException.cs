using System;

namespace SphFluid.Headless.Scenes;

/// <summary>A scene file the runner cannot simulate; every line names the file, GameObject, component and
/// field at fault (exit code 3).</summary>
public sealed class SceneException(string message, Exception? inner = null) : Exception(message, inner);
