// Live worlds, large edits: whole bricks an edit covers become tiles, their mesh
// is their surface, and they match the dense model and undo exactly.
#include "grotto/error.h"
#include "tests/live_world_checks.h"
#include "tests/live_world_model.h"
#include "tests/test_util.h"
#include "voxel/generators.h"
#include "voxel/reference_ao.h"
#include "voxel/solid.h"

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include <cmath>
#include <random>

namespace grotto::voxel {
namespace {

using namespace test;  // the live-world checks, the model and the worlds

// Whole bricks an edit covers become tiles: the memory of a fill follows its
// faces, not its volume, and its undo keeps one record per brick.
TEST(LiveWorld, LargeFillsAreTilesAndUndoExactly) {
    World w = slabWorld();
    const World before = w;
    const uint64_t leavesBefore = w.impl().solid->tree().leafCount();
    const IndexBox box{{0, 64, 0}, {511, 575, 511}};  // 512^3 voxels, on brick boundaries
    const EditResult r = w.apply(Edit::fillBox(box, 2));  // a second material: the material grid too
    EXPECT_EQ(r.changed, uint64_t(512) * 512 * 512);
    EXPECT_EQ(r.voxels.min, box.min);
    EXPECT_EQ(r.voxels.max, box.max);
    for (glm::ivec3 v : {box.min, box.max, glm::ivec3(200, 300, 400)}) EXPECT_EQ(w.material(v), 2);
    EXPECT_EQ(w.material(box.min - 1), 0);
    EXPECT_EQ(w.stats().bricks, before.stats().bricks + 64 * 64 * 64);
    EXPECT_EQ(w.stats().solidVoxels, before.stats().solidVoxels + r.changed);
    // As voxels, each of its 262144 bricks would be a leaf of both grids (over 500 MiB).
    EXPECT_EQ(w.impl().solid->tree().leafCount(), leavesBefore);
    EXPECT_LT(w.stats().hostBytes, size_t(32) << 20);
    EXPECT_EQ(w.undoDepth(), 1u);
    EXPECT_EQ(w.undo().changed, r.changed);
    expectSameVoxels(w, before, {glm::ivec3(-1), glm::ivec3(16)}, "after undoing the fill");
    EXPECT_EQ(w.stats().bricks, before.stats().bricks);
    EXPECT_EQ(w.material(glm::ivec3(200, 300, 400)), 0);
}

// The chunks inside a large fill (solid with all their neighbours) and those
// beside it (empty) are told from their bricks to have no faces: the mesh is the
// fill's surface, every face of it once.
TEST(LiveWorld, MeshOfALargeFillIsItsSurface) {
    World w = slabWorld();  // the slab lies inside the fill
    // 256^3 (128^3 under the sanitizers, where meshing the surface's chunks was
    // the time: still 4 chunks a side, 18 of them inside), off brick and chunk
    // boundaries.
    const int side = grotto::test::underSanitizers(256, 128);
    const IndexBox box{{-37, -5, -3}, glm::ivec3(-37, -5, -3) + (side - 1)};
    w.apply(Edit::fillBox(box, 2));
    const Mesh mesh = w.mesh();
    uint64_t twiceArea = 0;  // of each convex quad or triangle: half the cross product of its diagonals
    for (const MeshQuad& q : mesh.quads) {
        const glm::dvec3 d = glm::abs(glm::cross(glm::dvec3(q.corner(2) - q.corner(0)), glm::dvec3(q.corner(3) - q.corner(1))));
        twiceArea += uint64_t(d.x + d.y + d.z);  // one axis is non-zero: the face's normal
    }
    EXPECT_EQ(twiceArea, 2 * 6ull * uint64_t(side) * uint64_t(side));
    size_t insideChunks = 0;  // chunks wholly inside the fill, whose bricks say they have no faces
    for (int z = -64; z <= 256; z += 32)
        for (int y = -64; y <= 256; y += 32)
            for (int x = -64; x <= 256; x += 32)
                insideChunks += glm::all(glm::greaterThan(glm::ivec3(x, y, z), box.min)) &&
                                glm::all(glm::lessThan(glm::ivec3(x, y, z) + 31, box.max));
    EXPECT_GE(insideChunks, 18u) << "the test needs chunks inside the fill";
    for (const MeshChunk& c : mesh.chunks) {  // only chunks on the surface hold quads
        const glm::ivec3 lo = c.origin, hi = c.origin + 31;
        const bool inside = glm::all(glm::greaterThan(lo, box.min)) && glm::all(glm::lessThan(hi, box.max));
        EXPECT_FALSE(inside) << c.origin.x << " " << c.origin.y << " " << c.origin.z;
    }
}

// Off brick boundaries, over solid voxels and tiles, and spheres: each changes
// exactly what a plain model of the voxels says, and undo brings back the world.
TEST(LiveWorld, FillsAndCarvesAcrossTilesMatchTheModel) {
    World w = thinWorldWithTiles();
    const World before = w;
    const IndexBox region{{-20, -4, -20}, {60, 50, 60}};
    Model model(w, region);
    const Edit edits[] = {
        Edit::fillBox({{-13, 3, -9}, {41, 37, 50}}, 2),
        Edit::carveSphere(centreOf(w, {14, 20, 20}), 13.0),
        Edit::paintBox({{-20, -4, -20}, {12, 12, 12}}, 5),
        Edit::fillSphere(centreOf(w, {30, 30, 30}), 11.0, 1),
        Edit::carveBox({{-16, 8, -16}, {31, 31, 31}}),
    };
    for (const Edit& e : edits) {
        expectSameResult(w.apply(e), model.apply(e), describe(e));
        uint64_t wrong = 0;
        Model::forEach(region, [&](glm::ivec3 v) { wrong += w.material(v) != model.at(v); });
        EXPECT_EQ(wrong, 0u) << describe(e);
    }
    while (w.undoDepth() > 0) w.undo();
    expectSameVoxels(w, before, region, "after undoing them all");
}

// A sphere's inside becomes tiles: only the bricks its surface crosses are leaves.
TEST(LiveWorld, LargeSphereIsTilesInsideLeavesOnItsSurface) {
    World w = slabWorld();
    // Voxels; the world's voxels are half a unit. Under the sanitizers 100, not
    // 200: the voxels of its surface's bricks, set one at a time, were the time;
    // its inside is still over 5,000 bricks of tiles.
    const int ri = grotto::test::underSanitizers(200, 100);
    const double r = ri;
    const glm::dvec3 c = centreOf(w, {0, 2 * ri, 0});
    const EditResult e = w.apply(Edit::fillSphere(c, r * w.voxelSize(), 3));
    uint64_t inside = 0;  // voxel centres within the radius, counted by hand
    for (int x = -ri - 1; x <= ri + 1; ++x)
        for (int y = -ri - 1; y <= ri + 1; ++y)
            for (int z = -ri - 1; z <= ri + 1; ++z) inside += double(x) * x + double(y) * y + double(z) * z <= r * r;
    EXPECT_EQ(e.changed, inside);
    const double pi = 3.14159265358979, d = 8.0 * std::sqrt(3.0);
    const double surfaceBricks = 4.0 / 3.0 * pi * (std::pow(r + d, 3) - std::pow(r - d, 3)) / 512.0;
    const uint64_t leaves = w.impl().solid->tree().leafCount();
    EXPECT_LT(double(leaves), surfaceBricks);
    EXPECT_GT(double(w.stats().bricks), 4.0 / 3.0 * pi * std::pow(r - d, 3) / 512.0);  // the tiles inside count as bricks
}

TEST(LiveWorld, ChunksTouchingIncludeNeighboursAcrossBorders) {
    const World w = slabWorld();
    EXPECT_EQ(w.chunksTouching({glm::ivec3(5), glm::ivec3(5)}), std::vector<glm::ivec3>{glm::ivec3(0)});
    EXPECT_EQ(w.chunksTouching({glm::ivec3(31), glm::ivec3(31)}).size(), 8u);
    const std::vector<glm::ivec3> lower = w.chunksTouching({{0, 5, 5}, {0, 5, 5}});
    EXPECT_EQ(lower, (std::vector<glm::ivec3>{{-32, 0, 0}, {0, 0, 0}}));
    EXPECT_TRUE(w.chunksTouching({}).empty());
    EXPECT_THROW(w.meshChunk({1, 0, 0}), Error);
}

TEST(LiveWorld, BrickTableFollowsGrowthFarAwayAndBackToEmpty) {
    World w = slabWorld();
    BrickTable table(w);
    ASSERT_TRUE(table.dense());
    std::mt19937 rng(3);
    const IndexBox near{{40, 40, 40}, {60, 41, 42}};
    table.update(w, w.apply(Edit::fillBox(near, 2)).voxels);
    expectSameTable(table, w, rng, "after a fill beyond the range");
    // So far away that a dense table would be too large: the table turns sparse.
    const IndexBox far{{1 << 28, 0, 0}, {(1 << 28) + 3, 1, 1}};
    table.update(w, w.apply(Edit::fillBox(far, 3)).voxels);
    EXPECT_FALSE(table.dense());
    EXPECT_EQ(table.find(far.min >> 3) != 0, true);
    expectSameTable(table, w, rng, "after a far fill");
    table.update(w, w.apply(Edit::carveBox({glm::ivec3(-100), glm::ivec3((1 << 28) + 100)})).voxels);
    EXPECT_TRUE(w.bounds().empty());
    expectSameTable(table, w, rng, "after carving everything");
    while (w.undoDepth()) table.update(w, w.undo().voxels);
    expectSameTable(table, w, rng, "after undoing everything");
}

TEST(LiveWorld, ReferenceAoFromAnUpdatedTableEqualsAFreshOne) {
    World w = cavesWorld();
    BrickTable table(w);
    table.update(w, w.apply(Edit::carveSphere(centreOf(w, {0, 60, 0}), 9.0)).voxels);
    table.update(w, w.apply(Edit::fillBox({{-5, 70, -5}, {5, 72, 5}}, 2)).voxels);
    std::vector<glm::dvec3> points, normals;
    for (int i = 0; i < 20; ++i) {
        points.push_back(centreOf(w, {i - 10, 52 + i, 0}));
        normals.push_back({0.0, 1.0, 0.0});
    }
    const ReferenceAoSettings s{.radius = 6.0, .spp = 64};
    const ReferenceAo fresh = referenceAo(w, points, normals, s), kept = referenceAo(table, w, points, normals, s);
    EXPECT_EQ(fresh.visibility, kept.visibility);
}

}  // namespace
}  // namespace grotto::voxel
