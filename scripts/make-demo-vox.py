#!/usr/bin/env python3
"""Writes worlds/demo.vox: a small island as a MagicaVoxel model (deterministic).

The demo's world (worlds/demo.json) and the first-hour guide (docs/guide.md) use
it: grass over dirt and stone, a pond, a sand path, trees, a house with a red roof
and an open door, and a stone arch, so the sky light and the AO have corners,
overhangs and interiors to show. Plain Python, no packages: .vox is a few chunks.
  scripts/make-demo-vox.py [OUT]   (default worlds/demo.vox)
"""
import math
import os
import struct
import sys

SX, SY, SZ = 64, 64, 40  # MagicaVoxel axes: X, Y across, Z up

# Colour index -> sRGB; MagicaVoxel's palette entry i is colour index i + 1.
PALETTE = {
    1: (104, 168, 64),    # grass
    2: (128, 86, 52),     # dirt
    3: (128, 128, 134),   # stone
    4: (54, 112, 186),    # water
    5: (222, 200, 138),   # sand
    6: (102, 70, 42),     # bark
    7: (52, 128, 58),     # leaves
    8: (236, 226, 204),   # plaster
    9: (190, 58, 44),     # roof
    10: (150, 100, 60),   # door and frames
    11: (236, 196, 56),   # flowers
}
GRASS, DIRT, STONE, WATER, SAND, BARK, LEAVES, PLASTER, ROOF, WOOD, FLOWERS = range(1, 12)
WATER_LEVEL = 3  # the sea around the island, over the base's top
POND_LEVEL = 6


def height(x, y):
    """Ground height: a rolling island that falls into the water at its rim."""
    cx, cy = x - SX / 2 + 0.5, y - SY / 2 + 0.5
    r = math.hypot(cx, cy) / (SX / 2)
    hills = 2.2 * math.sin(x * 0.21) * math.cos(y * 0.17) + 1.6 * math.sin((x + 2 * y) * 0.09)
    h = 8.0 + hills - 13.0 * max(0.0, r - 0.55) ** 1.4 * 2.2
    if in_pond(x, y) and h > POND_LEVEL:  # the pond's hollow, its floor below its water
        h = POND_LEVEL - 1 - int(2.5 * (1.0 - pond_distance(x, y)))
    return int(round(h))


def pond_distance(x, y):
    return math.hypot((x - 20) / 7.5, (y - 41) / 6.0)


def in_pond(x, y):
    return pond_distance(x, y) < 1.0


def inside_base(x, y):
    """The round stone base the island stands on, under the sea."""
    return math.hypot(x - SX / 2 + 0.5, y - SY / 2 + 0.5) < SX / 2 - 0.5


def hashed(x, y, k):
    """A fixed pseudo-random number in [0, 1) per cell, independent of visiting order."""
    n = (x * 73856093) ^ (y * 19349663) ^ (k * 83492791)
    n = (n ^ (n >> 13)) * 1274126177 & 0xFFFFFFFF
    return ((n ^ (n >> 16)) & 0xFFFF) / 65536.0


def build():
    v = {}
    ground = {}
    for x in range(SX):
        for y in range(SY):
            if not inside_base(x, y):
                continue
            h = max(height(x, y), WATER_LEVEL - 2)
            ground[(x, y)] = h
            for z in range(0, h + 1):
                depth = h - z
                v[(x, y, z)] = GRASS if depth == 0 else DIRT if depth < 3 else STONE
            level = POND_LEVEL if in_pond(x, y) and h < POND_LEVEL - 1 else WATER_LEVEL
            if h < level:
                v[(x, y, h)] = SAND
                for z in range(h + 1, level + 1):
                    v[(x, y, z)] = WATER
            elif h == level + 1 or (h == level + 2 and hashed(x, y, 1) < 0.5):
                v[(x, y, h)] = SAND
    # A sand path from the house's door to the pond.
    for t in range(0, 40):
        px, py = int(34 - t * 0.45), int(30 + t * 0.35)
        for dx in (0, 1):
            h = ground.get((px + dx, py), -1)
            if h > WATER_LEVEL:
                v[(px + dx, py, h)] = SAND
    # The house: plaster walls on a stone plinth, an open door, windows, a pitched roof.
    x0, x1, y0, y1 = 30, 42, 20, 29
    base = max(ground[(x, y)] for x in range(x0, x1 + 1) for y in range(y0, y1 + 1))
    for x in range(x0, x1 + 1):
        for y in range(y0, y1 + 1):
            for z in range(ground[(x, y)], base + 1):
                v[(x, y, z)] = STONE
            wall = x in (x0, x1) or y in (y0, y1)
            for z in range(base + 1, base + 7):
                v.pop((x, y, z), None)
                if wall:
                    v[(x, y, z)] = PLASTER
    for z in range(base + 1, base + 5):  # the door, in the +Y wall
        for x in (35, 36):
            v.pop((x, y1, z), None)
    for x in (34, 37):
        for z in range(base + 1, base + 6):
            v[(x, y1, z)] = WOOD
    for (wx, wy) in ((x0, 24), (x0, 25), (x1, 24), (x1, 25), (32, y0), (33, y0), (39, y0), (40, y0)):
        for z in (base + 3, base + 4):
            v.pop((wx, wy, z), None)
    for step in range(0, 7):  # the roof: two slopes meeting over the ridge along X
        z = base + 7 + step
        for x in range(x0 - 1, x1 + 2):
            for y in (y0 - 1 + step, y1 + 1 - step):
                v[(x, y, z)] = ROOF
            if step < 6:
                for y in range(y0 + step, y1 - step + 1):
                    if x in (x0, x1):
                        v[(x, y, z)] = PLASTER
    # Trees: a trunk and a round crown.
    for (tx, ty, th) in ((14, 18, 7), (20, 12, 9), (40, 8, 8), (50, 20, 7), (24, 30, 6), (42, 52, 8), (10, 28, 6), (26, 52, 7)):
        g = ground[(tx, ty)]
        for z in range(g + 1, g + th + 1):
            v[(tx, ty, z)] = BARK
        c = g + th + 1
        for x in range(tx - 4, tx + 5):
            for y in range(ty - 4, ty + 5):
                for z in range(c - 3, c + 4):
                    d = math.sqrt((x - tx) ** 2 + (y - ty) ** 2 + ((z - c) * 1.25) ** 2)
                    if d < 3.6 + 0.8 * hashed(x, y, z) and (x, y, z) not in v:
                        v[(x, y, z)] = LEAVES
    # A stone arch across the hill to the east.
    ax, ay = 48, 33
    for t in range(-8, 9):
        for w in range(0, 3):
            y = ay + w
            top = ground[(ax + t, y)] + int(round(9 * math.sqrt(max(0.0, 1 - (t / 8.5) ** 2))))
            inner = ground[(ax + t, y)] + int(round(7 * math.sqrt(max(0.0, 1 - (t / 6.0) ** 2)))) if abs(t) < 6 else -1
            for z in range(ground[(ax + t, y)] + 1, top + 1):
                if z > inner:
                    v[(ax + t, y, z)] = STONE
    # Flowers on the grass.
    for (x, y), z in ground.items():
        if v.get((x, y, z)) == GRASS and hashed(x, y, 7) < 0.035 and (x, y, z + 1) not in v:
            v[(x, y, z + 1)] = FLOWERS
    return v


def chunk(tag, content, children=b""):
    return tag + struct.pack("<II", len(content), len(children)) + content + children


def vox_bytes(voxels):
    items = sorted((k, c) for k, c in voxels.items() if 0 <= k[2] < SZ)
    xyzi = struct.pack("<I", len(items)) + b"".join(struct.pack("<4B", x, y, z, c) for (x, y, z), c in items)
    rgba = b"".join(struct.pack("<4B", *PALETTE.get(i, (200, 200, 200)), 255) for i in range(1, 257))
    body = chunk(b"SIZE", struct.pack("<3I", SX, SY, SZ)) + chunk(b"XYZI", xyzi) + chunk(b"RGBA", rgba)
    return b"VOX " + struct.pack("<I", 150) + chunk(b"MAIN", b"", body)


if __name__ == "__main__":
    out = sys.argv[1] if len(sys.argv) > 1 else "worlds/demo.vox"
    with open(out + ".tmp", "wb") as f:
        f.write(vox_bytes(build()))
    os.replace(out + ".tmp", out)  # whole or untouched
