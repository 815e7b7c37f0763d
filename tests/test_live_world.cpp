// Live worlds: random edits checked against a plain model of the voxels, the
// chunk-by-chunk mesh and the updated brick table checked against fresh ones,
// everything undone back to the original; and hand-built cases of each edit.
#include "grotto/error.h"
#include "tests/live_world_checks.h"
#include "voxel/generators.h"
#include "voxel/live_mesh.h"
#include "voxel/reference_ao.h"
#include "voxel/solid.h"

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>

namespace grotto::voxel {
namespace {

using test::expectSameMesh;
using test::expectSameTable;

// Material ids over a box, in a dense array, edited the way edit.h says: the
// oracle for what World::apply must change.
struct Model {
    IndexBox box;
    glm::dvec3 origin;
    double voxelSize;
    std::vector<int> ids;

    Model(const World& w, IndexBox b) : box(b), origin(w.origin()), voxelSize(w.voxelSize()) {
        const glm::ivec3 n = b.max - b.min + 1;
        ids.resize(size_t(n.x) * n.y * n.z);
        forEach(b, [&](glm::ivec3 v) { at(v) = w.material(v); });
    }
    int& at(glm::ivec3 v) {
        const glm::ivec3 r = v - box.min, n = box.max - box.min + 1;
        return ids[(size_t(r.x) * n.y + r.y) * n.z + r.z];
    }
    template <typename F>
    static void forEach(const IndexBox& b, F f) {
        for (int x = b.min.x; x <= b.max.x; ++x)
            for (int y = b.min.y; y <= b.max.y; ++y)
                for (int z = b.min.z; z <= b.max.z; ++z) f(glm::ivec3(x, y, z));
    }
    bool inside(const Edit& e, glm::ivec3 v) const {
        if (e.shape == Edit::Shape::Box) return e.box.contains(v);
        const glm::dvec3 d = origin + (glm::dvec3(v) + 0.5) * voxelSize - e.centre;
        return glm::dot(d, d) <= e.radius * e.radius;
    }
    EditResult apply(const Edit& e) {
        IndexBox scan = e.box;
        if (e.shape == Edit::Shape::Sphere) {
            const glm::dvec3 c = (e.centre - origin) / voxelSize;
            const double r = e.radius / voxelSize;
            scan = {glm::ivec3(glm::floor(c - r)) - 1, glm::ivec3(glm::ceil(c + r)) + 1};
        }
        EditResult out;
        forEach(scan, [&](glm::ivec3 v) {
            if (!inside(e, v)) return;
            EXPECT_TRUE(box.contains(v)) << "the test's edit leaves the model's box";
            int& id = at(v);
            const int after = e.op == Edit::Op::Carve ? 0 : e.op == Edit::Op::Fill ? e.material : id ? e.material : 0;
            if (after == id) return;
            id = after;
            out.voxels = out.voxels.merged({v, v});
            ++out.changed;
        });
        if (!out.voxels.empty())
            out.box = {origin + glm::dvec3(out.voxels.min) * voxelSize, origin + glm::dvec3(out.voxels.max + 1) * voxelSize};
        return out;
    }
    IndexBox solidBounds() {
        IndexBox b;
        forEach(box, [&](glm::ivec3 v) {
            if (at(v)) b = b.merged({v, v});
        });
        return b;
    }
};

void expectSameVoxels(const World& got, const World& want, const IndexBox& over, const std::string& when) {
    uint64_t wrong = 0;
    Model::forEach(over, [&](glm::ivec3 v) { wrong += got.material(v) != want.material(v); });
    EXPECT_EQ(wrong, 0u) << when;
    EXPECT_EQ(got.bounds().min, want.bounds().min) << when;
    EXPECT_EQ(got.bounds().max, want.bounds().max) << when;
    EXPECT_EQ(got.stats().solidVoxels, want.stats().solidVoxels) << when;
}

void expectSameResult(const EditResult& got, const EditResult& want, const std::string& what) {
    EXPECT_EQ(got.changed, want.changed) << what;
    EXPECT_EQ(got.voxels.min, want.voxels.min) << what;
    EXPECT_EQ(got.voxels.max, want.voxels.max) << what;
    EXPECT_EQ(got.box.min, want.box.min) << what;
    EXPECT_EQ(got.box.max, want.box.max) << what;
}

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

WorldDesc paletteDesc() {
    WorldDesc d;
    d.materials = defaultMaterials();
    return d;
}

World cavesWorld() {
    openvdb::initialize();
    return makeWorld(generateWorld("caves", {.seed = 5, .size = 40}), paletteDesc());
}

// A bool grid with 8^3 active tiles, one against a chunk border: edits inside
// them must voxelize just the part they change.
World thinWorldWithTiles() {
    openvdb::initialize();
    auto grid = openvdb::gridPtrCast<openvdb::BoolGrid>(generateWorld("thin", {.seed = 2, .size = 32}));
    grid->tree().addTile(1, openvdb::Coord(24, 8, 24), true, true);
    grid->tree().addTile(1, openvdb::Coord(-8, 16, 0), true, true);
    return makeWorld(grid, paletteDesc());
}

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

TEST(LiveWorld, RandomEditsMatchAModelAndFreshMeshesAndTables) { editAndUndo(cavesWorld(), 1000, 11); }

TEST(LiveWorld, RandomEditsOnAMaskWorldWithTiles) { editAndUndo(thinWorldWithTiles(), 300, 23); }

// A 16^3 world of voxel size 0.5 at (10, 20, 30): a slab of material 1 at y < 4.
World slabWorld() {
    std::vector<uint8_t> ids(16 * 16 * 16, 0);
    for (int z = 0; z < 16; ++z)
        for (int y = 0; y < 4; ++y)
            for (int x = 0; x < 16; ++x) ids[(z * 16 + y) * 16 + x] = 1;
    return World::fromDense({16, 16, 16}, ids.data(), 0.5, {10, 20, 30});
}

glm::dvec3 centreOf(const World& w, glm::ivec3 v) { return w.origin() + (glm::dvec3(v) + 0.5) * w.voxelSize(); }

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
    const IndexBox box{{-37, -5, -3}, {218, 250, 252}};  // 256^3, off brick and chunk boundaries
    w.apply(Edit::fillBox(box, 2));
    const Mesh mesh = w.mesh();
    uint64_t twiceArea = 0;  // of each convex quad or triangle: half the cross product of its diagonals
    for (const MeshQuad& q : mesh.quads) {
        const glm::dvec3 d = glm::abs(glm::cross(glm::dvec3(q.corner(2) - q.corner(0)), glm::dvec3(q.corner(3) - q.corner(1))));
        twiceArea += uint64_t(d.x + d.y + d.z);  // one axis is non-zero: the face's normal
    }
    EXPECT_EQ(twiceArea, 2 * 6ull * 256 * 256);
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
    const double r = 200.0;  // voxels; the world's voxels are half a unit
    const glm::dvec3 c = centreOf(w, {0, 400, 0});
    const EditResult e = w.apply(Edit::fillSphere(c, r * w.voxelSize(), 3));
    uint64_t inside = 0;  // voxel centres within the radius, counted by hand
    for (int x = -201; x <= 201; ++x)
        for (int y = -201; y <= 201; ++y)
            for (int z = -201; z <= 201; ++z) inside += double(x) * x + double(y) * y + double(z) * z <= r * r;
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
