// thin: the thin-occluder stress case. Everything except the floor is one voxel
// thick: fence posts and rails, freestanding poles, a raised grate with 1- and
// 2-voxel gaps, and plates standing and lying. Screen-space AO sees each of these
// as a single depth layer, so it tends to over-darken behind them.
#include "voxel/generators/noise.h"
#include "voxel/mkworld.h"

#include "voxel/openvdb_grids.h"

#include <algorithm>

namespace grotto::voxel {

openvdb::GridBase::Ptr generateThin(const GeneratorOptions& options) {
    auto grid = openvdb::BoolGrid::create(false);
    grid->setTransform(openvdb::math::Transform::createLinearTransform(options.voxelSize));
    grid->setName("solid");

    const int S = options.size;
    const int lo = -S / 2, hi = lo + S;
    // Half-open box, clipped to the footprint so small sizes stay valid.
    auto box = [&](int x0, int y0, int z0, int x1, int y1, int z1) {
        x0 = std::max(x0, lo), z0 = std::max(z0, lo);
        x1 = std::min(x1, hi), z1 = std::min(z1, hi);
        if (x0 < x1 && y0 < y1 && z0 < z1)
            grid->fill(openvdb::CoordBBox({x0, y0, z0}, {x1 - 1, y1 - 1, z1 - 1}), true, true);
    };
    auto column = [&](int x, int z, int y0, int y1) { box(x, y0, z, x + 1, y1, z + 1); };

    box(lo, -2, lo, hi, 0, hi);  // floor slab, top at y = 0

    // Fence along x: posts every 4 voxels, rails at two heights.
    const int fz = lo + 4;
    for (int x = lo + 4; x < hi - 4; x += 4) column(x, fz, 0, 6);
    box(lo + 4, 2, fz, hi - 4, 3, fz + 1);
    box(lo + 4, 5, fz, hi - 4, 6, fz + 1);
    // Fence along z, denser: posts every 3, rails lower.
    const int fx = lo + 4;
    for (int z = lo + 4; z < lo + S / 2; z += 3) column(fx, z, 0, 5);
    box(fx, 1, lo + 4, fx + 1, 2, lo + S / 2);
    box(fx, 4, lo + 4, fx + 1, 5, lo + S / 2);

    // Freestanding poles two voxels apart, 2..21 voxels tall (the seed picks).
    const int pz = lo + 12;
    for (int i = 0, x = lo + 8; x < hi - 8; ++i, x += 3)
        column(x, pz, 0, 2 + int(hashCoord(i, 0, 0, options.seed) % 20u));

    // Grate raised 8 voxels on four legs: bars along x with gaps of 1 and 2
    // voxels in turn, held by two cross bars along z.
    const int gx0 = lo + 8, gx1 = lo + 28, gz0 = lo + 18, gz1 = lo + 38, gy = 8;
    for (int z = gz0, i = 0; z < gz1; z += (i++ % 2 == 0) ? 2 : 3)
        box(gx0, gy, z, gx1, gy + 1, z + 1);
    box(gx0, gy, gz0, gx0 + 1, gy + 1, gz1);
    box(gx1 - 1, gy, gz0, gx1, gy + 1, gz1);
    for (int x : {gx0, gx1 - 1})
        for (int z : {gz0, gz1 - 1}) column(x, z, 0, gy);

    // Plates: a standing plate carrying a lying one (an L), the lying plate's far
    // edge on two legs, and a second standing plate one voxel in front of the first.
    const int xp = lo + S / 2 + 4, pz0 = lo + 20, pz1 = lo + 36, top = 14;
    box(xp, 0, pz0, xp + 1, top, pz1);
    box(xp, top, pz0, xp + 16, top + 1, pz1);
    column(xp + 15, pz0, 0, top);
    column(xp + 15, pz1 - 1, 0, top);
    box(xp - 2, 0, pz0 + 3, xp - 1, 10, pz1 - 3);
    // A low lying plate on a single central leg, like a mushroom.
    box(xp + 4, 3, lo + 44, xp + 12, 4, lo + 54);
    column(xp + 8, lo + 49, 0, 3);

    return grid;
}

}  // namespace grotto::voxel
