"""Renders a .glb with Blender's Cycles, headless, from a camera given in the glTF frame
(metres, +Y up): how the pictures of docs/render.md ("Export") show an export in another
tool.

    blender -b --factory-startup --python scripts/blender/render_glb.py -- \
        scene.glb out.png X,Y,Z TX,TY,TZ FOV_DEG WIDTH HEIGHT [SAMPLES] [frame=N] [only=NAME]

One sun light and a grey sky; no denoiser (Debian's Blender has none). frame=N shows the
animation at scene frame N; only=NAME renders only the meshes whose object name contains
NAME (e.g. one level of detail of a file with several).
"""
import math
import sys
import warnings

import numpy

# Blender 3.4's glTF importer still uses numpy.bool, which numpy 1.24 removed.
with warnings.catch_warnings():
    warnings.simplefilter("ignore", FutureWarning)
    if not hasattr(numpy, "bool"):
        numpy.bool = bool

import bpy  # noqa: E402
import mathutils  # noqa: E402


def blender_frame(p):
    """glTF (x, y, z), +Y up, to Blender's +Z up frame, as the importer converts."""
    return mathutils.Vector((p[0], -p[2], p[1]))


def main(args):
    options = dict(a.split("=", 1) for a in args if "=" in a)
    args = [a for a in args if "=" not in a]
    src, out = args[0], args[1]
    eye, target = [[float(v) for v in a.split(",")] for a in args[2:4]]
    fov, width, height = float(args[4]), int(args[5]), int(args[6])
    samples = int(args[7]) if len(args) > 7 else 32
    bpy.ops.wm.read_factory_settings(use_empty=True)
    bpy.ops.import_scene.gltf(filepath=src)
    scene = bpy.context.scene
    if "only" in options:
        for o in scene.objects:
            if o.type == "MESH":
                o.hide_render = options["only"] not in o.name
    if "frame" in options:
        scene.frame_set(int(options["frame"]))
    cam = bpy.data.objects.new("camera", bpy.data.cameras.new("camera"))
    scene.collection.objects.link(cam)
    cam.location = blender_frame(eye)
    cam.rotation_euler = (blender_frame(target) - cam.location).to_track_quat("-Z", "Y").to_euler()
    cam.data.sensor_fit = "VERTICAL"
    cam.data.angle_y = math.radians(fov)
    cam.data.clip_start = 0.001
    scene.camera = cam
    sun = bpy.data.objects.new("sun", bpy.data.lights.new("sun", "SUN"))
    sun.data.energy = 3
    sun.rotation_euler = (math.radians(40), math.radians(20), math.radians(30))
    scene.collection.objects.link(sun)
    scene.world = bpy.data.worlds.new("sky")
    scene.world.use_nodes = True
    scene.world.node_tree.nodes["Background"].inputs[0].default_value = (0.25, 0.25, 0.27, 1)
    scene.render.engine = "CYCLES"
    scene.cycles.device = "CPU"
    scene.cycles.samples = samples
    scene.cycles.use_denoising = False
    scene.render.resolution_x, scene.render.resolution_y = width, height
    scene.render.filepath = out
    bpy.ops.render.render(write_still=True)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[sys.argv.index("--") + 1:]))
