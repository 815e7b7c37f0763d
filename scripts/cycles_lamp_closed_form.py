"""The lamp box's direct light in closed form, pixel by pixel, against both images of
scripts/cycles_check.sh's `lamp-direct` case: which of Grotto and Cycles is right.

Inside the empty box every wall point sees the whole glowing voxel, so its direct
radiance is albedo / pi x emission x the projected solid angle of the voxel's faces
turned toward it, each a polygon (Lambert's edge formula: half the sum over its
edges of the edge's angle times the normal's cosine to the edge's plane).

    blender -b --factory-startup -P scripts/cycles_lamp_closed_form.py -- \
        LAMP.json GROTTO.exr CYCLES_PREFIX
"""
import json
import math
import os
import sys

import numpy

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import cycles_check  # noqa: E402  (read_exr, LUMA)
import cycles_worlds as lamp  # noqa: E402  (the box's geometry and light)


def camera_rays(cam, width, height):
    """Unit rays through the pixels' centres, row 0 at the top (Grotto's camera: Y up,
    vertical field of view)."""
    p, t = numpy.array(cam["position"], float), numpy.array(cam["target"], float)
    f = (t - p) / numpy.linalg.norm(t - p)
    r = numpy.cross(f, [0.0, 1.0, 0.0])
    r /= numpy.linalg.norm(r)
    u = numpy.cross(r, f)
    h = math.tan(math.radians(cam["fov"]) / 2)
    x = (2 * (numpy.arange(width) + 0.5) / width - 1) * h * width / height
    y = (1 - 2 * (numpy.arange(height) + 0.5) / height) * h
    d = f + x[None, :, None] * r + y[:, None, None] * u
    return p, d / numpy.linalg.norm(d, axis=-1, keepdims=True)


def voxel_faces(lo, hi):
    """(corners, outward normal, centre) of the box's six faces."""
    faces = []
    for axis in range(3):
        a1, a2 = (axis + 1) % 3, (axis + 2) % 3
        for side, plane in ((-1.0, lo[axis]), (1.0, hi[axis])):
            quad = []
            for s1, s2 in ((0, 0), (1, 0), (1, 1), (0, 1)):
                v = numpy.zeros(3)
                v[axis], v[a1], v[a2] = plane, (lo, hi)[s1][a1], (lo, hi)[s2][a2]
                quad.append(v)
            normal = numpy.zeros(3)
            normal[axis] = side
            faces.append((numpy.array(quad), normal, numpy.mean(quad, axis=0)))
    return faces


def projected_solid_angle(point, normal, quad):
    corners = [(v - point) / numpy.linalg.norm(v - point) for v in quad]
    total = 0.0
    for k in range(len(corners)):
        a, b = corners[k], corners[(k + 1) % len(corners)]
        c = numpy.cross(a, b)
        if numpy.linalg.norm(c) > 1e-15:
            total += math.acos(min(1.0, max(-1.0, float(a @ b)))) * float(normal @ c) / numpy.linalg.norm(c)
    return abs(0.5 * total)


def closed_form(cam, width, height):
    """Luminance of the direct light at each pixel; NaN on the glowing voxel itself."""
    lo, hi = (numpy.array(c) for c in lamp.LAMP_VOXEL)
    faces = voxel_faces(lo, hi)
    light = numpy.array(lamp.LAMP_ALBEDO) * numpy.array(lamp.LAMP_EMISSION) / math.pi @ cycles_check.LUMA
    origin, rays = camera_rays(cam, width, height)
    out = numpy.full((height, width), numpy.nan)
    for j in range(height):
        for i in range(width):
            d = rays[j, i]
            with numpy.errstate(divide="ignore", invalid="ignore"):
                t0, t1 = (lo - origin) / d, (hi - origin) / d
                if numpy.max(numpy.minimum(t0, t1)) <= numpy.min(numpy.maximum(t0, t1)):
                    continue  # the ray meets the glowing voxel
                walls = numpy.where(d > 0, lamp.LAMP_INTERIOR - origin, -lamp.LAMP_INTERIOR - origin) / d
            axis = int(numpy.argmin(walls))
            point = origin + walls[axis] * d
            normal = numpy.zeros(3)
            normal[axis] = -numpy.sign(d[axis])
            omega = sum(projected_solid_angle(point, normal, q) for q, n, c in faces if (point - c) @ n > 1e-9)
            out[j, i] = light * omega
    return out


def main():
    world_path, grotto_path, cycles_prefix = sys.argv[sys.argv.index("--") + 1:][:3]
    world = json.load(open(world_path))
    cam = world["cameras"][world["default_camera"]]
    luma = lambda img: numpy.stack([img["R"], img["G"], img["B"]], -1) @ cycles_check.LUMA
    grotto = luma(cycles_check.read_exr(grotto_path))
    a, b = (luma(cycles_check.read_exr(f"{cycles_prefix}.{half}.exr")) for half in "ab")
    exact = closed_form(cam, grotto.shape[1], grotto.shape[0])
    walls = ~numpy.isnan(exact)
    cycles = 0.5 * (a + b)
    print(f"CLOSED_FORM {int(walls.sum())} wall pixels: mean over the closed form's, Grotto "
          f"{grotto[walls].sum() / exact[walls].sum():.5f}, Cycles {cycles[walls].sum() / exact[walls].sum():.5f}; "
          f"median ratio Grotto {numpy.median(grotto[walls] / exact[walls]):.5f}, "
          f"Cycles {numpy.median(cycles[walls] / exact[walls]):.5f}")


if __name__ == "__main__":
    main()
