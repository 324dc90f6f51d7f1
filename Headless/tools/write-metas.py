#!/usr/bin/env python3
"""Writes the .meta file Unity would write for every file and folder under Assets/ and under each embedded
package (Packages/<name>/ with a package.json; the package folder itself has none) that lacks one.

Package samples (the "samples" entries of package.json, folders under Samples~) get them too: Unity never imports
Samples~ in place, but Package Manager copies a sample with its .meta files, so the GUIDs its scene and assets
reference must already be there. The sample folder itself gets none (Package Manager makes the folder it copies into),
as in Unity's own packages.

Each new .meta gets a fresh random GUID (uuid4, as Unity does); existing .meta files are never
touched, so GUIDs stay stable. Run it after adding assets:  python3 Headless/tools/write-metas.py
"""
import json
import os
import sys
import uuid

TAIL = "  userData: \n  assetBundleName: \n  assetBundleVariant: \n"

IMPORTERS = {
    ".cs": "MonoImporter:\n  externalObjects: {}\n  serializedVersion: 2\n  defaultReferences: []\n"
           "  executionOrder: 0\n  icon: {instanceID: 0}\n" + TAIL,
    ".compute": "ComputeShaderImporter:\n  externalObjects: {}\n  preprocessorOverride: 0\n" + TAIL,
    ".shader": "ShaderImporter:\n  externalObjects: {}\n  defaultTextures: []\n  nonModifiableTextures: []\n"
               "  preprocessorOverride: 0\n" + TAIL,
    ".hlsl": "ShaderIncludeImporter:\n  externalObjects: {}\n" + TAIL,
    ".cginc": "ShaderIncludeImporter:\n  externalObjects: {}\n" + TAIL,
    ".asmdef": "AssemblyDefinitionImporter:\n  externalObjects: {}\n" + TAIL,
    ".unity": "DefaultImporter:\n  externalObjects: {}\n" + TAIL,
    ".mat": "NativeFormatImporter:\n  externalObjects: {}\n  mainObjectFileID: 2100000\n" + TAIL,
    ".asset": "NativeFormatImporter:\n  externalObjects: {}\n  mainObjectFileID: 11400000\n" + TAIL,
    ".renderTexture": "NativeFormatImporter:\n  externalObjects: {}\n  mainObjectFileID: 8400000\n" + TAIL,
    ".physicMaterial": "NativeFormatImporter:\n  externalObjects: {}\n  mainObjectFileID: 13400000\n" + TAIL,
    ".prefab": "PrefabImporter:\n  externalObjects: {}\n" + TAIL,
    ".asmref": "AssemblyDefinitionReferenceImporter:\n  externalObjects: {}\n" + TAIL,
    # Short TextureImporter form (unity-kit 3.2): Unity fills in the remaining defaults on first import.
    ".png": "TextureImporter:\n  externalObjects: {}\n  textureType: 0\n" + TAIL,
    ".jpg": "TextureImporter:\n  externalObjects: {}\n  textureType: 0\n" + TAIL,
    ".md": "TextScriptImporter:\n  externalObjects: {}\n" + TAIL,
    ".bytes": "TextScriptImporter:\n  externalObjects: {}\n" + TAIL,
    ".csv": "TextScriptImporter:\n  externalObjects: {}\n" + TAIL,
    ".xml": "TextScriptImporter:\n  externalObjects: {}\n" + TAIL,
    ".txt": "TextScriptImporter:\n  externalObjects: {}\n" + TAIL,
    ".json": "TextScriptImporter:\n  externalObjects: {}\n" + TAIL,
    ".inputactions": "ScriptedImporter:\n  internalIDToNameTable: []\n  externalObjects: {}\n"
                     "  serializedVersion: 2\n" + TAIL +
                     "  script: {fileID: 11500000, guid: 8404be70184654265930450def6a9037, type: 3}\n"
                     "  generateWrapperCode: 0\n  wrapperCodePath: \n  wrapperClassName: \n"
                     "  wrapperCodeNamespace: \n",
}
FOLDER = "folderAsset: yes\nDefaultImporter:\n  externalObjects: {}\n" + TAIL
DEFAULT = "DefaultImporter:\n  externalObjects: {}\n" + TAIL


def hidden(name):
    # Unity skips dot-files and names ending in '~' (and everything below such folders).
    return name.startswith(".") or name.endswith("~")


def write_meta(path, body):
    meta = path + ".meta"
    if os.path.exists(meta):
        return False
    with open(meta, "w", newline="\n") as f:
        f.write("fileFormatVersion: 2\nguid: %s\n%s" % (uuid.uuid4().hex, body))
    print("wrote", meta)
    return True


def asset_roots(root):
    yield os.path.join(root, "Assets")
    packages = os.path.join(root, "Packages")
    for name in sorted(os.listdir(packages)):
        folder = os.path.join(packages, name)
        if not hidden(name) and os.path.isfile(os.path.join(folder, "package.json")):
            yield folder
            for sample in sample_folders(folder):
                yield sample


def sample_folders(package):
    with open(os.path.join(package, "package.json"), encoding="utf-8") as f:
        samples = json.load(f).get("samples") or []
    for sample in samples:
        path = sample.get("path") or ""
        folder = os.path.normpath(os.path.join(package, path))
        if path.startswith("Samples~/") and ".." not in path.split("/") and os.path.isdir(folder):
            yield folder


def main(root):
    for folder in asset_roots(root):
        write_metas(folder)


def write_metas(assets):
    for dirpath, dirnames, filenames in os.walk(assets):
        dirnames[:] = [d for d in dirnames if not hidden(d) and d not in ("bin", "obj")]
        for d in dirnames:
            write_meta(os.path.join(dirpath, d), FOLDER)
        for f in filenames:
            if hidden(f) or f.endswith(".meta"):
                continue
            ext = os.path.splitext(f)[1]
            write_meta(os.path.join(dirpath, f), IMPORTERS.get(ext, IMPORTERS.get(ext.lower(), DEFAULT)))
    # Orphans: a .meta whose asset is gone makes Unity warn and delete it.
    for dirpath, dirnames, filenames in os.walk(assets):
        for f in filenames:
            if f.endswith(".meta") and not os.path.exists(os.path.join(dirpath, f[:-5])):
                print("orphan .meta (delete it):", os.path.join(dirpath, f), file=sys.stderr)


if __name__ == "__main__":
    main(sys.argv[1] if len(sys.argv) > 1 else os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__)))))
