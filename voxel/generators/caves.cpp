// caves: noise terrain with overhangs and tunnels. A height field sets the ground;
// 3D fractal noise pushes the surface in and out (overhangs) and two more noise
// fields carve worm-like tunnels where both are near zero. Only a crust down to
// kCrust voxels below the height field is solid, so the world stays small.
#include "voxel/generators/leaf_grid.h"
#include "voxel/generators/noise.h"
#include "voxel/mkworld.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <vector>

namespace grotto::voxel {
namespace {

enum CaveMaterial : int32_t { Rock = 1, Dirt = 2, Grass = 3 };

using LeafT = MaterialLeaf;
constexpr int kDim = kLeafDim;

constexpr int kTop = 96;            // world height in voxels
constexpr float kCrust = 24.0f;     // solid depth below the height field
constexpr float kOverhang = 30.0f;  // how far the 3D noise moves the surface
constexpr int kDirt = 3;            // dirt layer thickness

class Terrain {
public:
    Terrain(uint32_t seed, int lo, int size) : seed_(seed), lo_(lo), size_(size) {
        heights_.resize(size_t(size) * size_t(size));
        tbb::parallel_for(0, size, [&](int j) {
            for (int i = 0; i < size; ++i) {
                const float x = float(lo + i), z = float(lo + j);
                // Broad hills plus a smaller detail layer; the y offset keeps the
                // slice off the noise lattice, where gradient noise is zero.
                const float f = fbm(x / 96.0f, 0.37f, z / 96.0f, seed_, 5);
                heights_[size_t(j) * size_t(size) + size_t(i)] = 44.0f + 64.0f * f;
            }
        });
    }

    float height(int x, int z) const {
        return heights_[size_t(z - lo_) * size_t(size_) + size_t(x - lo_)];
    }

    bool solid(int x, int y, int z) const {
        if (x < lo_ || x >= lo_ + size_ || z < lo_ || z >= lo_ + size_) return false;
        const float h = height(x, z), fy = float(y);
        if (y < 0 || y >= kTop || fy < h - kCrust || fy > h + kOverhang * 1.2f) return false;
        const float fx = float(x), fz = float(z);
        const float d = h - fy + kOverhang * fbm(fx / 32.0f, fy / 10.0f, fz / 32.0f, seed_ + 1u, 3);
        return d > 0.0f && !inWormTunnel(fx, fy, fz, seed_);
    }

    // By the solid run above a voxel: open above -> grass (near the height field;
    // deeper, a cave floor stays rock), under 1..kDirt solid voxels -> dirt, else rock.
    int32_t material(int x, int y, int z, int solidAbove) const {
        if (solidAbove == 0) return height(x, z) - float(y) < 8.0f ? Grass : Rock;
        return solidAbove <= kDirt ? Dirt : Rock;
    }

    std::unique_ptr<LeafT> leaf(const openvdb::Coord& origin) const {
        // kDirt + 1 extra rows on top: a voxel's material depends on the ones above.
        constexpr int rows = kDim + kDirt + 1;
        bool s[kDim][rows][kDim];
        bool any = false;
        for (int i = 0; i < kDim; ++i)
            for (int j = 0; j < rows; ++j)
                for (int k = 0; k < kDim; ++k) {
                    s[i][j][k] = solid(origin.x() + i, origin.y() + j, origin.z() + k);
                    any = any || (j < kDim && s[i][j][k]);
                }
        if (!any) return nullptr;
        auto out = std::make_unique<LeafT>(origin, 0, false);
        for (int i = 0; i < kDim; ++i)
            for (int k = 0; k < kDim; ++k) {
                int run = 0;  // solid voxels directly above j, up to kDirt + 1
                for (int j = rows - 1; j >= 0; --j) {
                    if (j < kDim && s[i][j][k]) {
                        const openvdb::Coord c = origin.offsetBy(i, j, k);
                        out->setValueOn(c, material(c.x(), c.y(), c.z(), run));
                    }
                    run = s[i][j][k] ? std::min(run + 1, kDirt + 1) : 0;
                }
            }
        return out;
    }

private:
    uint32_t seed_;
    int lo_, size_;
    std::vector<float> heights_;
};

}  // namespace

openvdb::GridBase::Ptr generateCaves(const GeneratorOptions& options) {
    const int S = options.size, lo = -S / 2, hi = lo + S;
    const Terrain terrain(options.seed, lo, S);

    // Leaves that can hold solid voxels: per 8x8 column, the crust's y range.
    std::vector<openvdb::Coord> origins;
    for (int z0 = floorTo(lo, kDim); z0 < hi; z0 += kDim)
        for (int x0 = floorTo(lo, kDim); x0 < hi; x0 += kDim) {
            float minH = 1e9f, maxH = -1e9f;
            for (int z = std::max(z0, lo); z < std::min(z0 + kDim, hi); ++z)
                for (int x = std::max(x0, lo); x < std::min(x0 + kDim, hi); ++x) {
                    minH = std::min(minH, terrain.height(x, z));
                    maxH = std::max(maxH, terrain.height(x, z));
                }
            const int y0 = std::max(0, floorTo(int(std::floor(minH - kCrust)), kDim));
            const int y1 = std::min(kTop, int(std::ceil(maxH + kOverhang * 1.2f)) + 1);
            for (int y = y0; y < y1; y += kDim) origins.emplace_back(x0, y, z0);
        }

    return gridFromLeaves(origins, [&](const openvdb::Coord& o) { return terrain.leaf(o); }, options.voxelSize);
}

}  // namespace grotto::voxel
