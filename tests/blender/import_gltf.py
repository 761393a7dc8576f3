"""Imports glTF files with Blender's own importer, headless, and checks what it finds.

    blender -b --factory-startup --python tests/blender/import_gltf.py -- \
        FILE.glb[:meshes=N][:joints=N][:animations=N][:shape_keys=N] ...

meshes: mesh objects; joints: bones of all armatures; animations: actions; shape_keys:
shape keys of all meshes without each mesh's "Basis". Counts not given are printed but
not checked. Every file is imported into an empty scene, all in one Blender run (Blender
takes seconds to start). Exit status 0 when every count matches, 1 otherwise.
"""
import sys
import warnings

try:
    import numpy
except ImportError:
    print("skip: Blender's glTF importer needs numpy (Debian python3-numpy, scripts/deps.sh blender)")
    sys.exit(77)

# Blender 3.4's glTF importer still uses numpy.bool, which numpy 1.24 removed (asking
# for it there only warns that it will come back).
with warnings.catch_warnings():
    warnings.simplefilter("ignore", FutureWarning)
    if not hasattr(numpy, "bool"):
        numpy.bool = bool

import bpy  # noqa: E402  (after the numpy fix, which the importer needs)

KEYS = ("meshes", "joints", "animations", "shape_keys")


def parse(arg):
    """'dir/a.glb:meshes=2:joints=0' -> ('dir/a.glb', {'meshes': 2, 'joints': 0})."""
    parts = arg.split(":")
    expect = {}
    while len(parts) > 1 and "=" in parts[-1]:
        key, _, value = parts.pop().partition("=")
        if key not in KEYS:
            raise SystemExit(f"import_gltf: unknown count '{key}' in '{arg}' ({', '.join(KEYS)})")
        expect[key] = int(value)
    return ":".join(parts), expect


def counts():
    objects = bpy.context.scene.objects
    meshes = [o for o in objects if o.type == "MESH"]
    found = {
        "meshes": len(meshes),
        "joints": sum(len(o.data.bones) for o in objects if o.type == "ARMATURE"),
        "animations": len(bpy.data.actions),
        "shape_keys": 0,
    }
    for o in meshes:
        keys = o.data.shape_keys
        if keys:
            found["shape_keys"] += sum(1 for k in keys.key_blocks if k != keys.reference_key)
    return found


def main(args):
    if not args:
        print(__doc__)
        return 2
    failed = False
    for arg in args:
        path, expect = parse(arg)
        bpy.ops.wm.read_factory_settings(use_empty=True)
        result = bpy.ops.import_scene.gltf(filepath=path)
        if result != {"FINISHED"}:
            print(f"{path}: FAILED: the importer returned {result}")
            failed = True
            continue
        found = counts()
        wrong = [k for k, v in expect.items() if found[k] != v]
        shown = ", ".join(f"{k} {found[k]}" + (f" (expected {expect[k]})" if k in wrong else "")
                          for k in KEYS)
        print(f"{path}: {'FAILED' if wrong else 'ok'}: {shown}")
        failed |= bool(wrong)
    return 1 if failed else 0


if __name__ == "__main__":
    argv = sys.argv[sys.argv.index("--") + 1:] if "--" in sys.argv else []
    sys.exit(main(argv))
