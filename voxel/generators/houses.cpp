// houses: interiors lit only through their openings. On open ground stand three
// one-room houses with walls and roofs one voxel thick: the first closed on every
// side, the second with one window toward the sun, the third with a doorway (x 15
// and 16, y 0 to 4, z 3) that the world file's door object swings shut. Sky light and sunlight reach a room
// only through its openings, so the first stays dark, the second gets a patch of
// sun and some sky, and the third is lit while its door stands open. The houses
// keep their sizes in voxels; the ground grows with options.size. With
// options.lamps each room gets a lamp, 2 x 1 x 2 voxels of material 6 under the
// middle of its ceiling (interior x0+5..x0+6, y 7, z0+5..z0+6), for a night.
#include "voxel/mkworld.h"

#include "voxel/openvdb_grids.h"

#include <algorithm>

namespace grotto::voxel {
namespace {

namespace house {  // names of its own: rooms.cpp has a Wall and a Stone too
enum Material : int32_t { Ground = 1, Wall = 2, Roof = 3, Stone = 5, Lamp = 6 };
}  // namespace house

}  // namespace

openvdb::GridBase::Ptr generateHouses(const GeneratorOptions& options) {
    auto grid = openvdb::Int32Grid::create(0);
    grid->setTransform(openvdb::math::Transform::createLinearTransform(options.voxelSize));
    const int S = options.size;
    const int lo = -S / 2, hi = lo + S;
    // Half-open box, clipped to the footprint so small sizes stay valid.
    auto box = [&](int x0, int y0, int z0, int x1, int y1, int z1, int32_t material) {
        x0 = std::max(x0, lo), z0 = std::max(z0, lo);
        x1 = std::min(x1, hi), z1 = std::min(z1, hi);
        if (x0 >= x1 || y0 >= y1 || z0 >= z1) return;
        const openvdb::CoordBBox b({x0, y0, z0}, {x1 - 1, y1 - 1, z1 - 1});
        if (material == 0)
            grid->fill(b, 0, /*active=*/false);
        else
            grid->fill(b, material, /*active=*/true);
    };
    box(lo, -2, lo, hi, 0, hi, house::Ground);

    // A room 10 x 7 x 10 inside, walls 1 thick on the ground, a roof above, its
    // outer corner at (x0, 0, z0); the interior is x0+1 .. x0+10, y 0 .. 6, z0+1 .. z0+10.
    auto house = [&](int x0, int z0) {
        box(x0, 0, z0, x0 + 12, 8, z0 + 12, house::Wall);
        box(x0, 8, z0, x0 + 12, 9, z0 + 12, house::Roof);
        box(x0 + 1, 0, z0 + 1, x0 + 11, 8, z0 + 11, 0);
        box(x0 + 1, -1, z0 + 1, x0 + 11, 0, z0 + 11, house::Stone);  // a stone floor inside
        if (options.lamps) box(x0 + 5, 7, z0 + 5, x0 + 7, 8, z0 + 7, house::Lamp);
    };
    const int z0 = -8;
    house(-22, z0);                              // closed
    house(-6, z0);                               // a window in its +X wall, toward the sun
    box(-6 + 11, 3, z0 + 4, -6 + 12, 6, z0 + 8, 0);
    house(10, z0);                               // a doorway in its +Z wall, 2 wide and 5 high
    box(10 + 5, 0, z0 + 11, 10 + 7, 5, z0 + 12, 0);
    return grid;
}

}  // namespace grotto::voxel
