// rooms: an indoor test scene for AO. Concave 90° corners, doorways, a one-voxel
// crevice, a staircase up to a mezzanine (an overhang), and a table whose legs are
// one voxel thin. Layout positions scale with options.size; the small features keep
// their sizes in voxels because they are what the AO has to resolve.
#include "voxel/generators/noise.h"
#include "voxel/mkworld.h"

#include "voxel/openvdb_grids.h"

#include <algorithm>

namespace grotto::voxel {
namespace {

enum RoomMaterial : int32_t { Floor = 1, Wall = 2, Stairs = 3, Wood = 4, Stone = 5, Trim = 6 };

class Builder {
public:
    Builder(openvdb::Int32Grid& grid, int lo, int hi) : grid_(grid), lo_(lo), hi_(hi) {}

    // Half-open box [x0,x1) x [y0,y1) x [z0,z1), clipped to the world's footprint.
    void box(int x0, int y0, int z0, int x1, int y1, int z1, int32_t material) {
        x0 = std::max(x0, lo_), z0 = std::max(z0, lo_);
        x1 = std::min(x1, hi_), z1 = std::min(z1, hi_);
        if (x0 >= x1 || y0 >= y1 || z0 >= z1) return;
        const openvdb::CoordBBox bbox({x0, y0, z0}, {x1 - 1, y1 - 1, z1 - 1});
        if (material == 0)
            grid_.fill(bbox, 0, /*active=*/false);
        else
            grid_.fill(bbox, material, /*active=*/true);
    }
    void carve(int x0, int y0, int z0, int x1, int y1, int z1) { box(x0, y0, z0, x1, y1, z1, 0); }

private:
    openvdb::Int32Grid& grid_;
    int lo_, hi_;
};

}  // namespace

openvdb::GridBase::Ptr generateRooms(const GeneratorOptions& options) {
    auto grid = openvdb::Int32Grid::create(0);
    grid->setTransform(openvdb::math::Transform::createLinearTransform(options.voxelSize));
    grid->setName("material");

    const int S = options.size;
    const int lo = -S / 2, hi = lo + S;
    const int T = 3;                    // wall thickness
    const int H = std::max(12, S / 2);  // wall height; no ceiling, so the sun gets in
    const int door = 4, doorH = 10;
    Builder b(*grid, lo, hi);

    // Floor slab below y = 0 and the enclosing walls.
    b.box(lo, -6, lo, hi, 0, hi, Floor);
    b.box(lo, 0, lo, hi, H, lo + T, Wall);
    b.box(lo, 0, hi - T, hi, H, hi, Wall);
    b.box(lo, 0, lo, lo + T, H, hi, Wall);
    b.box(hi - T, 0, lo, hi, H, hi, Wall);

    // Wall A splits west from east; wall B splits the east half: three rooms.
    const int xa = lo + S * 3 / 8, zb = lo + S / 2;
    b.box(xa, 0, lo, xa + T, H, hi, Wall);
    b.box(xa + T, 0, zb, hi, H, zb + T, Wall);
    const int zd = lo + S / 4, xd = xa + T + S / 8;
    b.carve(xa, 0, zd, xa + T, doorH, zd + door);
    b.carve(xd, 0, zb, xd + door, doorH, zb + T);

    // Crevice: wall C stands one voxel west of wall A, closed at the north end.
    b.box(xa - 3, 0, lo + S * 5 / 8, xa - 1, H, hi - T, Wall);
    // A two-voxel slot between a lower slab and the east wall (north-east room).
    b.box(hi - T - 4, 0, zb + T + 4, hi - T - 2, 16, zb + T + 16, Trim);
    // A low bench along the west wall: more concave edges at floor level.
    b.box(lo + T, 0, lo + T, lo + T + 3, 4, lo + T + S / 4, Trim);

    // South-east room: a mezzanine in the corner, reached by seven steps (rise 2, run 2).
    const int mx = hi - T - 12, mz0 = lo + T, mz1 = lo + T + 14, mTop = 14;
    b.box(mx, mTop - 2, mz0, hi - T, mTop, mz1, Stone);
    b.box(mx, 0, mz1 - 2, mx + 2, mTop - 2, mz1, Trim);  // pillar under the free corner
    const int steps = mTop / 2;
    for (int i = 0; i < steps; ++i) {
        const int x0 = mx - 2 * (steps - i);
        b.box(x0, 0, mz0, x0 + 2, 2 * (i + 1), mz0 + 5, Stairs);
    }

    // North-east room: a table, its top one voxel thick on four one-voxel legs. The
    // seed nudges it so different seeds give different (but equally valid) rooms.
    const uint32_t h = hashCoord(0, 0, 0, options.seed);
    const int tx = xa + T + 6 + int(h % 4u), tz = zb + T + 6 + int((h >> 8) % 4u);
    const int tw = 8, td = 5, legH = 6;
    b.box(tx, legH, tz, tx + tw, legH + 1, tz + td, Wood);
    for (int cx : {tx, tx + tw - 1})
        for (int cz : {tz, tz + td - 1}) b.box(cx, 0, cz, cx + 1, legH, cz + 1, Wood);

    return grid;
}

}  // namespace grotto::voxel
