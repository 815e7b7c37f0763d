// Face culling and greedy merging per 32^3 chunk into rectangles, which LiveMesh
// welds into quads that meet corner to corner (watertight.h).
#include "grotto/error.h"
#include "voxel/live_mesh.h"
#include "voxel/solid.h"

#include <algorithm>
#include <set>

namespace grotto::voxel {
namespace {

constexpr int N = kChunkEdge;

// One level's cells of a chunk, n^3 of them, with a one-cell border from the
// neighbours: material ids, 0 = empty. Level 0 is the voxels themselves.
struct LevelCells {
    int n;
    std::vector<uint8_t> id;
    explicit LevelCells(int size) : n(size), id(size_t(size + 2) * (size + 2) * (size + 2), 0) {}
    uint8_t& at(int x, int y, int z) { return id[(size_t(x + 1) * (n + 2) + (y + 1)) * (n + 2) + (z + 1)]; }
};

void gather(const World::Impl& w, const openvdb::Coord& origin, LevelCells& out) {
    const auto& tree = w.solid->tree();
    openvdb::MaskGrid::ConstAccessor solid = w.solid->getConstAccessor();
    std::optional<openvdb::Int32Grid::ConstAccessor> mat;
    if (w.materials) mat.emplace(w.materials->getConstAccessor());
    const openvdb::Coord lo = origin.offsetBy(-1), hi = origin.offsetBy(N);
    auto materialOf = [&](const openvdb::Coord& c) {
        return uint8_t(mat ? mat->getValue(c) : w.uniformMaterial);
    };
    auto store = [&](const openvdb::Coord& c) {
        out.at(c.x() - origin.x(), c.y() - origin.y(), c.z() - origin.z()) = materialOf(c);
    };
    for (int bx = (lo.x() & ~7); bx <= hi.x(); bx += 8)
        for (int by = (lo.y() & ~7); by <= hi.y(); by += 8)
            for (int bz = (lo.z() & ~7); bz <= hi.z(); bz += 8) {
                const openvdb::Coord b(bx, by, bz);
                const openvdb::CoordBBox clip(openvdb::Coord::maxComponent(b, lo),
                                              openvdb::Coord::minComponent(b.offsetBy(7), hi));
                if (const auto* leaf = tree.probeConstLeaf(b)) {
                    for (auto it = leaf->cbeginValueOn(); it; ++it)
                        if (clip.isInside(it.getCoord())) store(it.getCoord());
                } else if (solid.isValueOn(b)) {  // inside an active tile
                    for (auto it = clip.begin(); it; ++it) store(*it);
                }
            }
}

// The next coarser level: cells of twice the size. Inside the chunk a cell is
// solid where any of its eight is (the commonest material), so the coarse surface
// only ever grows outward and never opens a hole. Across the chunk's faces a border
// cell counts as solid only where all four finer ones touching it are, which by
// induction means the neighbour's whole layer of voxels touching it: a coarse face
// on the border is dropped only where the neighbour covers it at any level, so no
// crack opens between chunks drawn at different levels.
LevelCells coarsen(LevelCells& finer) {
    LevelCells c(finer.n / 2);
    for (int x = 0; x < c.n; ++x)
        for (int y = 0; y < c.n; ++y)
            for (int z = 0; z < c.n; ++z) {
                uint8_t ids[8];
                for (int i = 0; i < 8; ++i) ids[i] = finer.at(2 * x + (i & 1), 2 * y + (i >> 1 & 1), 2 * z + (i >> 2));
                uint8_t best = 0;
                int bestCount = 0;
                for (int i = 0; i < 8; ++i) {
                    if (!ids[i]) continue;
                    const int count = int(std::count(ids, ids + 8, ids[i]));
                    if (count > bestCount || (count == bestCount && ids[i] < best)) best = ids[i], bestCount = count;
                }
                c.at(x, y, z) = best;
            }
    for (int a = 0; a < 3; ++a) {
        const int ua = (a + 1) % 3, va = (a + 2) % 3;
        for (int side = 0; side < 2; ++side)
            for (int u = 0; u < c.n; ++u)
                for (int v = 0; v < c.n; ++v) {
                    uint8_t all = 1;
                    int p[3];
                    p[a] = side ? finer.n : -1;
                    for (int i = 0; i < 4 && all; ++i) {
                        p[ua] = 2 * u + (i & 1), p[va] = 2 * v + (i >> 1);
                        all = finer.at(p[0], p[1], p[2]);
                    }
                    int q[3];
                    q[a] = side ? c.n : -1, q[ua] = u, q[va] = v;
                    c.at(q[0], q[1], q[2]) = all;
                }
    }
    return c;
}

// Greedy merge of one n x n slice of face materials into rectangles.
template <typename Emit>
void mergeSlice(uint8_t (&face)[N][N], int n, bool greedy, Emit emit) {
    for (int v = 0; v < n; ++v)
        for (int u = 0; u < n;) {
            const uint8_t m = face[u][v];
            if (!m) { ++u; continue; }
            int w = 1, h = 1;
            if (greedy) {
                while (u + w < n && face[u + w][v] == m) ++w;
                for (bool grow = true; grow && v + h < n; ) {
                    for (int k = 0; k < w; ++k)
                        if (face[u + k][v + h] != m) { grow = false; break; }
                    if (grow) ++h;
                }
            }
            for (int dv = 0; dv < h; ++dv)
                for (int du = 0; du < w; ++du) face[u + du][v + dv] = 0;
            emit(u, v, w, h, m);
            u += w;
        }
}

// Face culling and merging of one level's cells; rectangles in voxel units (a cell
// is `scale` voxels), sorted by face.
std::vector<gpu::PackedQuad> meshCells(LevelCells& cells, int scale, bool greedy) {
    std::vector<gpu::PackedQuad> quads;
    const int n = cells.n;
    uint8_t face[N][N];
    for (uint32_t f = 0; f < 6; ++f) {
        const int a = int(gpu::faceAxis(f)), ua = int(gpu::faceUAxis(f)), va = int(gpu::faceVAxis(f));
        const int step = gpu::facePositive(f) ? 1 : -1;
        // Visible +axis faces are nearer the camera the higher their slice, -axis
        // faces the lower: emit them nearest first so depth tests reject more.
        for (int i = 0; i < n; ++i) {
            const int d = step > 0 ? n - 1 - i : i;
            bool any = false;
            for (int u = 0; u < n; ++u)
                for (int v = 0; v < n; ++v) {
                    int c[3];
                    c[a] = d; c[ua] = u; c[va] = v;
                    const uint8_t m = cells.at(c[0], c[1], c[2]);
                    c[a] += step;
                    face[u][v] = (m && !cells.at(c[0], c[1], c[2])) ? m : 0;
                    any |= face[u][v] != 0;
                }
            if (!any) continue;
            mergeSlice(face, n, greedy, [&](int u, int v, int qw, int qh, uint8_t m) {
                uint32_t p[3];
                // The voxel whose face it is: a + face belongs to the cell's last layer.
                p[a] = uint32_t(step > 0 ? (d + 1) * scale - 1 : d * scale);
                p[ua] = uint32_t(u * scale); p[va] = uint32_t(v * scale);
                quads.push_back({gpu::packQuadBits(p[0], p[1], p[2], qw * scale, qh * scale, f), m});
            });
        }
    }
    return quads;
}

// A chunk with no solid voxel, or whose voxels and their neighbours are all
// solid (inside a large fill: active tiles), has no faces. Told from its bricks
// and those around it, without gathering its cells: an edit across a large
// region touches many such chunks.
bool hasNoFaces(const World::Impl& w, const openvdb::Coord& origin) {
    openvdb::MaskGrid::ConstAccessor solid = w.solid->getConstAccessor();
    bool anySolid = false, allSolid = true;
    for (int bx = -8; bx <= N && (allSolid || !anySolid); bx += 8)
        for (int by = -8; by <= N; by += 8)
            for (int bz = -8; bz <= N; bz += 8) {
                const openvdb::Coord b = origin.offsetBy(bx, by, bz);
                const auto* leaf = solid.probeConstLeaf(b);
                const bool full = leaf ? leaf->isValueMaskOn() : solid.isValueOn(b);
                const bool empty = leaf ? leaf->isEmpty() : !full;
                allSolid = allSolid && full;
                const bool own = bx >= 0 && by >= 0 && bz >= 0 && bx < N && by < N && bz < N;
                anySolid = anySolid || (own && !empty);
            }
    return !anySolid || allSolid;
}

// The one chunk mesher (rectangles only; LiveMesh welds them): World::meshChunk() is it.
MeshChunkQuads meshOneChunk(const World::Impl& w, const openvdb::Coord& origin, const MeshOptions& options) {
    MeshChunkQuads chunk;
    chunk.origin = {origin.x(), origin.y(), origin.z()};
    if (hasNoFaces(w, origin)) return chunk;
    LevelCells voxels(N);
    gather(w, origin, voxels);
    chunk.rects = meshCells(voxels, 1, options.greedy);
    const int levels = std::clamp(options.coarseLevels, 0, kMaxCoarseLevels);
    LevelCells cells = std::move(voxels);
    for (int level = 1; level <= levels && !chunk.rects.empty(); ++level) {
        cells = coarsen(cells);
        chunk.coarser.push_back({.rects = meshCells(cells, 1 << level, options.greedy)});
    }
    return chunk;
}

}  // namespace

std::array<glm::ivec3, 4> Mesh::corners(const MeshChunk& c, const MeshQuad& q) const {
    return {c.origin + q.corner(0), c.origin + q.corner(1), c.origin + q.corner(2), c.origin + q.corner(3)};
}

std::vector<glm::ivec3> World::chunkOrigins() const {
    // Every chunk touched by a leaf or an active tile.
    std::set<openvdb::Coord> origins;
    const auto& tree = impl_->solid->tree();
    auto chunkOf = [](const openvdb::Coord& c) {
        return openvdb::Coord(c.x() & ~(N - 1), c.y() & ~(N - 1), c.z() & ~(N - 1));
    };
    for (auto leaf = tree.cbeginLeaf(); leaf; ++leaf) origins.insert(chunkOf(leaf->origin()));
    for (auto it = tree.cbeginValueOn(); it; ++it) {
        if (!it.isTileValue()) continue;
        openvdb::CoordBBox box;
        it.getBoundingBox(box);
        for (int x = box.min().x(); x <= box.max().x(); x += N)
            for (int y = box.min().y(); y <= box.max().y(); y += N)
                for (int z = box.min().z(); z <= box.max().z(); z += N)
                    origins.insert(chunkOf(openvdb::Coord(x, y, z)));
    }
    std::vector<glm::ivec3> out;
    out.reserve(origins.size());
    for (const openvdb::Coord& c : origins) out.push_back({c.x(), c.y(), c.z()});
    return out;
}

Mesh World::mesh(const MeshOptions& options) const { return LiveMesh(*this, options).flatten(); }

void appendChunk(Mesh& mesh, const MeshChunkQuads& c) {
    if (c.quads.empty()) return;
    mesh.chunks.push_back({.origin = c.origin, .firstQuad = uint32_t(mesh.quads.size()), .faceCount = c.faceCount});
    mesh.quads.insert(mesh.quads.end(), c.quads.begin(), c.quads.end());
}

std::vector<glm::ivec3> World::chunksTouching(const IndexBox& changed) const {
    std::vector<glm::ivec3> out;
    if (changed.empty()) return out;
    // Grown by one: a voxel's faces are meshed by its own chunk, and whether they
    // show depends on the neighbour, which may lie in the next chunk.
    const glm::ivec3 lo = (changed.min - 1) & ~(N - 1), hi = (changed.max + 1) & ~(N - 1);
    for (int x = lo.x; x <= hi.x; x += N)
        for (int y = lo.y; y <= hi.y; y += N)
            for (int z = lo.z; z <= hi.z; z += N) out.push_back({x, y, z});
    return out;
}

MeshChunkQuads World::meshChunk(glm::ivec3 chunkOrigin, const MeshOptions& options) const {
    if (chunkOrigin != (chunkOrigin & ~(N - 1)))
        throw Error::internal("World::meshChunk", "chunk origin (" + std::to_string(chunkOrigin.x) + ", " +
                                                      std::to_string(chunkOrigin.y) + ", " + std::to_string(chunkOrigin.z) +
                                                      ") is not a multiple of the chunk size",
                              "use World::chunksTouching or World::mesh()'s chunk origins");
    return meshOneChunk(*impl_, openvdb::Coord(chunkOrigin.x, chunkOrigin.y, chunkOrigin.z), options);
}

}  // namespace grotto::voxel
