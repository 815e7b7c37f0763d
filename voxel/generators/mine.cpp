// mine: caves lit from within. A block of rock S x 40 x S, grass on top, holds
// four halls joined in a ring by tunnels, all with a flat floor at y = 4 and
// walls roughened by noise that only ever widens them (so what the layout says
// is open stays open), plus the caves' worm tunnels. The layout is fixed in
// voxels (it needs S >= 64; smaller sizes cut it at the block's sides):
//   - the shaft hall at x = z = -18, under a shaft open to the sky: a vertical
//     one (radius 3.5) and one slanted along the default sun (radius 4.5), both
//     from the floor at (-18, 4, -18), so the sun reaches that floor;
//   - the lava hall at (18, -18): a pool of lava, ellipse 6 x 5 voxels, one
//     below the floor (its voxels at y = 2, air at y = 3);
//   - the crystal hall at (18, 18): three clusters of crystal spikes, 1 to 4 high;
//   - the torch hall at (-18, 18): torches (a flame voxel on a wooden post three
//     high) at kTorches, three in the hall and one in each tunnel beside it.
// The seed moves the rough walls, the worm tunnels and the spikes' heights.
#include "voxel/generators/leaf_grid.h"
#include "voxel/generators/noise.h"
#include "voxel/mkworld.h"

#include "grotto/settings.h"

#include <algorithm>
#include <array>
#include <cmath>

namespace grotto::voxel {
namespace {

namespace mine {  // names of its own: the generators share one unity build (caves has a kTop too)

enum Material : int32_t { Rock = 1, Dirt = 2, Grass = 3, Wood = 4, Torch = 5, Crystal = 6, Lava = 7 };

constexpr int kTop = 40;          // the block's height; grass at y = kTop - 1
constexpr int kFloor = 4;         // the first open row of every hall and tunnel
constexpr float kRough = 0.45f;   // how far noise widens the walls, as a fraction of a shape's size
constexpr int kPost = 3;          // a torch's post height; its flame sits on top

struct Hall {
    float x, z, radius, height;
};
constexpr std::array<Hall, 4> kHalls = {{{-18, -18, 9, 9}, {18, -18, 10, 9}, {18, 18, 9, 9}, {-18, 18, 9, 8}}};
constexpr float kTunnelHalfWidth = 3.5f, kTunnelHeight = 7.0f;

struct Column {
    int x, z;
};
constexpr std::array<Column, 5> kTorches = {{{-22, 14}, {-14, 22}, {-22, 22}, {-20, 0}, {0, 20}}};
constexpr std::array<Column, 3> kCrystalClusters = {{{13, 14}, {23, 16}, {17, 24}}};
constexpr std::array<Column, 7> kSpikes = {{{0, 0}, {1, 0}, {0, 1}, {-1, 0}, {0, -1}, {1, 1}, {-1, -1}}};
constexpr Column kShaft{-18, -18};
constexpr float kShaftRadius = 3.5f, kSunShaftRadius = 4.5f;
constexpr Column kLava{18, -18};
constexpr float kLavaX = 6.0f, kLavaZ = 5.0f;

float sq(float v) { return v * v; }

// How far inside the halls and tunnels (x, y, z) is: < 1 inside, by the shape it is deepest in.
float layoutDepth(float x, float y, float z) {
    const float up = y - float(kFloor);
    float e = 1e9f;
    for (const Hall& h : kHalls)
        e = std::min(e, (sq(x - h.x) + sq(z - h.z)) / sq(h.radius) + sq(up / h.height));
    for (size_t i = 0; i < kHalls.size(); ++i) {  // the ring: each hall to the next
        const Hall& a = kHalls[i];
        const Hall& b = kHalls[(i + 1) % kHalls.size()];
        const float dx = b.x - a.x, dz = b.z - a.z;
        const float t = std::clamp(((x - a.x) * dx + (z - a.z) * dz) / (dx * dx + dz * dz), 0.0f, 1.0f);
        const float across = sq(x - a.x - t * dx) + sq(z - a.z - t * dz);
        e = std::min(e, across / sq(kTunnelHalfWidth) + sq(up / kTunnelHeight));
    }
    return e;
}

bool inShaft(float x, float y, float z) {
    if (sq(x - float(kShaft.x)) + sq(z - float(kShaft.z)) < sq(kShaftRadius)) return true;
    const glm::vec3 sun = Lighting{}.sunDirection;  // the documented default
    const float up = y - float(kFloor);
    return sq(x - float(kShaft.x) - up * sun.x / sun.y) + sq(z - float(kShaft.z) - up * sun.z / sun.y) <
           sq(kSunShaftRadius);
}

class Mine {
public:
    Mine(uint32_t seed, int lo, int size) : seed_(seed), lo_(lo), hi_(lo + size) {}

    // The material at a voxel, 0 for air.
    int32_t at(int x, int y, int z) const {
        if (x < lo_ || x >= hi_ || z < lo_ || z >= hi_ || y < 0 || y >= kTop) return 0;
        if (const int32_t f = feature(x, y, z); f >= 0) return f;
        if (y >= kFloor && open(float(x), float(y), float(z))) return 0;
        if (y == kTop - 1) return Grass;
        return y >= kTop - 4 ? Dirt : Rock;
    }

    std::unique_ptr<MaterialLeaf> leaf(const openvdb::Coord& origin) const {
        auto out = std::make_unique<MaterialLeaf>(origin, 0, false);
        bool any = false;
        for (int i = 0; i < kLeafDim; ++i)
            for (int j = 0; j < kLeafDim; ++j)
                for (int k = 0; k < kLeafDim; ++k) {
                    const openvdb::Coord c = origin.offsetBy(i, j, k);
                    if (const int32_t m = at(c.x(), c.y(), c.z()); m != 0) {
                        out->setValueOn(c, m);
                        any = true;
                    }
                }
        return any ? std::move(out) : nullptr;
    }

private:
    // What the layout places (-1 where it places nothing): the lava basin, posts,
    // flames and crystal spikes win over rock and over open space alike.
    int32_t feature(int x, int y, int z) const {
        if (y == kFloor - 2 || y == kFloor - 1) {
            if (sq(float(x - kLava.x) / kLavaX) + sq(float(z - kLava.z) / kLavaZ) < 1.0f)
                return y == kFloor - 2 ? Lava : 0;
        }
        if (y < kFloor) return -1;
        for (const Column& t : kTorches)
            if (x == t.x && z == t.z && y < kFloor + kPost + 1) return y < kFloor + kPost ? Wood : Torch;
        for (const Column& c : kCrystalClusters)
            for (const Column& s : kSpikes)
                if (x == c.x + s.x && z == c.z + s.z) return y < kFloor + spikeHeight(x, z) ? Crystal : -1;
        return -1;
    }

    int spikeHeight(int x, int z) const { return 1 + int(hashUnit(x, 0, z, seed_ + 7u) * 4.0f); }

    bool open(float x, float y, float z) const {
        const float e = layoutDepth(x, y, z);
        if (e < 1.0f || inShaft(x, y, z)) return true;
        if (e < 1.0f + kRough) {  // rough walls: noise in [-1, 1] moves the wall out by up to kRough
            const float n = std::clamp(fbm(x / 10.0f, y / 10.0f, z / 10.0f, seed_ + 5u, 3), -1.0f, 1.0f);
            if (e < 1.0f + kRough * 0.5f * (n + 1.0f)) return true;
        }
        // The caves' worm tunnels, kept off the block's sides and its roof so the
        // sky comes in through the shaft alone.
        const bool inside = x >= float(lo_ + 6) && x < float(hi_ - 6) && z >= float(lo_ + 6) && z < float(hi_ - 6);
        return inside && y < float(kTop - 10) && inWormTunnel(x, y, z, seed_);
    }

    uint32_t seed_;
    int lo_, hi_;
};

}  // namespace mine
}  // namespace

openvdb::GridBase::Ptr generateMine(const GeneratorOptions& options) {
    const int S = options.size, lo = -S / 2, hi = lo + S;
    const mine::Mine mine(options.seed, lo, S);
    std::vector<openvdb::Coord> origins;
    for (int z0 = floorTo(lo, kLeafDim); z0 < hi; z0 += kLeafDim)
        for (int x0 = floorTo(lo, kLeafDim); x0 < hi; x0 += kLeafDim)
            for (int y0 = 0; y0 < mine::kTop; y0 += kLeafDim) origins.emplace_back(x0, y0, z0);
    auto grid = gridFromLeaves(origins, [&](const openvdb::Coord& o) { return mine.leaf(o); }, options.voxelSize);
    grid->tree().prune();  // the solid rock inside: whole leaves of one material become tiles
    return grid;
}

}  // namespace grotto::voxel
