// Meshing: one quad per exposed face without merging; greedy quads cover exactly
// the same unit faces, without overlap, in fewer quads; and quads meet corner to
// corner (no corner of one lies inside the edge of another, within a level and
// across chunks drawn at any levels), so rasterising them leaves no pinholes.
#include "voxel/live_mesh.h"
#include "voxel/ply_export.h"
#include "voxel/solid.h"
#include "tests/test_util.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <numeric>
#include <random>
#include <set>
#include <tuple>
#include <unordered_set>

namespace grotto::voxel {
namespace {

using Face = std::tuple<int, int, int, int>;  // voxel x, y, z and face 0..5
// Faces sorted, each once: sorted vectors, not sets (the sanitizers' unoptimised
// test code fills and compares them several times faster).
using FaceSet = std::vector<Face>;

// Brute force: every face of a solid voxel whose neighbour is empty.
FaceSet exposedFaceSet(const World& w) {
    FaceSet faces;
    const IndexBox b = w.bounds();
    for (int x = b.min.x; x <= b.max.x; ++x)
        for (int y = b.min.y; y <= b.max.y; ++y)
            for (int z = b.min.z; z <= b.max.z; ++z) {
                if (!w.solid({x, y, z})) continue;
                for (int f = 0; f < 6; ++f) {
                    glm::ivec3 n(x, y, z);
                    n[f / 2] += (f % 2 == 0) ? 1 : -1;
                    if (!w.solid(n)) faces.push_back({x, y, z, f});
                }
            }
    std::sort(faces.begin(), faces.end());  // each face was pushed once
    return faces;
}

// The area of the convex polygon p (in a face's u, v) within the unit square at (u, v).
double areaInSquare(std::vector<glm::dvec2> p, int u, int v) {
    const double lo[2] = {double(u), double(v)}, hi[2] = {double(u + 1), double(v + 1)};
    for (int side = 0; side < 4 && !p.empty(); ++side) {  // Sutherland-Hodgman against each side
        const int a = side / 2;
        const bool upper = side % 2 == 1;
        auto inside = [&](glm::dvec2 q) { return upper ? q[a] <= hi[a] : q[a] >= lo[a]; };
        std::vector<glm::dvec2> out;
        for (size_t i = 0; i < p.size(); ++i) {
            const glm::dvec2 c = p[i], n = p[(i + 1) % p.size()];
            if (inside(c)) out.push_back(c);
            if (inside(c) != inside(n)) {
                const double limit = upper ? hi[a] : lo[a];
                out.push_back(c + (n - c) * ((limit - c[a]) / (n[a] - c[a])));
            }
        }
        p = std::move(out);
    }
    double twice = 0.0;
    for (size_t i = 0; i < p.size(); ++i) twice += p[i].x * p[(i + 1) % p.size()].y - p[i].y * p[(i + 1) % p.size()].x;
    return 0.5 * twice;
}

// The unit faces a mesh covers; counts overlaps and faces covered only in part.
FaceSet meshFaces(const Mesh& mesh, size_t& overlaps, size_t* partial = nullptr) {
    std::vector<std::pair<Face, double>> pieces;  // each unit face a quad covers, and how much
    for (const MeshChunk& c : mesh.chunks)
        for (uint32_t i = 0; i < c.quadCount(); ++i) {
            const MeshQuad& q = mesh.quads[c.firstQuad + i];
            const uint32_t f = q.face();
            const int a = int(gpu::faceAxis(f)), ua = int(gpu::faceUAxis(f)), va = int(gpu::faceVAxis(f));
            const std::array<glm::ivec3, 4> k = mesh.corners(c, q);
            std::vector<glm::dvec2> poly;
            glm::ivec2 lo(INT32_MAX), hi(INT32_MIN);
            for (const glm::ivec3& p : k) {
                if (!poly.empty() && poly.back() == glm::dvec2(p[ua], p[va])) continue;
                poly.push_back({p[ua], p[va]});
                lo = glm::min(lo, glm::ivec2(p[ua], p[va]));
                hi = glm::max(hi, glm::ivec2(p[ua], p[va]));
            }
            for (int u = lo.x; u < hi.x; ++u)
                for (int v = lo.y; v < hi.y; ++v) {
                    const double inSquare = areaInSquare(poly, u, v);
                    if (inSquare <= 1e-12) continue;
                    glm::ivec3 voxel;
                    voxel[a] = k[0][a] - (gpu::facePositive(f) ? 1 : 0);
                    voxel[ua] = u;
                    voxel[va] = v;
                    pieces.push_back({{voxel.x, voxel.y, voxel.z, int(f)}, inSquare});
                }
        }
    std::sort(pieces.begin(), pieces.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
    FaceSet faces;
    overlaps = 0;
    size_t parts = 0;
    for (size_t i = 0; i < pieces.size();) {
        double covered = 0.0;
        size_t j = i;
        for (; j < pieces.size() && pieces[j].first == pieces[i].first; ++j) covered += pieces[j].second;
        faces.push_back(pieces[i].first);
        overlaps += covered > 1.0 + 1e-9;
        parts += covered < 1.0 - 1e-9;
        i = j;
    }
    if (partial) *partial = parts;
    return faces;
}

// Random voxels over [lo, hi), and an 8^3 active tile.
World randomWorld(uint32_t seed, double fill, glm::ivec3 lo = {-20, -5, -40}, glm::ivec3 hi = {45, 30, 10}) {
    openvdb::initialize();
    std::mt19937 rng(seed);
    std::bernoulli_distribution on(fill);
    auto grid = openvdb::MaskGrid::create();
    auto acc = grid->getAccessor();
    for (int x = lo.x; x < hi.x; ++x)
        for (int y = lo.y; y < hi.y; ++y)
            for (int z = lo.z; z < hi.z; ++z)
                if (on(rng)) acc.setValueOn(openvdb::Coord(x, y, z));
    grid->tree().addTile(1, openvdb::Coord(64, 0, 0), true, true);  // an 8^3 active tile
    WorldDesc d;
    d.materials = defaultMaterials();
    return makeWorld(grid, d);
}

TEST(Mesher, OneQuadPerExposedFace) {
    const uint32_t seeds[] = {1u, 3u, 2u};
    for (int k = 0; k < grotto::test::underSanitizers(3, 2); ++k) {  // a sparse and the dense world under the sanitizers
        const uint32_t seed = seeds[k];
        const World w = randomWorld(seed, seed == 3 ? 0.7 : 0.25);
        const FaceSet expected = exposedFaceSet(w);
        const Mesh mesh = w.mesh({.greedy = false});
        EXPECT_EQ(mesh.quads.size(), expected.size()) << "seed " << seed;
        size_t overlaps = 0;
        EXPECT_EQ(meshFaces(mesh, overlaps), expected);
        EXPECT_EQ(overlaps, 0u);
    }
}

TEST(Mesher, GreedyCoversTheSameFacesWithFewerQuads) {
    const uint32_t seeds[] = {4u, 5u};
    for (int k = 0; k < grotto::test::underSanitizers(2, 1); ++k) {  // seed 4 only under the sanitizers
        const uint32_t seed = seeds[k];
        const World w = randomWorld(seed, 0.6);
        const FaceSet expected = exposedFaceSet(w);
        const Mesh mesh = w.mesh({.greedy = true});
        size_t overlaps = 0, partial = 0;
        EXPECT_EQ(meshFaces(mesh, overlaps, &partial), expected) << "seed " << seed;
        EXPECT_EQ(overlaps, 0u);
        EXPECT_EQ(partial, 0u);
        EXPECT_LT(mesh.quads.size(), expected.size());
    }
}

TEST(Mesher, ChunkQuadsAreSortedByFace) {
    const Mesh mesh = randomWorld(9, 0.4).mesh();
    for (const MeshChunk& c : mesh.chunks) {
        uint32_t q = c.firstQuad;
        for (uint32_t f = 0; f < 6; ++f)
            for (uint32_t i = 0; i < c.faceCount[f]; ++i, ++q) ASSERT_EQ(mesh.quads[q].face(), f);
    }
}

TEST(Mesher, PlyHoldsExactlyTheQuads) {
    const Mesh mesh = randomWorld(11, 0.3).mesh();
    grotto::test::ScratchDir dir;
    writePly(mesh, dir / "m.ply");
    std::ifstream in(dir / "m.ply", std::ios::binary);
    std::string line;
    size_t vertices = 0, faces = 0;
    while (std::getline(in, line) && line != "end_header") {
        std::sscanf(line.c_str(), "element vertex %zu", &vertices);
        std::sscanf(line.c_str(), "element face %zu", &faces);
    }
    EXPECT_EQ(faces, mesh.quads.size());
    EXPECT_EQ(vertices, 4 * mesh.quads.size());
    EXPECT_TRUE(std::any_of(mesh.quads.begin(), mesh.quads.end(), [](const MeshQuad& q) {
        return q.corners[2] == q.corners[3];  // triangles among them (written with three corners)
    }));
    // First vertex of the first quad, in world units.
    float xyz[3];
    in.read(reinterpret_cast<char*>(xyz), sizeof xyz);
    const glm::ivec3 v = mesh.corners(mesh.chunks[0], mesh.quads[0])[0];
    EXPECT_FLOAT_EQ(xyz[0], float(mesh.origin.x + v.x * mesh.voxelSize));
    EXPECT_FLOAT_EQ(xyz[2], float(mesh.origin.z + v.z * mesh.voxelSize));
}

// Corners of quads lying strictly inside an edge of another quad along which the
// first quad has an edge too (a T-junction: rasterising the two leaves pinholes
// along that edge), within each level and between chunks drawn at different
// levels. An edge that a quad of its chunk and face shares end to end (inside a
// rectangle, or between two) has surface on both sides and cannot open; quads of
// opposite faces (back to back in one plane, where coarse cells grow into each
// other) are never seen together. `levels[k]` holds, per chunk, level k's quads
// in world voxel coordinates.
struct Junctions {
    size_t edges = 0, found = 0;
};
struct WorldQuad {
    std::array<glm::ivec3, 4> corners;
    uint32_t face;
};
using LevelQuads = std::vector<std::vector<WorldQuad>>;  // per chunk

Junctions tJunctions(const std::vector<glm::ivec3>& origins, const std::vector<LevelQuads>& levels) {
    auto key = [](glm::ivec3 p) {
        return (uint64_t(uint32_t(p.x) & 0x1fffff) << 42) | (uint64_t(uint32_t(p.y) & 0x1fffff) << 21) |
               uint64_t(uint32_t(p.z) & 0x1fffff);
    };
    auto unit = [](glm::ivec3 d) {
        const int g = std::gcd(std::gcd(std::abs(d.x), std::abs(d.y)), std::abs(d.z));
        return d / g;
    };
    Junctions j;
    for (size_t la = 0; la < levels.size(); ++la)
        for (size_t lb = 0; lb < levels.size(); ++lb)
            for (size_t cb = 0; cb < origins.size(); ++cb) {
                // The corners of chunk cb's neighbours (and its own, at its own level),
                // each with the directions of the edges leaving it, and its quad's face.
                struct Leaving {
                    glm::ivec3 direction;
                    uint32_t face;
                };
                std::unordered_multimap<uint64_t, Leaving> leaving;
                for (size_t ca = 0; ca < origins.size(); ++ca) {
                    if ((la != lb && ca == cb) ||
                        glm::any(glm::greaterThan(glm::abs(origins[ca] - origins[cb]), glm::ivec3(int(GROTTO_CHUNK_SIZE)))))
                        continue;
                    for (const WorldQuad& q : levels[la][ca])
                        for (int e = 0; e < 4; ++e) {
                            const glm::ivec3 a = q.corners[size_t(e)], b = q.corners[size_t(e + 1) % 4];
                            if (a == b) continue;
                            leaving.insert({key(a), {unit(b - a), q.face}});
                            leaving.insert({key(b), {unit(a - b), q.face}});
                        }
                }
                std::set<std::tuple<uint64_t, uint64_t, uint32_t>> shared;  // edges, one way, with their face
                for (const WorldQuad& q : levels[lb][cb])
                    for (int e = 0; e < 4; ++e)
                        shared.insert({key(q.corners[size_t(e)]), key(q.corners[size_t(e + 1) % 4]), q.face});
                for (const WorldQuad& q : levels[lb][cb])
                    for (int e = 0; e < 4; ++e) {
                        const glm::ivec3 a = q.corners[size_t(e)], b = q.corners[size_t(e + 1) % 4];
                        if (a == b || shared.count({key(b), key(a), q.face})) continue;
                        ++j.edges;
                        const glm::ivec3 d = unit(b - a);
                        for (glm::ivec3 p = a + d; p != b; p += d) {
                            const auto [first, last] = leaving.equal_range(key(p));
                            for (auto it = first; it != last; ++it)
                                j.found += (it->second.direction == d || it->second.direction == -d) &&
                                           (it->second.face == q.face || it->second.face / 2 != q.face / 2);
                        }
                    }
            }
    return j;
}

TEST(Mesher, QuadsMeetCornerToCornerWithinAndAcrossChunksAtEveryLevel) {
    // Under the sanitizers only the denser world, whose rectangles are cut more.
    const uint32_t seeds[] = {22u, 21u};
    for (int k = 0; k < grotto::test::underSanitizers(2, 1); ++k) {
        const uint32_t seed = seeds[k];  // 2 x 2 x 2 chunks around the origin, and the tile's
        const World w = randomWorld(seed, seed == 21 ? 0.3 : 0.55, {-14, -9, -12}, {17, 11, 15});
        const LiveMesh live(w, {.coarseLevels = kMaxCoarseLevels});
        std::vector<glm::ivec3> origins;
        std::vector<LevelQuads> levels(1 + kMaxCoarseLevels);
        size_t rects = 0, quads = 0;
        for (const auto& [origin, c] : live.chunks()) {
            origins.push_back(origin);
            rects += c.rects.size();
            quads += c.quads.size();
            for (size_t k = 0; k < levels.size(); ++k) {
                levels[k].emplace_back();
                if (k > c.coarser.size()) continue;
                for (const MeshQuad& q : k == 0 ? c.quads : c.coarser[k - 1].quads)
                    levels[k].back().push_back({{origin + q.corner(0), origin + q.corner(1), origin + q.corner(2),
                                                 origin + q.corner(3)}, q.face()});
            }
        }
        const Junctions j = tJunctions(origins, levels);
        std::printf("[ measured ] seed %u: %zu chunks, %zu greedy rectangles cut into %zu quads; %zu edges, "
                    "%zu corners inside another quad's edge\n",
                    seed, origins.size(), rects, quads, j.edges, j.found);
        EXPECT_GE(origins.size(), 9u);
        EXPECT_GT(quads, rects);  // there were junctions to resolve
        EXPECT_EQ(j.found, 0u) << "seed " << seed;
    }
}

}  // namespace
}  // namespace grotto::voxel
