"""The independent check of `grotto reference --light full`: renders the same view of
the same world with Blender's Cycles and compares the two images' radiance.

    blender -b --factory-startup -P scripts/cycles_check.py -- \
        --world W.json --camera NAME --mesh W.gltf --grotto light.exr --size 160x90 \
        --samples 1024 [--bounces B] --out PREFIX

W.gltf is `grotto export-mesh W.json --origin world -o W.gltf` (world coordinates,
the materials' albedo and emission); light.exr is `grotto reference W.json --light
full` of the same camera and size. Renders twice with half the samples and different
seeds, PREFIX.a.exr and PREFIX.b.exr (Cycles' radiance, RGBA, A = 1 on surface
pixels), and writes PREFIX.json (the figures) and prints them. Run by hand
(scripts/cycles_check.sh); needs Debian's blender and python3-numpy.

The scene is Grotto's light as docs/lighting.md ("Units") defines it:
- Faces: Diffuse BSDF at roughness 0, which is exactly Lambertian (Principled's
  diffuse has a retro-reflective term even at specular 0), plus an Emission of the
  material's emission (radiance = colour x strength, as Grotto's).
- Sky: the world shader evaluates ambient.intensity x (horizon + (zenith - horizon)
  x sqrt(w.y)) above the horizon, 0.8 x horizon below, w in Grotto's Y-up frame
  (Blender's Z).
- Sun: a Sun lamp of the same angular diameter. Blender's sun strength is the
  irradiance at normal incidence (W/m^2, a white Lambertian face sends back
  strength / pi); Grotto's sun gives irradiance pi x color x intensity, so the
  strength is pi x intensity and the colour the sun's.
- Camera: the world camera's position and target, vertical field of view, pixels
  sampled at their centres (filter width 0.01 px), as the reference's G-buffer is.
No clamping, no denoising, no adaptive sampling, Standard view transform, exposure 0.
"""
import argparse
import json
import math
import os
import struct
import sys
import zlib

import numpy

numpy.bool = bool  # Blender 3.4's glTF importer still names numpy.bool (gone in numpy 1.24)
import bpy  # noqa: E402
import mathutils  # noqa: E402

# Grotto's defaults (include/grotto/settings.h), for fields a world file leaves out.
DEFAULT_LIGHTING = {
    "sun": {"direction": [0.45, 0.8, 0.3], "color": [1.0, 0.95, 0.85], "intensity": 1.0, "angle": 0.0},
    "ambient": {"intensity": 0.7},
    "sky": {"zenith": [0.28, 0.45, 0.78], "horizon": [0.75, 0.82, 0.92]},
}
LUMA = numpy.array([0.2126, 0.7152, 0.0722])  # Rec. 709, as Grotto's luminance


def blender_vec(v):
    """Grotto / glTF (Y up) to Blender (Z up), as Blender's glTF importer turns them."""
    return mathutils.Vector((v[0], -v[2], v[1]))


def read_exr(path):
    """{channel: HxW float array} of a scanline EXR of FLOAT channels, no or ZIP compression
    (what Grotto and Blender write here). Row 0 is the top."""
    data = open(path, "rb").read()
    if data[:4] != b"\x76\x2f\x31\x01":
        raise SystemExit(f"{path}: not an OpenEXR file")
    pos, attrs = 8, {}
    while data[pos] != 0:
        name_end = data.index(b"\0", pos)
        type_end = data.index(b"\0", name_end + 1)
        size = struct.unpack_from("<i", data, type_end + 1)[0]
        attrs[data[pos:name_end].decode()] = data[type_end + 5:type_end + 5 + size]
        pos = type_end + 5 + size
    pos += 1
    channels, c = [], attrs["channels"]
    while c[0] != 0:
        end = c.index(b"\0")
        if struct.unpack_from("<i", c, end + 1)[0] != 2:
            raise SystemExit(f"{path}: channel {c[:end].decode()} is not 32-bit float")
        channels.append(c[:end].decode())
        c = c[end + 17:]
    x0, y0, x1, y1 = struct.unpack("<4i", attrs["dataWindow"])
    w, h = x1 - x0 + 1, y1 - y0 + 1
    compression = attrs["compression"][0]
    lines = {0: 1, 2: 1, 3: 16}.get(compression)
    if lines is None:
        raise SystemExit(f"{path}: compression {compression} is not read here (none or ZIP)")
    blocks = (h + lines - 1) // lines
    offsets = struct.unpack_from(f"<{blocks}Q", data, pos)
    out = {ch: numpy.zeros((h, w), numpy.float32) for ch in channels}
    for off in offsets:
        y, size = struct.unpack_from("<ii", data, off)
        raw = data[off + 8:off + 8 + size]
        n = min(lines, y0 + h - y)
        if compression != 0 and size < n * w * 4 * len(channels):
            t = numpy.frombuffer(zlib.decompress(raw), numpy.uint8).astype(numpy.int64)
            t = numpy.cumsum(t - 128) + 128  # undo the byte predictor (first byte stored as is)
            t = (t & 0xFF).astype(numpy.uint8)
            half = (len(t) + 1) // 2
            raw_bytes = numpy.empty_like(t)
            raw_bytes[0::2], raw_bytes[1::2] = t[:half], t[half:]
            raw = raw_bytes.tobytes()
        block = numpy.frombuffer(raw, numpy.float32).reshape(n, len(channels), w)
        for i, ch in enumerate(channels):
            out[ch][y - y0:y - y0 + n] = block[:, i]
    return out


def world_lighting(world):
    lighting = json.loads(json.dumps(DEFAULT_LIGHTING))
    for block, fields in world.get("lighting", {}).items():
        if isinstance(fields, dict) and block in lighting:
            lighting[block].update(fields)
    return lighting


def diffuse_material(name, albedo, emission, strength):
    mat = bpy.data.materials.new(name)
    mat.use_nodes = True
    nodes, links = mat.node_tree.nodes, mat.node_tree.links
    nodes.clear()
    out = nodes.new("ShaderNodeOutputMaterial")
    diffuse = nodes.new("ShaderNodeBsdfDiffuse")
    diffuse.inputs["Color"].default_value = (*albedo[:3], 1.0)
    diffuse.inputs["Roughness"].default_value = 0.0
    shader = diffuse.outputs["BSDF"]
    if any(e > 0 for e in emission) and strength > 0:
        glow = nodes.new("ShaderNodeEmission")
        glow.inputs["Color"].default_value = (*emission, 1.0)
        glow.inputs["Strength"].default_value = strength
        add = nodes.new("ShaderNodeAddShader")
        links.new(shader, add.inputs[0])
        links.new(glow.outputs["Emission"], add.inputs[1])
        shader = add.outputs["Shader"]
    links.new(shader, out.inputs["Surface"])
    return mat


def set_materials(gltf_path):
    """Each imported material becomes Lambertian with the glTF file's albedo and emission."""
    gltf = json.load(open(gltf_path))
    by_name = {}
    for m in gltf.get("materials", []):
        strength = m.get("extensions", {}).get("KHR_materials_emissive_strength", {}).get("emissiveStrength", 1.0)
        by_name[m["name"]] = diffuse_material(m["name"], m["pbrMetallicRoughness"]["baseColorFactor"],
                                              m.get("emissiveFactor", [0.0, 0.0, 0.0]), strength)
    for obj in bpy.context.scene.objects:
        for slot in getattr(obj, "material_slots", []):
            name = slot.material.name if slot.material else ""
            base = name if name in by_name else name.rsplit(".", 1)[0]
            if base not in by_name:
                raise SystemExit(f"{gltf_path}: Blender's material '{name}' matches no glTF material")
            slot.material = by_name[base]


def set_sky(lighting):
    world = bpy.data.worlds.new("grotto sky")
    bpy.context.scene.world = world
    world.use_nodes = True
    nodes, links = world.node_tree.nodes, world.node_tree.links
    nodes.clear()
    zenith, horizon = lighting["sky"]["zenith"], lighting["sky"]["horizon"]
    direction = nodes.new("ShaderNodeTexCoord").outputs["Generated"]  # the ray's direction in a world shader
    unit = nodes.new("ShaderNodeVectorMath")
    unit.operation = "NORMALIZE"
    links.new(direction, unit.inputs[0])
    xyz = nodes.new("ShaderNodeSeparateXYZ")
    links.new(unit.outputs["Vector"], xyz.inputs[0])
    up = xyz.outputs["Z"]  # Grotto's w.y
    clamped = nodes.new("ShaderNodeMath")
    clamped.operation = "MAXIMUM"
    links.new(up, clamped.inputs[0])
    clamped.inputs[1].default_value = 0.0
    root = nodes.new("ShaderNodeMath")
    root.operation = "SQRT"
    links.new(clamped.outputs[0], root.inputs[0])
    above = nodes.new("ShaderNodeMixRGB")
    links.new(root.outputs[0], above.inputs["Fac"])
    above.inputs["Color1"].default_value = (*horizon, 1.0)
    above.inputs["Color2"].default_value = (*zenith, 1.0)
    is_above = nodes.new("ShaderNodeMath")
    is_above.operation = "GREATER_THAN"
    links.new(up, is_above.inputs[0])
    is_above.inputs[1].default_value = 0.0
    sky = nodes.new("ShaderNodeMixRGB")
    links.new(is_above.outputs[0], sky.inputs["Fac"])
    sky.inputs["Color1"].default_value = (*(0.8 * h for h in horizon), 1.0)
    links.new(above.outputs["Color"], sky.inputs["Color2"])
    background = nodes.new("ShaderNodeBackground")
    links.new(sky.outputs["Color"], background.inputs["Color"])
    background.inputs["Strength"].default_value = lighting["ambient"]["intensity"]
    out = nodes.new("ShaderNodeOutputWorld")
    links.new(background.outputs["Background"], out.inputs["Surface"])


def set_sun(lighting):
    sun = lighting["sun"]
    if sun["intensity"] <= 0:
        return
    light = bpy.data.lights.new("grotto sun", "SUN")
    light.energy = math.pi * sun["intensity"]  # irradiance pi x color x intensity at normal incidence
    light.color = sun["color"]
    light.angle = math.radians(sun.get("angle", 0.0))  # both: the angular diameter
    obj = bpy.data.objects.new("grotto sun", light)
    bpy.context.scene.collection.objects.link(obj)
    towards = blender_vec(sun["direction"]).normalized()
    obj.rotation_euler = towards.to_track_quat("Z", "Y").to_euler()  # the lamp shines down its -Z


def set_camera(cam, width, height):
    data = bpy.data.cameras.new("grotto camera")
    data.sensor_fit = "VERTICAL"
    data.angle_y = math.radians(cam.get("fov", 60.0))
    data.clip_start, data.clip_end = 1e-3, 1e5
    obj = bpy.data.objects.new("grotto camera", data)
    bpy.context.scene.collection.objects.link(obj)
    obj.location = blender_vec(cam["position"])
    obj.rotation_euler = (blender_vec(cam["target"]) - obj.location).to_track_quat("-Z", "Y").to_euler()
    scene = bpy.context.scene
    scene.camera = obj
    scene.render.resolution_x, scene.render.resolution_y, scene.render.resolution_percentage = width, height, 100


def set_cycles(samples, bounces, threads):
    scene = bpy.context.scene
    scene.render.engine = "CYCLES"
    c = scene.cycles
    c.device = "CPU"
    c.samples = samples
    c.use_adaptive_sampling = False
    c.use_denoising = False
    c.max_bounces = c.diffuse_bounces = bounces
    c.glossy_bounces = c.transmission_bounces = c.volume_bounces = c.transparent_max_bounces = 0
    c.sample_clamp_direct = c.sample_clamp_indirect = 0.0  # clamping biases the light
    c.light_sampling_threshold = 0.0
    c.filter_width = 0.01  # a pixel is its centre's radiance, as the reference's
    scene.render.film_transparent = True  # alpha 1 marks the surface pixels
    scene.view_settings.view_transform = "Standard"
    scene.view_settings.look = "None"
    scene.view_settings.exposure = 0.0
    scene.view_settings.gamma = 1.0
    if threads > 0:
        scene.render.threads_mode, scene.render.threads = "FIXED", threads
    f = scene.render.image_settings
    f.file_format, f.color_mode, f.color_depth, f.exr_codec = "OPEN_EXR", "RGBA", "32", "ZIP"


def render(path, seed):
    scene = bpy.context.scene
    scene.cycles.seed = seed
    scene.render.filepath = path
    bpy.ops.render.render(write_still=True)
    return read_exr(path)


def compare(grotto, a, b):
    """Figures of Grotto's luminance against Cycles' (the mean of renders a and b) over
    the pixels both call surface, with each side's noise: Grotto's from its standard
    errors, Cycles' from the difference of its two independent halves."""
    rgb = lambda img: numpy.stack([img["R"], img["G"], img["B"]], -1)
    g, ca, cb = rgb(grotto), rgb(a), rgb(b)
    c = 0.5 * (ca + cb)
    surface = (a["A"] > 0.999) & (b["A"] > 0.999)
    yg, yc = g[surface] @ LUMA, c[surface] @ LUMA
    se_g = numpy.stack([grotto["R_stderr"], grotto["G_stderr"], grotto["B_stderr"]], -1)[surface] @ LUMA
    se_c = 0.5 * numpy.abs((ca[surface] - cb[surface]) @ LUMA)  # one pixel's |a - b| / 2 estimates its error
    mean_c = float(yc.mean())
    lit = yc > 1e-3 * mean_c
    noise = math.sqrt(float(numpy.mean(se_g ** 2) + numpy.mean(se_c ** 2)))
    return {
        "surface_pixels": int(surface.sum()),
        "grotto_mean": float(yg.mean()),
        "cycles_mean": mean_c,
        "mean_ratio": float(yg.mean()) / mean_c,
        "mean_ratio_stderr": noise / math.sqrt(surface.sum()) / mean_c,
        "channel_mean_ratios": [float(g[surface][:, k].mean() / c[surface][:, k].mean()) for k in range(3)],
        "median_ratio": float(numpy.median(yg[lit] / yc[lit])),
        "relative_rmse": math.sqrt(float(numpy.mean((yg - yc) ** 2))) / mean_c,
        "relative_rmse_of_noise": noise / mean_c,
    }


def main():
    argv = sys.argv[sys.argv.index("--") + 1:] if "--" in sys.argv else []
    p = argparse.ArgumentParser(prog="cycles_check.py")
    p.add_argument("--world", required=True)
    p.add_argument("--camera")
    p.add_argument("--mesh", required=True)
    p.add_argument("--grotto", required=True)
    p.add_argument("--size", default="160x90")
    p.add_argument("--samples", type=int, default=1024)
    p.add_argument("--bounces", type=int, default=128, help="Cycles' max bounces (0: direct light only)")
    p.add_argument("--threads", type=int, default=0)
    p.add_argument("--out", required=True)
    args = p.parse_args(argv)
    width, height = (int(v) for v in args.size.split("x"))
    world = json.load(open(args.world))
    camera_name = args.camera or world.get("default_camera")
    camera = world.get("cameras", {}).get(camera_name)
    if camera is None:
        raise SystemExit(f"{args.world}: no camera '{camera_name}'")
    lighting = world_lighting(world)

    bpy.ops.wm.read_factory_settings(use_empty=True)
    bpy.ops.import_scene.gltf(filepath=os.path.abspath(args.mesh))
    set_materials(args.mesh)
    set_sky(lighting)
    set_sun(lighting)
    set_camera(camera, width, height)
    set_cycles(max(1, args.samples // 2), args.bounces, args.threads)
    a = render(os.path.abspath(args.out + ".a.exr"), 1)
    b = render(os.path.abspath(args.out + ".b.exr"), 2)
    grotto = read_exr(args.grotto)
    if grotto["R"].shape != a["R"].shape:
        raise SystemExit(f"{args.grotto}: {grotto['R'].shape[1]}x{grotto['R'].shape[0]}, not {args.size}")
    figures = compare(grotto, a, b)
    figures.update(world=args.world, camera=camera_name, size=args.size, samples=args.samples, bounces=args.bounces)
    with open(args.out + ".json.tmp", "w") as f:
        json.dump(figures, f, indent=1)
    os.replace(args.out + ".json.tmp", args.out + ".json")
    print("CYCLES_CHECK " + json.dumps(figures))


if __name__ == "__main__":
    main()
