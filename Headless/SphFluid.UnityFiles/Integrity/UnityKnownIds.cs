using System.Collections.Generic;

namespace SphFluid.UnityFiles.Integrity;

/// <summary>Fixed Unity identifiers the checks compare against (unity-kit §1.2, §3.2, §4.2, §4.3, §5.2).</summary>
public static class UnityKnownIds
{
    /// <summary>YAML class id to the type name Unity writes as the document's root key.</summary>
    public static readonly IReadOnlyDictionary<int, string> TypeNames = new Dictionary<int, string>
    {
        [1] = "GameObject", [4] = "Transform", [5] = "TimeManager", [11] = "AudioManager", [13] = "InputManager",
        [19] = "Physics2DSettings", [20] = "Camera", [21] = "Material", [23] = "MeshRenderer", [28] = "Texture2D",
        [29] = "OcclusionCullingSettings", [30] = "GraphicsSettings", [33] = "MeshFilter", [43] = "Mesh", [47] = "QualitySettings",
        [48] = "Shader", [49] = "TextAsset", [54] = "Rigidbody", [55] = "PhysicsManager", [64] = "MeshCollider",
        [65] = "BoxCollider", [72] = "ComputeShader", [78] = "TagManager", [81] = "AudioListener", [82] = "AudioSource",
        [84] = "RenderTexture", [104] = "RenderSettings", [108] = "Light", [114] = "MonoBehaviour", [115] = "MonoScript",
        [126] = "NavMeshProjectSettings", [129] = "PlayerSettings", [135] = "SphereCollider", [136] = "CapsuleCollider",
        [157] = "LightmapSettings", [159] = "EditorSettings", [196] = "NavMeshSettings", [198] = "ParticleSystem",
        [199] = "ParticleSystemRenderer", [120] = "LineRenderer", [212] = "SpriteRenderer", [215] = "ReflectionProbe",
        [222] = "CanvasRenderer", [223] = "Canvas", [224] = "RectTransform", [236] = "ClusterInputManager", [310] = "UnityConnectSettings",
        [1001] = "PrefabInstance", [1045] = "EditorBuildSettings", [1660057539] = "SceneRoots", [890905787] = "VersionControlSettings",
        [937362698] = "VFXManager", [1386491679] = "PresetManager", [387306366] = "MemorySettings",
    };

    /// <summary>ProjectSettings file name to (class id, type name) of its single <c>&amp;1</c> document.</summary>
    public static readonly IReadOnlyDictionary<string, (int ClassId, string TypeName)> SettingsFiles = new Dictionary<string, (int, string)>
    {
        ["ProjectSettings.asset"] = (129, "PlayerSettings"), ["EditorSettings.asset"] = (159, "EditorSettings"),
        ["GraphicsSettings.asset"] = (30, "GraphicsSettings"), ["EditorBuildSettings.asset"] = (1045, "EditorBuildSettings"),
        ["QualitySettings.asset"] = (47, "QualitySettings"), ["TagManager.asset"] = (78, "TagManager"),
        ["DynamicsManager.asset"] = (55, "PhysicsManager"), ["Physics2DSettings.asset"] = (19, "Physics2DSettings"),
        ["AudioManager.asset"] = (11, "AudioManager"), ["InputManager.asset"] = (13, "InputManager"),
        ["TimeManager.asset"] = (5, "TimeManager"), ["NavMeshAreas.asset"] = (126, "NavMeshProjectSettings"),
        ["UnityConnectSettings.asset"] = (310, "UnityConnectSettings"), ["VFXManager.asset"] = (937362698, "VFXManager"),
        ["ClusterInputManager.asset"] = (236, "ClusterInputManager"), ["PresetManager.asset"] = (1386491679, "PresetManager"),
        ["MemorySettings.asset"] = (387306366, "MemorySettings"), ["VersionControlSettings.asset"] = (890905787, "VersionControlSettings"),
        ["PackageManagerSettings.asset"] = (114, "MonoBehaviour"),
    };

    /// <summary>Assemblies that packages in the manifest provide, with the package that must be listed for each.</summary>
    public static readonly IReadOnlyDictionary<string, string> PackageAssemblies = new Dictionary<string, string>
    {
        ["Unity.Mathematics"] = "com.unity.mathematics",
        ["Unity.InputSystem"] = "com.unity.inputsystem",
        ["Unity.InputSystem.TestFramework"] = "com.unity.inputsystem",
        ["UnityEngine.TestRunner"] = "com.unity.test-framework",
        ["UnityEditor.TestRunner"] = "com.unity.test-framework",
        ["UnityEngine.UI"] = "com.unity.ugui",
        ["UnityEditor.UI"] = "com.unity.ugui",
        ["Unity.ugui"] = "com.unity.ugui",
        ["Unity.RenderPipelines.Core.Runtime"] = "com.unity.render-pipelines.core",
        ["Unity.RenderPipelines.Universal.Runtime"] = "com.unity.render-pipelines.universal",
    };

    /// <summary>Packages a package brings with it (its package.json dependencies; URP 14.0.7 as seen in
    /// Unity-Technologies/Graphics, Packages/com.unity.render-pipelines.universal/package.json).</summary>
    public static readonly IReadOnlyDictionary<string, IReadOnlySet<string>> PackageDependencies = new Dictionary<string, IReadOnlySet<string>>
    {
        ["com.unity.render-pipelines.universal"] = new HashSet<string>
        {
            "com.unity.render-pipelines.core", "com.unity.shadergraph", "com.unity.burst", "com.unity.mathematics",
        },
    };

    /// <summary>asmdef GUIDs of package assemblies (for <c>"GUID:..."</c> references).</summary>
    public static readonly IReadOnlyDictionary<string, string> PackageAssemblyGuids = new Dictionary<string, string>
    {
        ["d8b63aba1907145bea998dd612889d6b"] = "Unity.Mathematics",
        ["75469ad4d38634e559750d17036d5f7c"] = "Unity.InputSystem",
        ["dc04f38471c3a459fb4d31124ee9127d"] = "Unity.InputSystem.TestFramework",
        ["27619889b8ba8c24980f49ee34dbb44a"] = "UnityEngine.TestRunner",
        ["0acc523941302664db1f4e527237feb3"] = "UnityEditor.TestRunner",
        // needle-mirror/com.unity.render-pipelines.core and .universal at 13.0.0, Runtime/*.asmdef.meta (unchanged in 14.x)
        ["df380645f10b7bc4b97d4f5eb6303d95"] = "Unity.RenderPipelines.Core.Runtime",
        ["15fc0a57446b3144c949da3e2b9737a9"] = "Unity.RenderPipelines.Universal.Runtime",
    };

    /// <summary>
    /// Scripts and assets inside packages that project files may reference by guid, with the package that must be in the
    /// manifest (guids as seen in public 2022.3 scenes and metas).
    /// </summary>
    public static readonly IReadOnlyDictionary<string, (string Name, string Package)> PackageObjectGuids = new Dictionary<string, (string, string)>
    {
        ["8404be70184654265930450def6a9037"] = ("InputActionImporter", "com.unity.inputsystem"),
        ["62899f850307741f2a39c98a8b639597"] = ("PlayerInput", "com.unity.inputsystem"),
        ["01614664b831546d2ae94a42149d80ac"] = ("InputSystemUIInputModule", "com.unity.inputsystem"),
        ["ca9f5fa95ffab41fb9a615ab714db018"] = ("DefaultInputActions", "com.unity.inputsystem"),
        ["76c392e42b5098c458856cdf6ecaaaa1"] = ("EventSystem", "com.unity.ugui"),
        ["4f231c4fb786f3946a6b90b886c48677"] = (StandaloneInputModule, "com.unity.ugui"),
        ["0cd44c1031e13a943bb63640046fad76"] = ("CanvasScaler", "com.unity.ugui"),
        ["dc42784cf147c0c48a680349fa168899"] = ("GraphicRaycaster", "com.unity.ugui"),
        ["5f7201a12d95ffc409449d95f23cf332"] = ("Text", "com.unity.ugui"),
        ["fe87c0e1cc204ed48ad3b37840f39efc"] = ("Image", "com.unity.ugui"),
        ["4e29b1a8efbd4b44bb3f3716e73f07ff"] = ("Button", "com.unity.ugui"),
        // URP: what a pipeline asset, its renderer data and a URP scene reference. A GUID is fixed once Unity writes
        // the package's .meta, so these hold for every URP version that ships the file. From the .meta files of
        // needle-mirror/com.unity.render-pipelines.universal at tag 13.0.0 unless marked:
        ["bf2edee5c58d82540a51f03df9d42094"] = ("UniversalRenderPipelineAsset", Urp),
        ["de640fe3d0db1804a85f9fc8f5cadab6"] = ("UniversalRendererData", Urp),
        ["a79441f348de89743a2939f4d699eac1"] = ("UniversalAdditionalCameraData", Urp),
        ["474bcb49853aa07438625e644c072ee6"] = ("UniversalAdditionalLightData", Urp),
        ["41439944d30ece34e96484bdb6645b55"] = ("Runtime/Data/PostProcessData.asset", Urp),
        ["60e1133243b97e347b653163a8c01b64"] = ("Runtime/Data/XRSystemData.asset", Urp),
        ["c17132b1f77d20942aa75f8429c0f8bc"] = ("Shaders/Utils/Blit.shader", Urp),
        ["d6dae50ee9e1bfa4db75f19f99355220"] = ("Shaders/Utils/CopyDepth.shader", Urp),
        ["04c410c9937594faa893a11dceb85f7e"] = ("Shaders/Utils/Sampling.shader", Urp),
        ["e9155b26e1bc55942a41e518703fe304"] = ("Shaders/Utils/StencilDeferred.shader", Urp),
        ["e6e9a19c3678ded42a3bc431ebef7dbd"] = ("Shaders/Utils/FallbackError.shader", Urp),
        ["5fd9a8feb75a4b5894c241777f519d4e"] = ("Shaders/Utils/MaterialError.shader", Urp),
        ["93446b5c5339d4f00b85c159e1159b7c"] = ("Shaders/Utils/CoreBlit.shader", Urp),
        ["d104b2fc1ca6445babb8e90b0758136b"] = ("Shaders/Utils/CoreBlitColorAndDepth.shader", Urp),
        ["c56b7e0d4c7cb484e959caeeedae9bbf"] = ("Shaders/CameraMotionVectors.shader", Urp),
        ["7b3ede40266cd49a395def176e1bc486"] = ("Shaders/ObjectMotionVectors.shader", Urp),
        ["6cda457ac28612740adb23da5d39ea92"] = ("Shaders/PostProcessing/LensFlareDataDriven.shader", Urp),
        ["cf852408f2e174538bcd9b7fda1c5ae7"] = ("Shaders/Debug/DebugReplacement.shader", Urp),
        // Files added after 13.0.0, as Unity wrote them into URP's own sample settings (Unity-Technologies/Graphics,
        // Samples~/URPPackageSamples/SharedAssets/Settings/PackageSamplesURPAsset.asset and SamplesForwardRenderer.asset):
        ["573620ae32aec764abd4d728906d2587"] = ("Shaders/Debug/HDRDebugView.shader", Urp),
        ["e3d24661c1e055f45a7560c033dbb837"] = ("Textures/BlueNoise64/L/LDR_LLL1_0.png", Urp),
        ["f9ee4ed84c1d10c49aabb9b210b0fc44"] = ("Textures/BayerMatrix.png", Urp),
        // As a Unity-written URP global settings asset names it (m_BlitHDROverlay), quoted in a public project's log:
        ["a89bee29cffa951418fc1e2da94d1959"] = ("Shaders/Utils/BlitHDROverlay.shader", Urp),
    };

    const string Urp = "com.unity.render-pipelines.universal";

    /// <summary>uGUI's input module for the legacy Input Manager: throws every frame when only the Input System is active.</summary>
    public const string StandaloneInputModule = "StandaloneInputModule";

    /// <summary>
    /// GUIDs that must never be an asset's own: package GUIDs, the 3D template's SampleScene, and the kit's example
    /// GUIDs (copying them collides with other projects' assets; unity-kit §3.1).
    /// </summary>
    public static readonly IReadOnlySet<string> ForeignGuids = new HashSet<string>
    {
        "9fc0d4010bbf28b4594072e72b8655ab",
        "fc94efff5f024fbc99b8650b37d502a1", "60b2ebf9f4cc401ba5584be098b6bcb0", "70cfa7b43d6049a48a4f19482934acf9",
        "86eec503b08f4e649a4f1bed71eebdca", "b52d5e8063d14492a4813d14036502dc", "082291b846e5471cac5cd892eb241196",
        "c4ec5105f7f345e29d3b4fca8df70c4c", "1ec168a53eec478aa7e96ed4acf85120", "57c56eebd7414c62a667d9ebe976a9e1",
        "0db46a43f75d4c9184ad83c959a0fe23",
        "d8b63aba1907145bea998dd612889d6b", "75469ad4d38634e559750d17036d5f7c", "dc04f38471c3a459fb4d31124ee9127d",
        "27619889b8ba8c24980f49ee34dbb44a", "0acc523941302664db1f4e527237feb3", "8404be70184654265930450def6a9037",
        "62899f850307741f2a39c98a8b639597", "01614664b831546d2ae94a42149d80ac", "ca9f5fa95ffab41fb9a615ab714db018",
        "76c392e42b5098c458856cdf6ecaaaa1", "4f231c4fb786f3946a6b90b886c48677", "0cd44c1031e13a943bb63640046fad76",
        "dc42784cf147c0c48a680349fa168899", "5f7201a12d95ffc409449d95f23cf332", "fe87c0e1cc204ed48ad3b37840f39efc",
        "4e29b1a8efbd4b44bb3f3716e73f07ff",
    };

    /// <summary>Tags every project has without a TagManager entry.</summary>
    public static readonly IReadOnlySet<string> BuiltinTags = new HashSet<string>
    {
        "Untagged", "Respawn", "Finish", "EditorOnly", "MainCamera", "Player", "GameController",
    };

    /// <summary>Layers every project has without a TagManager entry: Default, TransparentFX, Ignore Raycast, Water, UI.</summary>
    public static readonly IReadOnlySet<int> BuiltinLayers = new HashSet<int> { 0, 1, 2, 4, 5 };

    /// <summary>Precompiled DLLs that packages provide (asmdef <c>precompiledReferences</c>).</summary>
    public static readonly IReadOnlyDictionary<string, string> PackageDlls = new Dictionary<string, string>
    {
        ["nunit.framework.dll"] = "com.unity.test-framework",
    };

    /// <summary>The importer Unity uses for a file extension (lower case, with dot).</summary>
    public static readonly IReadOnlyDictionary<string, string> Importers = new Dictionary<string, string>
    {
        [".cs"] = "MonoImporter", [".compute"] = "ComputeShaderImporter", [".shader"] = "ShaderImporter",
        [".hlsl"] = "ShaderIncludeImporter", [".cginc"] = "ShaderIncludeImporter", [".asmdef"] = "AssemblyDefinitionImporter",
        [".asmref"] = "AssemblyDefinitionReferenceImporter", [".unity"] = "DefaultImporter", [".mat"] = "NativeFormatImporter",
        [".asset"] = "NativeFormatImporter", [".renderTexture"] = "NativeFormatImporter", [".physicMaterial"] = "NativeFormatImporter",
        [".prefab"] = "PrefabImporter", [".inputactions"] = "ScriptedImporter", [".md"] = "TextScriptImporter",
        [".txt"] = "TextScriptImporter", [".json"] = "TextScriptImporter", [".bytes"] = "TextScriptImporter",
        [".xml"] = "TextScriptImporter", [".csv"] = "TextScriptImporter", [".png"] = "TextureImporter",
        [".jpg"] = "TextureImporter", [".tga"] = "TextureImporter", [".exr"] = "TextureImporter", [".dll"] = "PluginImporter",
    };

    /// <summary>
    /// The reference a file's main object takes: <c>{fileID: classId×100000, type}</c> (unity-kit §4.3). A null fileID means
    /// "the .meta's mainObjectFileID" (native .asset) or "any non-zero id" (prefabs, ScriptedImporter assets, textures with sprites).
    /// </summary>
    public static readonly IReadOnlyDictionary<string, (long? FileId, int Type)> MainObjects = new Dictionary<string, (long?, int)>
    {
        [".compute"] = (7200000, 3), [".shader"] = (4800000, 3), [".mat"] = (2100000, 2), [".cs"] = (11500000, 3),
        [".asset"] = (null, 2), [".renderTexture"] = (8400000, 2), [".physicMaterial"] = (13400000, 2),
        [".png"] = (null, 3), [".jpg"] = (null, 3), [".tga"] = (null, 3), [".exr"] = (null, 3),
        [".txt"] = (4900000, 3), [".json"] = (4900000, 3), [".bytes"] = (4900000, 3), [".md"] = (4900000, 3),
        [".unity"] = (102900000, 3), [".prefab"] = (null, 3), [".inputactions"] = (null, 3),
    };

    /// <summary>Base classes a scene or asset script may ultimately derive from.</summary>
    public static readonly IReadOnlySet<string> SerializableScriptBases = new HashSet<string>
    {
        "MonoBehaviour", "ScriptableObject", "StateMachineBehaviour", "UIBehaviour", "Graphic", "MaskableGraphic",
        "Selectable", "BaseInputModule", "PointerInputModule", "BaseRaycaster", "NetworkBehaviour",
    };

    /// <summary>Scene settings documents every 2022.3 scene starts with (unity-kit §4.1).</summary>
    public static readonly IReadOnlyList<(int ClassId, string TypeName)> SceneSettings = new[]
    {
        (29, "OcclusionCullingSettings"), (104, "RenderSettings"), (157, "LightmapSettings"), (196, "NavMeshSettings"),
    };
}
