# Builds one scene of a neutral scene description (../shared/refs/scenes.json or bench/cycles/*.json)
# in Blender and renders it with Cycles on the CPU, as the reference images were made: box filter
# 1 px wide, linear output, no denoising, no adaptive sampling, no clamping, caustics on, 64 bounces
# of every kind. Writes the linear image as PFM and prints the time of the whole render call on one
# line.
#
#   blender -b --factory-startup --python-exit-code 2 -P build_scene.py -- \
#       SCENES_JSON SCENE SPP THREADS SEED OUT.pfm
#
# Run by bench/cycles_race; see docs/performance.md.
import json
import math
import os
import struct
import sys
import tempfile
import time

import bpy
from mathutils import Matrix, Vector

args = sys.argv[sys.argv.index("--") + 1:]
scenes_path, scene_name, spp, threads, seed, out_path = args[0], args[1], int(args[2]), int(args[3]), int(args[4]), args[5]
document = json.load(open(scenes_path))
description = document["scenes"][scene_name]
# Where the description's file paths (mesh 'file', 'albedo_texture') are relative to: the refs'
# format says the parent of refs/ (its conventions have a 'files' entry); bench/cycles/*.json say
# this file's own folder.
conventions = document.get("conventions")
files_base = os.path.dirname(os.path.abspath(scenes_path))
if isinstance(conventions, dict) and "files" in conventions:
    files_base = os.path.dirname(files_base)

bpy.ops.wm.read_factory_settings(use_empty=True)
scene = bpy.context.scene


def node_material(name, build):
    material = bpy.data.materials.new(name)
    material.use_nodes = True
    nodes, links = material.node_tree.nodes, material.node_tree.links
    nodes.clear()
    output = nodes.new("ShaderNodeOutputMaterial")
    links.new(build(nodes, links), output.inputs["Surface"])
    return material


def rgba(rgb):
    return (rgb[0], rgb[1], rgb[2], 1.0)


def make_material(name, spec):
    kind = spec["type"]
    if kind in ("diffuse", "textured_diffuse"):  # textured_diffuse: the refs' name, albedo 1 x texture
        def build(nodes, links):
            bsdf = nodes.new("ShaderNodeBsdfDiffuse")
            bsdf.inputs["Color"].default_value = rgba(spec.get("albedo", [1, 1, 1]))
            bsdf.inputs["Roughness"].default_value = 0.0  # Lambertian, not Oren-Nayar
            if "albedo_texture" in spec:
                # albedo x texture: an 8-bit sRGB image, decoded to linear, bilinear, repeating,
                # read at the mesh's UV map (OBJ vt: v = 0 at the image's bottom row, as in Blender).
                texture = nodes.new("ShaderNodeTexImage")
                path = os.path.join(files_base, spec["albedo_texture"])
                texture.image = bpy.data.images.load(path)
                texture.image.colorspace_settings.name = "sRGB"
                texture.interpolation = "Linear"
                texture.extension = "REPEAT"
                product = nodes.new("ShaderNodeMixRGB")
                product.blend_type = "MULTIPLY"
                product.inputs["Fac"].default_value = 1.0
                product.inputs["Color1"].default_value = rgba(spec.get("albedo", [1, 1, 1]))
                links.new(texture.outputs["Color"], product.inputs["Color2"])
                links.new(product.outputs["Color"], bsdf.inputs["Color"])
            return bsdf.outputs[0]
    elif kind == "mirror":
        def build(nodes, links):
            bsdf = nodes.new("ShaderNodeBsdfGlossy")
            bsdf.distribution = "SHARP"
            bsdf.inputs["Color"].default_value = rgba(spec["reflectance"])
            return bsdf.outputs[0]
    elif kind == "glass":
        def build(nodes, links):
            bsdf = nodes.new("ShaderNodeBsdfGlass")
            bsdf.distribution = "SHARP"
            bsdf.inputs["Color"].default_value = rgba(spec.get("tint", [1, 1, 1]))
            bsdf.inputs["IOR"].default_value = spec["ior"]
            return bsdf.outputs[0]
    elif kind == "ggx":
        def build(nodes, links):
            bsdf = nodes.new("ShaderNodeBsdfGlossy")
            bsdf.distribution = "GGX"
            bsdf.inputs["Color"].default_value = rgba(spec["reflectance"])
            bsdf.inputs["Roughness"].default_value = math.sqrt(spec["alpha"])  # Cycles squares it
            return bsdf.outputs[0]
    elif kind == "emitter":
        # One-sided: radiance along the geometric normal, black (and reflecting nothing) behind.
        def build(nodes, links):
            front = nodes.new("ShaderNodeEmission")
            front.inputs["Color"].default_value = rgba(spec["radiance"])
            front.inputs["Strength"].default_value = 1.0
            back = nodes.new("ShaderNodeEmission")
            back.inputs["Strength"].default_value = 0.0
            geometry = nodes.new("ShaderNodeNewGeometry")
            mix = nodes.new("ShaderNodeMixShader")
            links.new(geometry.outputs["Backfacing"], mix.inputs["Fac"])
            links.new(front.outputs[0], mix.inputs[1])
            links.new(back.outputs[0], mix.inputs[2])
            return mix.outputs[0]
    else:
        raise SystemExit(f"{scenes_path}: /scenes/{scene_name}/materials/{name}: unsupported type {kind}")
    return node_material(name, build)


materials = {name: make_material(name, spec) for name, spec in description["materials"].items()}


def add_mesh(name, vertices, faces, material, smooth=False):
    mesh = bpy.data.meshes.new(name)
    mesh.from_pydata([tuple(v) for v in vertices], [], faces)
    mesh.update()
    if smooth:
        for polygon in mesh.polygons:
            polygon.use_smooth = True
    mesh.materials.append(materials[material])
    obj = bpy.data.objects.new(name, mesh)
    scene.collection.objects.link(obj)
    return obj


def read_obj(path):
    """Positions, faces (vertex indices) and per-corner texture coordinates of an OBJ file."""
    positions, uvs, faces, face_uvs = [], [], [], []
    for line in open(path):
        words = line.split()
        if not words:
            continue
        if words[0] == "v":
            positions.append(tuple(float(x) for x in words[1:4]))
        elif words[0] == "vt":
            uvs.append((float(words[1]), float(words[2])))
        elif words[0] == "f":
            corners = [w.split("/") for w in words[1:]]
            index = lambda text, count: int(text) - 1 if int(text) > 0 else count + int(text)
            faces.append([index(c[0], len(positions)) for c in corners])
            face_uvs.append([uvs[index(c[1], len(uvs))] if len(c) > 1 and c[1] else (0.0, 0.0) for c in corners])
    return positions, faces, face_uvs


def mesh_transform(spec):
    """translate x rotate x scale, as ptview's shape transforms compose them. The rotation is
    {axis, degrees} (bench/cycles/*.json) or rotate_y_deg (the refs' format)."""
    transform = spec.get("transform", {})
    scale = transform.get("scale", 1.0)
    scale = Matrix.Diagonal(Vector(scale if isinstance(scale, list) else [scale] * 3)).to_4x4()
    rotation = Matrix.Identity(4)
    if "rotation" in transform:
        rotation = Matrix.Rotation(math.radians(transform["rotation"]["degrees"]), 4, Vector(transform["rotation"]["axis"]))
    elif "rotate_y_deg" in transform:
        rotation = Matrix.Rotation(math.radians(transform["rotate_y_deg"]), 4, "Y")
    return Matrix.Translation(Vector(transform.get("translate", [0, 0, 0]))) @ rotation @ scale


def quad_corners(center, u, v):
    c, u, v = Vector(center), Vector(u), Vector(v)
    # Counter-clockwise seen from normalize(cross(u, v)), so Blender's normal is that one.
    return [c - u - v, c + u - v, c + u + v, c - u + v]


for shape in description["shapes"]:
    kind, name, material = shape["type"], shape["name"], shape["material"]
    if kind == "quad":
        add_mesh(name, quad_corners(shape["center"], shape["u"], shape["v"]), [(0, 1, 2, 3)], material)
    elif kind == "box":
        h = Vector(shape["half_size"])
        yaw = math.radians(shape["yaw_deg"])
        rotation = Matrix(((math.cos(yaw), 0, math.sin(yaw)), (0, 1, 0), (-math.sin(yaw), 0, math.cos(yaw))))
        center = Vector(shape["center"])
        corners = [center + rotation @ Vector((sx * h.x, sy * h.y, sz * h.z))
                   for sx in (-1, 1) for sy in (-1, 1) for sz in (-1, 1)]
        # Outward faces (index = 4 * (sx > 0) + 2 * (sy > 0) + (sz > 0)).
        faces = [(0, 1, 3, 2), (4, 6, 7, 5), (0, 4, 5, 1), (2, 3, 7, 6), (0, 2, 6, 4), (1, 5, 7, 3)]
        add_mesh(name, corners, faces, material)
    elif kind == "sphere":
        # A finely tessellated, smooth-shaded UV sphere: close to the analytic one, not exact.
        bpy.ops.mesh.primitive_uv_sphere_add(segments=256, ring_count=128, radius=shape["radius"],
                                             location=shape["center"])
        obj = bpy.context.active_object
        obj.name = name
        bpy.ops.object.shade_smooth()
        obj.data.materials.append(materials[material])
    elif kind == "mesh":
        # Flat shaded (the OBJ's own normals, if any, are not read), with its UV map.
        positions, faces, face_uvs = read_obj(os.path.join(files_base, shape["file"]))
        obj = add_mesh(name, positions, faces, material)
        uv_layer = obj.data.uv_layers.new(name="UVMap")
        for polygon, uvs in zip(obj.data.polygons, face_uvs):
            for loop, uv in zip(polygon.loop_indices, uvs):
                uv_layer.data[loop].uv = uv
        obj.matrix_world = mesh_transform(shape)
    else:
        raise SystemExit(f"{scenes_path}: /scenes/{scene_name}/shapes/{name}: unsupported type {kind}")

# Scene description: Y up; Blender: Z up. Rotating the whole scene keeps every relation (and the
# right-handedness), so build in Y-up and turn the objects by +90 degrees about X at the end.
to_blender = Matrix.Rotation(math.radians(90.0), 4, "X")
for obj in scene.collection.objects:
    obj.matrix_world = to_blender @ obj.matrix_world

camera_spec = description["camera"]
camera_data = bpy.data.cameras.new("camera")
camera_data.sensor_fit = "VERTICAL"
camera_data.angle_y = math.radians(camera_spec["vfov_deg"])
camera_data.clip_start = 1e-4
camera_data.clip_end = 1e4
camera = bpy.data.objects.new("camera", camera_data)
scene.collection.objects.link(camera)
eye = to_blender @ Vector(camera_spec["eye"])
target = to_blender @ Vector(camera_spec["target"])
up = (to_blender.to_3x3() @ Vector(camera_spec["up"])).normalized()
forward = (target - eye).normalized()
right = forward.cross(up).normalized()
true_up = right.cross(forward)
camera.matrix_world = Matrix((
    (right.x, true_up.x, -forward.x, eye.x),
    (right.y, true_up.y, -forward.y, eye.y),
    (right.z, true_up.z, -forward.z, eye.z),
    (0, 0, 0, 1)))
scene.camera = camera

world = bpy.data.worlds.new("world")
world.use_nodes = True
world.node_tree.nodes["Background"].inputs["Color"].default_value = rgba(description["environment"]["radiance"])
world.node_tree.nodes["Background"].inputs["Strength"].default_value = 1.0
scene.world = world

render = scene.render
render.engine = "CYCLES"
render.resolution_x = camera_spec["width"]
render.resolution_y = camera_spec["height"]
render.resolution_percentage = 100
render.threads_mode = "FIXED"
render.threads = threads
render.film_transparent = False
cycles = scene.cycles
cycles.device = "CPU"
cycles.samples = spp
cycles.use_adaptive_sampling = False
cycles.use_denoising = False
cycles.seed = seed
cycles.sampling_pattern = "PROGRESSIVE_MULTI_JITTER"
cycles.pixel_filter_type = "BOX"
cycles.filter_width = 1.0
for key in ("max_bounces", "diffuse_bounces", "glossy_bounces", "transmission_bounces", "transparent_max_bounces",
            "volume_bounces"):
    setattr(cycles, key, 64)
cycles.caustics_reflective = True
cycles.caustics_refractive = True
cycles.sample_clamp_direct = 0.0
cycles.sample_clamp_indirect = 0.0
cycles.blur_glossy = 0.0
scene.view_settings.view_transform = "Standard"
scene.view_settings.look = "None"
scene.view_settings.exposure = 0.0
scene.view_settings.gamma = 1.0
render.image_settings.file_format = "OPEN_EXR"
render.image_settings.color_depth = "32"

# The whole render call: scene sync (shader compilation, BVH), path tracing and writing the
# result. Cycles' own render time, which leaves the sync out, is in its log when Blender runs with
# --debug-cycles ("Render time (without synchronization)"); bench/cycles_race reads that one.
start = time.perf_counter()
bpy.ops.render.render(write_still=False)
seconds = time.perf_counter() - start

# The render result's pixels are only reachable through a saved file: EXR (scene linear), read
# back and written as PFM (rows bottom to top, as Blender's pixel buffer already has them).
with tempfile.TemporaryDirectory() as directory:
    exr = os.path.join(directory, "render.exr")
    bpy.data.images["Render Result"].save_render(filepath=exr)
    image = bpy.data.images.load(exr)
    width, height = image.size
    pixels = image.pixels[:]
rgb = bytearray()
for i in range(width * height):
    rgb += struct.pack("<3f", *pixels[4 * i:4 * i + 3])
with open(out_path + ".tmp", "wb") as f:
    f.write(f"PF\n{width} {height}\n-1.0\n".encode())
    f.write(rgb)
os.replace(out_path + ".tmp", out_path)
print(f"cycles_render_seconds {seconds:.4f}")
