# Renders every material of a glTF set (the .glb `matevo variants --deliver gltf` writes as
# DIR/delivered/set.glb) in Blender Cycles, in matevo's paper scene, one PNG per material, so that
# an independent client's renders can be compared with matevo's by `matevo compare`
# (docs/export.md, "Clients"). Not run in CI: Blender is not a test dependency.
#
#   blender -b --factory-startup --python-exit-code 1 --python scripts/blender-render-set.py -- \
#       SET/delivered/set.glb OUTDIR [SIZE] [SAMPLES]
#
# Writes OUTDIR/target.png (the glTF's first material, the set's target) and
# OUTDIR/variant_NNN.png (the others, in the file's order). How the scene is matched
# (core/scene/SceneSettings.h's defaults, the paper mode):
# - camera: a pinhole at (0, 0, 4) in glTF's frame looking at the origin, +y up, vertical field
#   of view 32 degrees, square image;
# - light: one sun (a directional light, angle 0) from glTF's (-0.5, 0.6, 0.62), strength 1.5
#   (W/m2: Cycles' sun strength is the irradiance at normal incidence, as matevo's
#   lightRadiance); a black world (the paper mode has no ambient light);
# - film: "Standard" view transform, look None, exposure 0, gamma 1 (no Filmic), transparent
#   background, a 1-pixel box filter (matevo: 2 x 2 subsamples per pixel), no denoising;
#   8-bit sRGB PNG with straight alpha, as matevo writes.
import json
import math
import struct
import sys

import bpy
import numpy
from mathutils import Vector

# Debian 12's Blender 3.4 glTF importer still uses numpy.bool, which Debian's numpy 1.24 no
# longer has; it meant the builtin.
if not hasattr(numpy, "bool"):
    numpy.bool = bool


def gltf_material_names(glb_path):
    """The material names of a .glb, in the file's order (its JSON chunk)."""
    with open(glb_path, "rb") as f:
        magic, _version, _length = struct.unpack("<4sII", f.read(12))
        if magic != b"glTF":
            raise SystemExit(f"{glb_path}: not a binary glTF")
        chunk_length, chunk_type = struct.unpack("<I4s", f.read(8))
        if chunk_type != b"JSON":
            raise SystemExit(f"{glb_path}: the first chunk is not JSON")
        document = json.loads(f.read(chunk_length))
    return [m.get("name", f"material_{i}") for i, m in enumerate(document["materials"])]


def gltf_to_blender(v):
    """glTF is +y up; Blender's importer turns (x, y, z) into (x, -z, y)."""
    return Vector((v[0], -v[2], v[1]))


def setup_scene(size, samples):
    scene = bpy.context.scene
    scene.render.engine = "CYCLES"
    scene.cycles.device = "CPU"
    scene.cycles.samples = samples
    scene.cycles.use_denoising = False
    scene.cycles.pixel_filter_type = "BOX"
    scene.cycles.filter_width = 1.0
    scene.cycles.sample_clamp_direct = 0.0
    scene.cycles.sample_clamp_indirect = 0.0
    scene.render.resolution_x = size
    scene.render.resolution_y = size
    scene.render.resolution_percentage = 100
    scene.render.film_transparent = True
    scene.view_settings.view_transform = "Standard"
    scene.view_settings.look = "None"
    scene.view_settings.exposure = 0.0
    scene.view_settings.gamma = 1.0
    scene.display_settings.display_device = "sRGB"
    scene.render.image_settings.file_format = "PNG"
    scene.render.image_settings.color_mode = "RGBA"
    scene.render.image_settings.color_depth = "8"

    world = bpy.data.worlds.new("black")
    world.use_nodes = True
    world.node_tree.nodes["Background"].inputs["Strength"].default_value = 0.0
    scene.world = world

    camera_data = bpy.data.cameras.new("camera")
    camera_data.type = "PERSP"
    camera_data.sensor_fit = "VERTICAL"
    camera_data.angle_y = math.radians(32.0)
    camera_data.clip_start = 0.1
    camera = bpy.data.objects.new("camera", camera_data)
    camera.location = gltf_to_blender((0.0, 0.0, 4.0))
    # A Blender camera looks down its local -z with +y up.
    camera.rotation_euler = (-camera.location).to_track_quat("-Z", "Y").to_euler()
    scene.collection.objects.link(camera)
    scene.camera = camera

    sun_data = bpy.data.lights.new("sun", "SUN")
    sun_data.energy = 1.5
    sun_data.angle = 0.0
    sun = bpy.data.objects.new("sun", sun_data)
    towards_light = gltf_to_blender((-0.5, 0.6, 0.62)).normalized()
    # A sun shines down its local -z: its +z points towards the light.
    sun.rotation_euler = towards_light.to_track_quat("Z", "Y").to_euler()
    scene.collection.objects.link(sun)
    return scene


def main():
    args = sys.argv[sys.argv.index("--") + 1:] if "--" in sys.argv else []
    if len(args) < 2:
        raise SystemExit("usage: blender -b --factory-startup --python blender-render-set.py -- "
                         "SET.glb OUTDIR [SIZE] [SAMPLES]")
    glb, out = args[0], args[1]
    size = int(args[2]) if len(args) > 2 else 256
    samples = int(args[3]) if len(args) > 3 else 64

    bpy.ops.wm.read_factory_settings(use_empty=True)
    scene = setup_scene(size, samples)
    bpy.ops.import_scene.gltf(filepath=glb)
    meshes = [o for o in scene.objects if o.type == "MESH"]
    if len(meshes) != 1:
        raise SystemExit(f"{glb}: expected one mesh, found {len(meshes)}")
    mesh = meshes[0]
    names = gltf_material_names(glb)
    for index, name in enumerate(names):
        material = bpy.data.materials.get(name)
        if material is None:
            raise SystemExit(f"{glb}: Blender's importer made no material named {name!r}")
        for slot in mesh.material_slots:
            slot.material = material
        stem = "target" if index == 0 else f"variant_{index - 1:03d}"
        scene.render.filepath = f"{out}/{stem}.png"
        bpy.ops.render.render(write_still=True)
        print(f"blender-render-set: {name} -> {scene.render.filepath}")


main()
