// Face culling and greedy merging per 32^3 chunk, chunks meshed in parallel.
#include "common/error.h"
#include "voxel/solid.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <set>

namespace grotto::voxel {
namespace {

constexpr int N = int(GROTTO_CHUNK_SIZE);
constexpr int P = N + 2;  // with a one-voxel border from the neighbours

// Material ids of a chunk and its border (0 = empty), from leaves and tiles.
struct ChunkVoxels {
    std::vector<uint8_t> id = std::vector<uint8_t>(P * P * P, 0);
    uint8_t& at(int x, int y, int z) { return id[(x * P + y) * P + z]; }
};

void gather(const World::Impl& w, const openvdb::Coord& origin, ChunkVoxels& out) {
    const auto& tree = w.solid->tree();
    openvdb::MaskGrid::ConstAccessor solid = w.solid->getConstAccessor();
    std::optional<openvdb::Int32Grid::ConstAccessor> mat;
    if (w.materials) mat.emplace(w.materials->getConstAccessor());
    const openvdb::Coord lo = origin.offsetBy(-1), hi = origin.offsetBy(N);
    auto materialOf = [&](const openvdb::Coord& c) {
        return uint8_t(mat ? mat->getValue(c) : w.uniformMaterial);
    };
    auto store = [&](const openvdb::Coord& c) {
        out.at(c.x() - lo.x(), c.y() - lo.y(), c.z() - lo.z()) = materialOf(c);
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

// Greedy merge of one 32x32 slice of face materials into rectangles.
template <typename Emit>
void mergeSlice(uint8_t (&face)[N][N], bool greedy, Emit emit) {
    for (int v = 0; v < N; ++v)
        for (int u = 0; u < N;) {
            const uint8_t m = face[u][v];
            if (!m) { ++u; continue; }
            int w = 1, h = 1;
            if (greedy) {
                while (u + w < N && face[u + w][v] == m) ++w;
                for (bool grow = true; grow && v + h < N; ) {
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

// The one chunk mesher: World::mesh() and World::meshChunk() both use it.
MeshChunkQuads meshOneChunk(const World::Impl& w, const openvdb::Coord& origin, bool greedy) {
    ChunkVoxels vox;
    gather(w, origin, vox);
    MeshChunkQuads chunk;
    chunk.origin = {origin.x(), origin.y(), origin.z()};
    std::vector<gpu::PackedQuad>& quads = chunk.quads;
    uint8_t face[N][N];
    for (uint32_t f = 0; f < 6; ++f) {
        const int a = int(gpu::faceAxis(f)), ua = int(gpu::faceUAxis(f)), va = int(gpu::faceVAxis(f));
        const int step = gpu::facePositive(f) ? 1 : -1;
        const size_t before = quads.size();
        // Visible +axis faces are nearer the camera the higher their slice, -axis
        // faces the lower: emit them nearest first so depth tests reject more.
        for (int i = 0; i < N; ++i) {
            const int d = step > 0 ? N - 1 - i : i;
            bool any = false;
            for (int u = 0; u < N; ++u)
                for (int v = 0; v < N; ++v) {
                    int c[3];
                    c[a] = d + 1; c[ua] = u + 1; c[va] = v + 1;
                    const uint8_t m = vox.at(c[0], c[1], c[2]);
                    c[a] += step;
                    face[u][v] = (m && !vox.at(c[0], c[1], c[2])) ? m : 0;
                    any |= face[u][v] != 0;
                }
            if (!any) continue;
            mergeSlice(face, greedy, [&](int u, int v, int qw, int qh, uint8_t m) {
                uint32_t p[3];
                p[a] = uint32_t(d); p[ua] = uint32_t(u); p[va] = uint32_t(v);
                quads.push_back({gpu::packQuadBits(p[0], p[1], p[2], qw, qh, f), m});
            });
        }
        chunk.faceCount[f] = uint32_t(quads.size() - before);
    }
    return chunk;
}

}  // namespace

std::array<glm::ivec3, 4> Mesh::corners(const MeshChunk& c, const gpu::PackedQuad& q) const {
    const uint32_t f = gpu::quadFace(q.bits);
    glm::ivec3 base = c.origin;
    for (uint32_t i = 0; i < 3; ++i) base[i] += int(gpu::quadCoord(q.bits, i));
    if (gpu::facePositive(f)) base[gpu::faceAxis(f)] += 1;
    glm::ivec3 du(0), dv(0);
    du[gpu::faceUAxis(f)] = int(gpu::quadWidth(q.bits));
    dv[gpu::faceVAxis(f)] = int(gpu::quadHeight(q.bits));
    return {base, base + du, base + du + dv, base + dv};
}

Mesh World::mesh(const MeshOptions& options) const {
    const Impl& w = *impl_;
    // Every chunk touched by a leaf or an active tile.
    std::set<openvdb::Coord> origins;
    const auto& tree = w.solid->tree();
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
    const std::vector<openvdb::Coord> list(origins.begin(), origins.end());
    std::vector<MeshChunkQuads> chunks(list.size());
    tbb::parallel_for(size_t(0), list.size(), [&](size_t i) { chunks[i] = meshOneChunk(w, list[i], options.greedy); });
    Mesh mesh;
    mesh.origin = w.origin;
    mesh.voxelSize = w.voxelSize;
    size_t total = 0;
    for (const MeshChunkQuads& c : chunks) total += c.quads.size();
    mesh.quads.reserve(total);
    for (const MeshChunkQuads& c : chunks) appendChunk(mesh, c);
    return mesh;
}

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
    return meshOneChunk(*impl_, openvdb::Coord(chunkOrigin.x, chunkOrigin.y, chunkOrigin.z), options.greedy);
}

}  // namespace grotto::voxel
