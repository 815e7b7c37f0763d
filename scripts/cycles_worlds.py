"""Writes the two made-up worlds scripts/cycles_check.sh compares with Cycles, each a
.vox model and a world .json whose materials, light and camera are the case's:

  slab: a 40 x 40 slab of albedo 0.5 under a uniform sky of 1, no sun; every top
        face sees the whole sky and nothing else, so its radiance is exactly 0.5.
  sunlit: the same slab under Grotto's default sky gradient (intensity 1) and a
        2-degree sun of (1, 0.9, 0.8) x 1: albedo x (sun x cos + the gradient's
        irradiance / pi), which checks the sun's scale and the sky's formula.
  lamp: a closed 14-voxel box (albedo 0.7, 0.6, 0.5) with one voxel on its floor
        glowing at 8 x (1, 0.85, 0.6); no sky or sun gets in.

    python3 scripts/cycles_worlds.py DIR
Plain Python, no packages: .vox is a few chunks (as scripts/make-demo-vox.py).
"""
import json
import os
import struct
import sys


# The lamp box in Grotto's world coordinates (a .vox model is centred: x - 7, its
# z up - 7, 6 - its y), for the closed form of its direct light
# (scripts/cycles_lamp_closed_form.py).
LAMP_INTERIOR = 6.0                             # the open inside is [-6, 6]^3
LAMP_VOXEL = ((-1.0, -6.0, -1.0), (0.0, -5.0, 0.0))  # the glowing voxel's corners
LAMP_ALBEDO = (0.7, 0.6, 0.5)
LAMP_EMISSION = (8.0, 6.8, 4.8)                 # 8 x (1, 0.85, 0.6)


def chunk(tag, content, children=b""):
    return tag + struct.pack("<II", len(content), len(children)) + content + children


def vox_bytes(size, voxels):
    """voxels: {(x, y, z): colour index}, MagicaVoxel's z up."""
    items = sorted(voxels.items())
    xyzi = struct.pack("<I", len(items)) + b"".join(struct.pack("<4B", *k, c) for k, c in items)
    body = chunk(b"SIZE", struct.pack("<3I", *size)) + chunk(b"XYZI", xyzi)
    return b"VOX " + struct.pack("<I", 150) + chunk(b"MAIN", b"", body)


def write_atomically(path, data):
    with open(path + ".tmp", "wb") as f:
        f.write(data)
    os.replace(path + ".tmp", path)


def write_world(out_dir, name, size, voxels, world):
    write_atomically(os.path.join(out_dir, name + ".vox"), vox_bytes(size, voxels))
    world = dict({"grid": {"file": name + ".vox"}}, **world)
    write_atomically(os.path.join(out_dir, name + ".json"), json.dumps(world, indent=1).encode())


def slab(out_dir, name, lighting):
    n = 40
    voxels = {(x, y, 0): 1 for x in range(n) for y in range(n)}
    write_world(out_dir, name, (n, n, 1), voxels, {
        "materials": [{"name": "grey", "albedo": [0.5, 0.5, 0.5]}],
        "lighting": lighting,
        # Looking down at the slab's middle (.vox models are centred in x and z, standing
        # on y = 0 when 1 voxel high): only top faces in view.
        "cameras": {"top": {"position": [0, 14, 12], "target": [0, 1, 0], "fov": 50}},
        "default_camera": "top",
    })


def lamp(out_dir):
    n = 14
    voxels = {(x, y, z): 1 for x in range(n) for y in range(n) for z in range(n)
              if min(x, y, z) == 0 or max(x, y, z) == n - 1}
    voxels[(6, 7, 1)] = 2  # on the floor (z = 0 is the floor, z up); Grotto centres the box on 0
    write_world(out_dir, "lamp", (n, n, n), voxels, {
        "materials": [{"name": "wall", "albedo": list(LAMP_ALBEDO)},
                      {"name": "lamp", "albedo": [0.5, 0.5, 0.5],
                       "emission": {"color": [1.0, 0.85, 0.6], "intensity": 8.0}}],
        "lighting": {"sun": {"intensity": 0.0}},
        "cameras": {"corner": {"position": [5, 4, 5], "target": [-0.5, -5.5, 0], "fov": 70}},
        "default_camera": "corner",
    })


if __name__ == "__main__":
    out = sys.argv[1]
    os.makedirs(out, exist_ok=True)
    slab(out, "slab", {"sun": {"intensity": 0.0}, "ambient": {"intensity": 1.0},
                       "sky": {"zenith": [1, 1, 1], "horizon": [1, 1, 1]}})
    slab(out, "sunlit", {"sun": {"direction": [0.3, 1, 0.2], "color": [1, 0.9, 0.8], "intensity": 1.0, "angle": 2},
                         "ambient": {"intensity": 1.0}})
    lamp(out)
