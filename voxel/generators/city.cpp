// city: a large, cheap world. An asphalt ground slab and solid box buildings are
// filled with Grid::fill, which stores whole 8^3 (and larger) blocks as active
// tiles, so memory follows the surfaces rather than the volume.
#include "voxel/generators/noise.h"
#include "voxel/mkworld.h"

#include "voxel/openvdb_grids.h"

#include <algorithm>

namespace grotto::voxel {
namespace {

enum CityMaterial : int32_t { Asphalt = 1, Pavement = 2, FirstFacade = 3, FacadeCount = 4 };

// Every wall sits on a multiple of 8, a leaf boundary, so Grid::fill turns whole
// building sides into tiles; only roofs and the pavement layer need leaf voxels.
constexpr int kPitch = 80;   // street grid spacing
constexpr int kStreet = 16;  // street width
constexpr int kKerb = 8;     // pavement between the street and the buildings

struct Rng {  // a hash-driven sequence per city block, independent of visiting order
    int bx, bz;
    uint32_t seed;
    uint32_t n = 0;
    float next() { return hashUnit(bx, bz, int32_t(n++), seed); }
    int range(int a, int b) { return a + std::min(b - a, int(next() * float(b - a + 1))); }
};

void solid(openvdb::Int32Grid& grid, int x0, int y0, int z0, int x1, int y1, int z1, int32_t m) {
    if (x0 < x1 && y0 < y1 && z0 < z1)
        grid.fill(openvdb::CoordBBox({x0, y0, z0}, {x1 - 1, y1 - 1, z1 - 1}), m, true);
}

// A box building on the pavement (which is y = 0); tall ones get a narrower top tier.
void building(openvdb::Int32Grid& grid, Rng& rng, int x0, int z0, int x1, int z1, int height) {
    const int32_t facade = FirstFacade + rng.range(0, FacadeCount - 1);
    const int w = std::min(x1 - x0, z1 - z0);
    if (height > 60 && w >= 32) {
        const int base = height * 3 / 5, step = 8 * rng.range(1, w / 24);
        solid(grid, x0, 1, z0, x1, 1 + base, z1, facade);
        solid(grid, x0 + step, 1 + base, z0 + step, x1 - step, 1 + height, z1 - step, facade);
    } else {
        solid(grid, x0, 1, z0, x1, 1 + height, z1, facade);
    }
}

// Heights 8..maxH, most of them low: u^2 skews towards the bottom.
int pickHeight(Rng& rng, int maxH) {
    const float u = rng.next();
    return 8 + int(u * u * float(maxH - 8));
}

void cityBlock(openvdb::Int32Grid& grid, Rng& rng, int x0, int z0, int size) {
    solid(grid, x0, 0, z0, x0 + size, 1, z0 + size, Pavement);
    const int a = kKerb, b = size - kKerb;  // buildable range inside the block
    const int split = a + 16, gap = 8;      // lots of 16 and (b - split - gap), an alley between
    switch (rng.range(0, 2)) {
        case 0: {  // one tower, sometimes set back from the kerb
            const int m = 8 * rng.range(0, 1);
            building(grid, rng, x0 + a + m, z0 + a + m, x0 + b - m, z0 + b - m,
                     pickHeight(rng, 120));
            break;
        }
        case 1:  // four lots
            for (int i = 0; i < 2; ++i)
                for (int j = 0; j < 2; ++j) {
                    const int lx0 = i == 0 ? a : split + gap, lx1 = i == 0 ? split : b;
                    const int lz0 = j == 0 ? a : split + gap, lz1 = j == 0 ? split : b;
                    building(grid, rng, x0 + lx0, z0 + lz0, x0 + lx1, z0 + lz1,
                             pickHeight(rng, 60));
                }
            break;
        default: {  // two slabs split along x or z
            const bool alongX = rng.next() < 0.5f;
            for (int i = 0; i < 2; ++i) {
                const int s0 = i == 0 ? a : split + gap, s1 = i == 0 ? split : b;
                if (alongX)
                    building(grid, rng, x0 + s0, z0 + a, x0 + s1, z0 + b, pickHeight(rng, 90));
                else
                    building(grid, rng, x0 + a, z0 + s0, x0 + b, z0 + s1, pickHeight(rng, 90));
            }
        }
    }
}

}  // namespace

openvdb::GridBase::Ptr generateCity(const GeneratorOptions& options) {
    auto grid = openvdb::Int32Grid::create(0);
    grid->setTransform(openvdb::math::Transform::createLinearTransform(options.voxelSize));
    grid->setName("material");

    const int S = options.size;
    const int lo = -S / 2;
    solid(*grid, lo, -8, lo, lo + S, 0, lo + S, Asphalt);  // 8 thick: one layer of tiles

    // Only whole blocks fit, centred; the streets run between them.
    const int blocks = S / kPitch, blockSize = kPitch - kStreet;
    const int first = lo + (S - blocks * kPitch + kStreet) / 2;
    const int origin = first - ((first % 8) + 8) % 8;  // round down to a multiple of 8
    for (int bz = 0; bz < blocks; ++bz)
        for (int bx = 0; bx < blocks; ++bx) {
            Rng rng{bx, bz, options.seed};
            cityBlock(*grid, rng, origin + bx * kPitch, origin + bz * kPitch, blockSize);
        }
    return grid;
}

}  // namespace grotto::voxel
