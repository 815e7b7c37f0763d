// Live worlds: random edits checked against a plain model of the voxels, the
// chunk-by-chunk mesh and the updated brick table checked against fresh ones,
// everything undone back to the original; and hand-built cases of each edit
// (large edits that become tiles: test_live_world_tiles.cpp).
#include "grotto/error.h"
#include "tests/live_world_checks.h"
#include "tests/live_world_model.h"
#include "tests/test_util.h"
#include "voxel/generators.h"
#include "voxel/live_mesh.h"
#include "voxel/reference_ao.h"
#include "voxel/solid.h"

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include <limits>
#include <random>

namespace grotto::voxel {
namespace {

using namespace test;  // the live-world checks, the model and the worlds

// Random edits inside `region`: every kind and shape, a third placed across
// chunk borders, and one in ten a repeat of the last (a no-op: edits are idempotent).
class EditMaker {
public:
    EditMaker(IndexBox region, int palette, glm::dvec3 origin, double voxelSize, uint32_t seed)
        : region_(region), palette_(palette), origin_(origin), voxelSize_(voxelSize), rng(seed) {}

    Edit next() {
        if (has_ && pick(0, 9) == 0) return last_;
        const int kind = pick(0, 19);
        const int material = pick(1, palette_);
        Edit e;
        if (kind < 6) {
            e = Edit::setVoxel(place(0), pick(0, 2) == 0 ? 0 : material);
        } else if (kind < 14) {
            const int size = pick(1, 10);
            const glm::ivec3 lo = place(size);
            const IndexBox b{lo, lo + glm::ivec3(pick(1, size), pick(1, size), pick(1, size)) - 1};
            e = kind < 9 ? Edit::fillBox(b, material) : kind < 12 ? Edit::carveBox(b) : Edit::paintBox(b, material);
        } else {
            const double r = std::uniform_real_distribution<double>(0.3, 8.0)(rng) * voxelSize_;
            const glm::dvec3 jitter(unit(), unit(), unit());
            const glm::dvec3 c = origin_ + (glm::dvec3(place(9)) + jitter) * voxelSize_;
            e = kind < 16 ? Edit::fillSphere(c, r, material) : kind < 18 ? Edit::carveSphere(c, r) : Edit::paintSphere(c, r, material);
        }
        last_ = e, has_ = true;
        return e;
    }
    std::mt19937 rng;

private:
    int pick(int lo, int hi) { return std::uniform_int_distribution<int>(lo, hi)(rng); }
    double unit() { return std::uniform_real_distribution<double>(0.0, 1.0)(rng); }
    // A voxel at least `margin` inside the region; often on a chunk border.
    glm::ivec3 place(int margin) {
        glm::ivec3 v;
        for (int a = 0; a < 3; ++a) {
            const int lo = region_.min[a] + margin, hi = region_.max[a] - margin;
            v[a] = pick(lo, hi);
            if (pick(0, 2) == 0) {
                const int border = (v[a] + 16) & ~31;
                const int near = border - 1 + pick(0, 1);
                if (near >= lo && near <= hi) v[a] = near;
            }
        }
        return v;
    }
    IndexBox region_;
    int palette_;
    glm::dvec3 origin_;
    double voxelSize_;
    Edit last_;
    bool has_ = false;
};

// Applies `count` random edits, each checked against the model and followed by
// LiveMesh::update and BrickTable::update; checkpoints compare everything with
// fresh ones. Then undoes them all and expects the original world back.
void editAndUndo(World world, int count, uint32_t seed) {
    const World original = world;
    const IndexBox region{world.bounds().min - 12, world.bounds().max + 12};
    Model model(world, region);
    LiveMesh live(world);
    BrickTable table(world);
    std::mt19937 probe(seed + 1);
    EditMaker edits(region, 3, world.origin(), world.voxelSize(), seed);
    std::vector<EditResult> applied;
    auto checkpoint = [&](const std::string& when) {
        expectSameMesh(live.flatten(), world.mesh(), when);
        expectSameTable(table, world, probe, when);
    };
    for (int i = 1; i <= count; ++i) {
        const Edit e = edits.next();
        const size_t logged = world.editLog().size();
        const EditResult r = world.apply(e);
        expectSameResult(r, model.apply(e), "edit " + std::to_string(i) + ": " + describe(e));
        EXPECT_EQ(world.editLog().size(), logged + (r.changed ? 1 : 0)) << describe(e);
        if (r.changed) applied.push_back(r);
        live.update(world, r.voxels);
        table.update(world, r.voxels);
        if (i % 100 == 0 || i == count) checkpoint("after edit " + std::to_string(i));
        if (i % 250 == 0 || i == count) {
            uint64_t wrong = 0;
            Model::forEach(region, [&](glm::ivec3 v) { wrong += world.material(v) != model.at(v); });
            ASSERT_EQ(wrong, 0u) << "voxels after edit " << i;
            const IndexBox b = model.solidBounds();
            EXPECT_EQ(world.bounds().min, b.min) << "after edit " << i;
            EXPECT_EQ(world.bounds().max, b.max) << "after edit " << i;
        }
    }
    ASSERT_EQ(world.undoDepth(), applied.size());
    ASSERT_EQ(world.editLog().size(), applied.size());
    for (int undone = 1; !applied.empty(); ++undone) {
        const EditResult r = world.undo();
        expectSameResult(r, applied.back(), "undo " + std::to_string(undone));
        applied.pop_back();
        live.update(world, r.voxels);
        table.update(world, r.voxels);
        if (undone % 100 == 0) checkpoint("after undo " + std::to_string(undone));
    }
    EXPECT_EQ(world.undo().changed, 0u);
    EXPECT_TRUE(world.editLog().empty());
    expectSameVoxels(world, original, region, "after undoing everything");
    checkpoint("after undoing everything");
    expectSameMesh(live.flatten(), original.mesh(), "after undoing everything, against the original");
}

// A quarter of the edits under the sanitizers: still checkpoints after edits 100,
// 200 and 250, the voxels compared after the last, and every edit undone.
TEST(LiveWorld, RandomEditsMatchAModelAndFreshMeshesAndTables) {
    editAndUndo(cavesWorld(), grotto::test::underSanitizers(1000, 250), 11);
}

TEST(LiveWorld, RandomEditsOnAMaskWorldWithTiles) { editAndUndo(thinWorldWithTiles(), 300, 23); }

TEST(LiveWorld, ResultsAreTightAndUndoRestores) {
    struct Case {
        Edit edit;
        IndexBox voxels;
        uint64_t changed;
    };
    World w0 = slabWorld();
    const Case cases[] = {
        // y 2 and 3 are solid already: only y 4..6 changes.
        {Edit::fillBox({{3, 2, 3}, {6, 6, 6}}, 1), {{3, 4, 3}, {6, 6, 6}}, 4 * 3 * 4},
        // A different material repaints the solid part too.
        {Edit::fillBox({{3, 2, 3}, {6, 6, 6}}, 2), {{3, 2, 3}, {6, 6, 6}}, 4 * 5 * 4},
        // Radius just over a voxel: the centre voxel and its six neighbours.
        {Edit::carveSphere(centreOf(w0, {8, 2, 8}), 0.51), {{7, 1, 7}, {9, 3, 9}}, 7},
        // Empty voxels stay empty: only y 2..3 of the box.
        {Edit::paintBox({{0, 2, 0}, {1, 5, 1}}, 3), {{0, 2, 0}, {1, 3, 1}}, 8},
        {Edit::paintSphere(centreOf(w0, {8, 3, 8}), 0.4, 4), {{8, 3, 8}, {8, 3, 8}}, 1},
        {Edit::setVoxel({15, 15, 15}, 5), {{15, 15, 15}, {15, 15, 15}}, 1},
        {Edit::setVoxel({0, 0, 0}, 0), {{0, 0, 0}, {0, 0, 0}}, 1},
        // A fill sphere centred between voxels: the 8 around the centre.
        {Edit::fillSphere(w0.origin() + glm::dvec3(5.0, 5.0, 5.0), 0.45, 2), {{9, 9, 9}, {10, 10, 10}}, 8},
    };
    for (const Case& c : cases) {
        World w = slabWorld();
        const World before = w;
        const EditResult r = w.apply(c.edit);
        const std::string what = describe(c.edit);
        EXPECT_EQ(r.changed, c.changed) << what;
        EXPECT_EQ(r.voxels.min, c.voxels.min) << what;
        EXPECT_EQ(r.voxels.max, c.voxels.max) << what;
        EXPECT_EQ(r.box.min, w.origin() + glm::dvec3(c.voxels.min) * 0.5) << what;
        EXPECT_EQ(r.box.max, w.origin() + glm::dvec3(c.voxels.max + 1) * 0.5) << what;
        // Outside the result, nothing changed.
        uint64_t outside = 0;
        Model::forEach({glm::ivec3(-1), glm::ivec3(16)}, [&](glm::ivec3 v) {
            if (!r.voxels.contains(v)) outside += w.material(v) != before.material(v);
        });
        EXPECT_EQ(outside, 0u) << what;
        ASSERT_EQ(w.undoDepth(), 1u) << what;
        const EditResult u = w.undo();
        expectSameResult(u, r, "undo of " + what);
        expectSameVoxels(w, before, {glm::ivec3(-1), glm::ivec3(16)}, "undo of " + what);
        EXPECT_EQ(w.undoDepth(), 0u);
        EXPECT_TRUE(w.editLog().empty());
    }
}

TEST(LiveWorld, EditLogIsAppliedMinusUndone) {
    World w = slabWorld();
    const Edit a = Edit::fillBox({{0, 5, 0}, {2, 6, 2}}, 2), b = Edit::carveSphere(centreOf(w, {4, 3, 4}), 1.0),
               c = Edit::paintBox({{0, 0, 0}, {15, 0, 15}}, 4);
    w.apply(a), w.apply(b), w.apply(c);
    ASSERT_EQ(w.editLog().size(), 3u);
    w.undo();
    ASSERT_EQ(w.editLog().size(), 2u);
    EXPECT_EQ(describe(w.editLog()[0]), describe(a));
    EXPECT_EQ(describe(w.editLog()[1]), describe(b));
    EXPECT_EQ(describe(b), "carve sphere at (12.25, 21.75, 32.25) r 1");
    EXPECT_EQ(describe(a), "fill box (0, 5, 0) to (2, 6, 2) material 2");
    EXPECT_EQ(describe(Edit::setVoxel({1, 2, 3}, 0)), "carve voxel (1, 2, 3)");
}

TEST(LiveWorld, NoOpEditsAreNotRecorded) {
    World w = slabWorld();
    const Edit noOps[] = {
        Edit::carveBox({{0, 8, 0}, {15, 15, 15}}),             // empty already
        Edit::fillBox({{0, 0, 0}, {3, 3, 3}}, 1),              // solid with that material already
        Edit::paintBox({{0, 10, 0}, {15, 15, 15}}, 2),         // nothing solid to paint
        Edit::carveSphere(centreOf(w, {8, 10, 8}), 2.0),       // in the air
        Edit::fillSphere(centreOf(w, {8, 8, 8}) + 0.25, 0.1, 1),  // holds no voxel centre
        Edit::carveBox({{1000, 1000, 1000}, {1010, 1010, 1010}}),  // far outside the world
    };
    for (const Edit& e : noOps) {
        const EditResult r = w.apply(e);
        EXPECT_EQ(r.changed, 0u) << describe(e);
        EXPECT_TRUE(r.voxels.empty()) << describe(e);
        EXPECT_TRUE(r.box.empty()) << describe(e);
    }
    EXPECT_EQ(w.undoDepth(), 0u);
    EXPECT_TRUE(w.editLog().empty());
    EXPECT_EQ(w.undo().changed, 0u);
}

TEST(LiveWorld, BadEditsThrowAndChangeNothing) {
    World w = slabWorld();
    const double nan = std::numeric_limits<double>::quiet_NaN(), inf = std::numeric_limits<double>::infinity();
    const int palette = int(defaultMaterials().size());
    const glm::dvec3 c = centreOf(w, {4, 4, 4});
    const Edit bad[] = {
        Edit::fillBox({{0, 0, 0}, {1, 1, 1}}, 0),
        Edit::fillBox({{0, 0, 0}, {1, 1, 1}}, palette + 1),
        Edit::paintBox({{0, 0, 0}, {1, 1, 1}}, -1),
        Edit::fillSphere(c, 1.0, palette + 1),
        Edit::carveSphere(c, 0.0),
        Edit::carveSphere(c, -1.0),
        Edit::carveSphere(c, nan),
        Edit::fillSphere(c, inf, 1),
        Edit::carveSphere({nan, 0, 0}, 1.0),
        Edit::carveBox({{2, 2, 2}, {1, 3, 3}}),
        Edit::fillBox({{kMaxVoxelIndex - 1, 0, 0}, {kMaxVoxelIndex, 0, 0}}, 1),
        Edit::carveBox({{0, -kMaxVoxelIndex - 1, 0}, {0, 0, 0}}),
        Edit::carveSphere(w.origin() + glm::dvec3(0, 0, double(kMaxVoxelIndex) - 2.0) * w.voxelSize(), 4.0),
        // Larger than the memory budget could hold as bricks.
        Edit::fillBox({glm::ivec3(-(1 << 29)), glm::ivec3((1 << 29) - 1)}, 1),
    };
    const World before = w;
    for (const Edit& e : bad) {
        // check() refuses what apply() would, with the same message, changing nothing.
        std::string checked;
        try {
            w.check(e);
            ADD_FAILURE() << describe(e) << " passed the check";
        } catch (const Error& err) {
            checked = err.what();
        }
        try {
            w.apply(e);
            ADD_FAILURE() << describe(e) << " was accepted";
        } catch (const Error& err) {
            EXPECT_EQ(err.kind(), Error::Kind::Input) << err.what();
            EXPECT_NE(std::string(err.what()).find(describe(e)), std::string::npos) << err.what();
            EXPECT_FALSE(err.hint().empty()) << err.what();
            EXPECT_EQ(checked, err.what());
        }
    }
    EXPECT_TRUE(w.editLog().empty());
    expectSameVoxels(w, before, {glm::ivec3(-1), glm::ivec3(16)}, "after refused edits");
}

TEST(LiveWorld, UndoKeepsTheLast1024EditsAndTheLogStaysExact) {
    World w = slabWorld();
    const int count = 1030;
    for (int i = 0; i < count; ++i) w.apply(Edit::setVoxel({i % 16, 8 + (i / 16) % 8, (i / 128) % 16}, 1 + i % 2));
    EXPECT_EQ(w.undoDepth(), 1024u);
    EXPECT_EQ(w.editLog().size(), size_t(count));
    for (int i = 0; i < 1024; ++i) EXPECT_EQ(w.undo().changed, 1u);
    EXPECT_EQ(w.undo().changed, 0u);
    ASSERT_EQ(w.editLog().size(), 6u);
    for (int i = 0; i < 6; ++i) EXPECT_EQ(describe(w.editLog()[i]), describe(Edit::setVoxel({i, 8, 0}, 1 + i % 2)));
    EXPECT_EQ(w.material({5, 8, 0}), 2);
    EXPECT_EQ(w.material({6, 8, 0}), 0);
}

TEST(LiveWorld, CarvingTheBoundaryShrinksTheBounds) {
    World w = slabWorld();
    w.apply(Edit::setVoxel({20, 9, -3}, 2));
    EXPECT_EQ(w.bounds().min, glm::ivec3(0, 0, -3));
    EXPECT_EQ(w.bounds().max, glm::ivec3(20, 9, 15));
    w.apply(Edit::setVoxel({20, 9, -3}, 0));
    EXPECT_EQ(w.bounds().min, glm::ivec3(0));
    EXPECT_EQ(w.bounds().max, glm::ivec3(15, 3, 15));
    w.apply(Edit::carveBox({{0, 0, 0}, {15, 15, 15}}));
    EXPECT_TRUE(w.bounds().empty());
    EXPECT_EQ(w.stats().bricks, 0u);  // emptied leaves are dropped
    w.undo();
    EXPECT_EQ(w.bounds().max, glm::ivec3(15, 3, 15));
}

TEST(LiveWorld, PaintingAUniformWorldAddsMaterialsAndUndoRemovesThem) {
    World w = thinWorldWithTiles();
    const World before = w;
    const IndexBox around{w.bounds().min - 1, w.bounds().max + 1};
    // Inside an active tile: only the sphere's voxels change.
    const EditResult r = w.apply(Edit::paintSphere(centreOf(w, {28, 12, 28}), 2.0, 3));
    EXPECT_EQ(r.changed, 33u);  // voxel centres within 2 of a voxel centre
    EXPECT_EQ(w.material({28, 12, 28}), 3);
    EXPECT_EQ(w.material({24, 8, 24}), 1);
    w.undo();
    expectSameVoxels(w, before, around, "after undoing the paint");
}

}  // namespace
}  // namespace grotto::voxel
