using System;
using SphFluid.Simulation;

namespace SphFluid.Headless.Scenes;

/// <summary>
/// What a command changes in a scene before it runs it (--solver and its settings, one configuration of a study),
/// and the words that name the change. <see cref="SceneLoader"/> applies it before it validates, so the scene is checked
/// as it will run: a DFSPH run is not refused for a WCSPH stiffness it never uses, a WCSPH run of a DFSPH scene is
/// refused for one, and either refusal still names the line of the file.
/// </summary>
/// <param name="Label">The command and arguments that make the change ("simulate --solver wcsph").</param>
/// <param name="Apply">Changes the scene's description in place; it may refuse an argument that does not fit the
/// scene by throwing a <see cref="Cli.UsageException"/>.</param>
public sealed record SceneChange(string Label, Action<FluidSceneDescription> Apply);
