// Meshing: one quad per exposed face without merging; greedy quads cover exactly
// the same unit faces, without overlap, in fewer quads.
#include "voxel/ply_export.h"
#include "voxel/solid.h"
#include "tests/test_util.h"

#include <gtest/gtest.h>

#include <fstream>
#include <random>
#include <set>
#include <tuple>

namespace grotto::voxel {
namespace {

using Face = std::tuple<int, int, int, int>;  // voxel x, y, z and face 0..5

// Brute force: every face of a solid voxel whose neighbour is empty.
std::set<Face> exposedFaces(const World& w) {
    std::set<Face> faces;
    const IndexBox b = w.bounds();
    for (int x = b.min.x; x <= b.max.x; ++x)
        for (int y = b.min.y; y <= b.max.y; ++y)
            for (int z = b.min.z; z <= b.max.z; ++z) {
                if (!w.solid({x, y, z})) continue;
                for (int f = 0; f < 6; ++f) {
                    glm::ivec3 n(x, y, z);
                    n[f / 2] += (f % 2 == 0) ? 1 : -1;
                    if (!w.solid(n)) faces.insert({x, y, z, f});
                }
            }
    return faces;
}

// The unit faces a mesh covers; counts overlaps.
std::set<Face> meshFaces(const Mesh& mesh, size_t& overlaps) {
    std::set<Face> faces;
    overlaps = 0;
    for (const MeshChunk& c : mesh.chunks)
        for (uint32_t i = 0; i < c.quadCount(); ++i) {
            const gpu::PackedQuad q = mesh.quads[c.firstQuad + i];
            const uint32_t f = gpu::quadFace(q.bits);
            glm::ivec3 v0 = c.origin;
            for (uint32_t a = 0; a < 3; ++a) v0[a] += int(gpu::quadCoord(q.bits, a));
            for (uint32_t u = 0; u < gpu::quadWidth(q.bits); ++u)
                for (uint32_t v = 0; v < gpu::quadHeight(q.bits); ++v) {
                    glm::ivec3 p = v0;
                    p[gpu::faceUAxis(f)] += int(u);
                    p[gpu::faceVAxis(f)] += int(v);
                    if (!faces.insert({p.x, p.y, p.z, int(f)}).second) ++overlaps;
                }
        }
    return faces;
}

World randomWorld(uint32_t seed, double fill) {
    openvdb::initialize();
    std::mt19937 rng(seed);
    std::bernoulli_distribution on(fill);
    auto grid = openvdb::MaskGrid::create();
    auto acc = grid->getAccessor();
    for (int x = -20; x < 45; ++x)
        for (int y = -5; y < 30; ++y)
            for (int z = -40; z < 10; ++z)
                if (on(rng)) acc.setValueOn(openvdb::Coord(x, y, z));
    grid->tree().addTile(1, openvdb::Coord(64, 0, 0), true, true);  // an 8^3 active tile
    WorldDesc d;
    d.materials = defaultMaterials();
    return makeWorld(grid, d);
}

TEST(Mesher, OneQuadPerExposedFace) {
    for (uint32_t seed : {1u, 2u, 3u}) {
        const World w = randomWorld(seed, seed == 3 ? 0.7 : 0.25);
        const std::set<Face> expected = exposedFaces(w);
        const Mesh mesh = w.mesh({.greedy = false});
        EXPECT_EQ(mesh.quads.size(), expected.size()) << "seed " << seed;
        size_t overlaps = 0;
        EXPECT_EQ(meshFaces(mesh, overlaps), expected);
        EXPECT_EQ(overlaps, 0u);
    }
}

TEST(Mesher, GreedyCoversTheSameFacesWithFewerQuads) {
    for (uint32_t seed : {4u, 5u}) {
        const World w = randomWorld(seed, 0.6);
        const std::set<Face> expected = exposedFaces(w);
        const Mesh mesh = w.mesh({.greedy = true});
        size_t overlaps = 0;
        EXPECT_EQ(meshFaces(mesh, overlaps), expected) << "seed " << seed;
        EXPECT_EQ(overlaps, 0u);
        EXPECT_LT(mesh.quads.size(), expected.size());
    }
}

TEST(Mesher, ChunkQuadsAreSortedByFace) {
    const Mesh mesh = randomWorld(9, 0.4).mesh();
    for (const MeshChunk& c : mesh.chunks) {
        uint32_t q = c.firstQuad;
        for (uint32_t f = 0; f < 6; ++f)
            for (uint32_t i = 0; i < c.faceCount[f]; ++i, ++q) ASSERT_EQ(gpu::quadFace(mesh.quads[q].bits), f);
    }
}

TEST(Mesher, PlyHoldsExactlyTheQuads) {
    const Mesh mesh = randomWorld(11, 0.3).mesh();
    test::ScratchDir dir;
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
    // First vertex of the first quad, in world units.
    float xyz[3];
    in.read(reinterpret_cast<char*>(xyz), sizeof xyz);
    const glm::ivec3 v = mesh.corners(mesh.chunks[0], mesh.quads[0])[0];
    EXPECT_FLOAT_EQ(xyz[0], float(mesh.origin.x + v.x * mesh.voxelSize));
    EXPECT_FLOAT_EQ(xyz[2], float(mesh.origin.z + v.z * mesh.voxelSize));
}

}  // namespace
}  // namespace grotto::voxel
