# Blender (headless) reads what `shitsukan tissue run` writes: rest.obj imported without axis
# conversion, the Mesh Cache modifier playing skin.pc2 on it, and at every frame the
# evaluated vertices must be those of frames/NNNN.obj. Run as:
#   blender -b --factory-startup --python blender_pc2.py -- RUN_DIR FRAMES
# (tests/blender/run.sh runs it, and skips without Blender).
import sys

import bpy

run_dir, frames = sys.argv[sys.argv.index("--") + 1], int(sys.argv[sys.argv.index("--") + 2])


def read_obj_vertices(path):
    with open(path) as f:
        return [tuple(float(v) for v in line.split()[1:4]) for line in f if line.startswith("v ")]


bpy.ops.wm.read_factory_settings(use_empty=True)
bpy.ops.wm.obj_import(filepath=run_dir + "/rest.obj", forward_axis="Y", up_axis="Z")
obj = bpy.context.selected_objects[0]
rest = read_obj_vertices(run_dir + "/rest.obj")
if len(obj.data.vertices) != len(rest):
    sys.exit("the OBJ import has %d vertices, the file %d" % (len(obj.data.vertices), len(rest)))
mod = obj.modifiers.new("cache", "MESH_CACHE")
mod.cache_format = "PC2"
mod.filepath = run_dir + "/skin.pc2"
mod.frame_start = 0
worst = 0.0
for frame in range(frames):
    bpy.context.scene.frame_set(frame)
    depsgraph = bpy.context.evaluated_depsgraph_get()
    mesh = obj.evaluated_get(depsgraph).to_mesh()
    want = read_obj_vertices("%s/frames/%04d.obj" % (run_dir, frame))
    for v, w in zip(mesh.vertices, want):
        worst = max(worst, max(abs(a - b) for a, b in zip(v.co, w)))
    obj.evaluated_get(depsgraph).to_mesh_clear()
print("blender: %d frames, largest difference %g mm" % (frames, worst))
sys.exit(0 if worst < 1e-3 else "the Mesh Cache frames differ from the OBJ frames by %g mm" % worst)
