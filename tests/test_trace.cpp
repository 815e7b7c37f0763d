// The world's solid voxels on the GPU (engine/scene/occupancy.h, shaders/trace.glsl)
// against the CPU's: every voxel of a random world with negative indices, of a
// sparse world whose tiles lie far apart, and of a live world after random edits
// staged through it (new and distant tiles, grown buffers, freed and reused masks,
// an undo) answers as World::solid does; and the sun-shadow pass agrees with exact
// CPU rays (World::raycast) on the shipped worlds, 1e6 units from the origin and at
// voxel indices near 2e6, except within a hair of a shadow edge.
#include "engine/scene/live_scene.h"
#include "engine/passes/compute_pass.h"
#include "engine/passes/trace_inputs.h"
#include "engine/renderer.h"
#include "engine/lab/surface_points.h"
#include "tests/gpu_fixture.h"
#include "tests/occupancy_query.h"
#include "tests/scenes.h"
#include "tests/sun_rays.h"
#include "tests/test_util.h"
#include "voxel/brick_table.h"
#include "voxel/solid.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <map>
#include <optional>
#include <random>
#include <set>
#include <tuple>

namespace grotto {
namespace {

using test::GpuTest;
using test::OccupancyQuery;

// Every voxel of the inclusive box, x fastest.
void appendBox(std::vector<glm::ivec3>& cells, const voxel::IndexBox& b) {
    for (int z = b.min.z; z <= b.max.z; ++z)
        for (int y = b.min.y; y <= b.max.y; ++y)
            for (int x = b.min.x; x <= b.max.x; ++x) cells.push_back({x, y, z});
}

voxel::IndexBox grown(const voxel::IndexBox& b, int by) { return {b.min - by, b.max + by}; }

struct Agreement {
    size_t cells = 0, solid = 0, mismatches = 0;
};

// The GPU's answers against World::solid; the first few mismatches are reported.
Agreement compare(const voxel::World& world, const std::vector<glm::ivec3>& cells, const std::vector<uint8_t>& gpu,
                  const char* what) {
    Agreement a;
    a.cells = cells.size();
    for (size_t i = 0; i < cells.size(); ++i) {
        const bool cpu = world.solid(cells[i]);
        a.solid += cpu;
        if (cpu != (gpu[i] != 0)) {
            if (++a.mismatches <= 10)
                ADD_FAILURE() << what << ": voxel (" << cells[i].x << ", " << cells[i].y << ", " << cells[i].z
                              << ") is " << (cpu ? "solid" : "empty") << " on the CPU, "
                              << (gpu[i] ? "solid" : "empty") << " on the GPU";
        }
    }
    std::printf("[ measured ] %s: %zu voxels queried, %zu solid, %zu disagree\n", what, a.cells, a.solid,
                a.mismatches);
    return a;
}

// A random world over a box with a negative, brick-unaligned corner (built through
// OpenVDB: World::fromDense always puts its first voxel at index 0): about 30% of
// its voxels solid, a quarter of its bricks empty, some bricks full, and one whole
// 64^3 tile empty (x in [-64, 0), y >= 0, z in [0, 64)), so the hash table misses it.
constexpr glm::ivec3 kDenseLo(-77, -45, -61), kDenseSize(150, 90, 130);
voxel::World denseRandomWorld() {
    std::mt19937 rng(20240611);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    std::vector<uint8_t> dense(size_t(kDenseSize.x) * kDenseSize.y * kDenseSize.z);
    for (uint8_t& v : dense) v = u(rng) < 0.3;
    auto brickHash = [](int x, int y, int z) {
        return (uint32_t(x >> 3) * 73856093u ^ uint32_t(y >> 3) * 19349663u ^ uint32_t(z >> 3) * 83492791u) % 97u;
    };
    return test::makeVoxelWorld(kDenseLo, kDenseLo + kDenseSize - 1, [&](int x, int y, int z) {
        if (x >= -64 && x < 0 && y >= 0 && z >= 0 && z < 64) return false;  // the empty tile
        const uint32_t h = brickHash(x, y, z);
        if (h < 24) return false;  // an empty brick
        if (h < 30) return true;   // a full brick
        const glm::ivec3 i = glm::ivec3(x, y, z) - kDenseLo;
        return dense[(size_t(i.z) * kDenseSize.y + i.y) * kDenseSize.x + i.x] != 0;
    }, 0.5, {-13.3, 7.1, -2.05});
}

// Clusters of random voxels far apart (more than 10^4 voxels, up to 5 * 10^5 from
// the origin), each straddling tile corners, so the hash table holds distant tiles
// and probes past collisions.
struct SparseWorld {
    voxel::World world;
    std::vector<voxel::IndexBox> clusters;
};
SparseWorld sparseRandomWorld() {
    openvdb::initialize();
    auto grid = openvdb::MaskGrid::create();
    auto acc = grid->getAccessor();
    const glm::ivec3 centres[] = {{0, 0, 0},           {-20032, 64, 12288},    {15040, -7040, -12352},
                                  {-512, 20032, -64},  {500032, -499968, 64}, {-300032, 320000, 250048},
                                  {64, 64, -40000},    {-64, -192, 40064}};
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    std::vector<voxel::IndexBox> clusters;
    for (const glm::ivec3& c : centres) {
        const voxel::IndexBox box{c - 13, c + 12};  // 26^3 across a tile corner
        clusters.push_back(box);
        for (int x = box.min.x; x <= box.max.x; ++x)
            for (int y = box.min.y; y <= box.max.y; ++y)
                for (int z = box.min.z; z <= box.max.z; ++z)
                    if (u(rng) < 0.35) acc.setValueOn(openvdb::Coord(x, y, z));
    }
    voxel::WorldDesc desc;
    desc.materials = voxel::defaultMaterials();
    return {voxel::makeWorld(grid, desc), clusters};
}

// Tiles (64^3) holding solid voxels, and how many share their hash table home
// slot with another (the table holds twice the tiles or more, at least 16).
std::pair<size_t, size_t> tilesAndCollisions(const voxel::World& world) {
    std::set<std::tuple<int, int, int>> tiles;
    for (const voxel::Brick& b : world.bricks()) {
        const glm::ivec3 t = b.origin >> GROTTO_TILE_SHIFT;
        tiles.insert({t.x, t.y, t.z});
    }
    const uint32_t mask = uint32_t(std::max<size_t>(std::bit_ceil(2 * tiles.size()), 16) - 1);
    std::map<uint32_t, int> homes;
    for (const auto& [x, y, z] : tiles) ++homes[gpu::occupancyHash(x, y, z) & mask];
    size_t shared = 0;
    for (const auto& [slot, n] : homes) shared += n > 1 ? n : 0;
    return {tiles.size(), shared};
}

using Occupancy = GpuTest;

TEST_F(Occupancy, RandomWorldsQueriedOnGpuAndCpuAgreeEverywhere) {
    OccupancyQuery query(ctx());
    {
        const voxel::World world = denseRandomWorld();
        ASSERT_EQ(world.bounds().min, kDenseLo);  // random voxels reach the box's corners
        ASSERT_EQ(world.bounds().max, kDenseLo + kDenseSize - 1);
        for (const voxel::Brick& b : world.bricks())  // the empty tile has no brick
            ASSERT_FALSE(b.origin.x >= -64 && b.origin.x < 0 && b.origin.y >= 0 && b.origin.z >= 0 && b.origin.z < 64);
        const GpuOccupancy occupancy(ctx(), world);
        std::vector<glm::ivec3> cells;
        appendBox(cells, grown(world.bounds(), 2));
        const Agreement a = compare(world, cells, query.solid(occupancy, cells), "dense world");
        EXPECT_EQ(a.mismatches, 0u);
        EXPECT_GT(a.solid, a.cells / 5);  // not a vacuous comparison: both answers are common
        EXPECT_LT(a.solid, a.cells / 2);
    }
    {
        const SparseWorld s = sparseRandomWorld();
        const auto [tiles, colliding] = tilesAndCollisions(s.world);
        std::printf("[ measured ] sparse world: %zu tiles, %zu sharing a hash home slot\n", tiles, colliding);
        EXPECT_GE(tiles, 8u * 8u);
        EXPECT_GT(colliding, 0u);  // linear probing is exercised
        const GpuOccupancy occupancy(ctx(), s.world);
        std::vector<glm::ivec3> cells;
        for (const voxel::IndexBox& c : s.clusters) appendBox(cells, grown(c, 2));
        // And voxels anywhere within the bounds: nearly all in absent tiles.
        std::mt19937 rng(3);
        const voxel::IndexBox b = s.world.bounds();
        std::uniform_int_distribution<int> x(b.min.x, b.max.x), y(b.min.y, b.max.y), z(b.min.z, b.max.z);
        for (int i = 0; i < 200000; ++i) cells.push_back({x(rng), y(rng), z(rng)});
        const Agreement a = compare(s.world, cells, query.solid(occupancy, cells), "sparse world");
        EXPECT_EQ(a.mismatches, 0u);
        EXPECT_GT(a.solid, 8u * 26 * 26 * 26 / 4);
    }
}

TEST_F(Occupancy, EditsStagedThroughALiveSceneKeepGpuAndCpuInStep) {
    OccupancyQuery query(ctx());
    LiveScene scene(ctx(), denseRandomWorld());
    // Checked: the cells the edits touched, and the world's own (under the
    // sanitizers a quarter of them, across all three axes: the fresh world's
    // every cell is checked by the test above, and the whole world twice
    // here took over a minute of their time).
    voxel::IndexBox world = scene.world().bounds();
    if (test::kAddressSanitizer) world.max = world.min + (world.max - world.min) * 5 / 8;
    std::vector<voxel::IndexBox> touched{world};
    std::mt19937 rng(99);
    std::uniform_int_distribution<int> inX(kDenseLo.x, kDenseLo.x + kDenseSize.x - 1),
        inY(kDenseLo.y, kDenseLo.y + kDenseSize.y - 1), inZ(kDenseLo.z, kDenseLo.z + kDenseSize.z - 1),
        extent(1, 14), material(1, 3);
    std::uniform_real_distribution<double> radius(1.0, 9.0);
    const voxel::World& w = scene.world();
    auto apply = [&](const voxel::Edit& e) {
        const voxel::EditResult r = scene.apply(e);
        if (!r.voxels.empty()) touched.push_back(r.voxels);
    };
    // Random boxes and spheres within the world, filled and carved.
    auto randomEdits = [&](int count) {
        for (int i = 0; i < count; ++i) {
            const glm::ivec3 c(inX(rng), inY(rng), inZ(rng)), e(extent(rng), extent(rng), extent(rng));
            const glm::dvec3 centre = w.origin() + (glm::dvec3(c) + 0.5) * w.voxelSize();
            switch (i % 4) {
                case 0: apply(voxel::Edit::fillBox({c, c + e}, material(rng))); break;
                case 1: apply(voxel::Edit::carveBox({c - e, c})); break;
                case 2: apply(voxel::Edit::fillSphere(centre, radius(rng) * w.voxelSize(), material(rng))); break;
                default: apply(voxel::Edit::carveSphere(centre, radius(rng) * w.voxelSize())); break;
            }
        }
    };
    auto check = [&](const char* what, GpuScene* pending) {
        // Each cell once (the edits' boxes overlap): a box's cells that lie in an
        // earlier box of the list are that box's. Sorting a million cells to find
        // the repeats took the sanitizers several seconds a check.
        std::vector<voxel::IndexBox> boxes;
        for (const voxel::IndexBox& b : touched) boxes.push_back(grown(b, 2));
        auto contains = [](const voxel::IndexBox& b, const glm::ivec3& c) {
            return glm::all(glm::greaterThanEqual(c, b.min)) && glm::all(glm::lessThanEqual(c, b.max));
        };
        std::vector<glm::ivec3> cells;
        for (size_t i = 0; i < boxes.size(); ++i) {
            const voxel::IndexBox& b = boxes[i];
            std::vector<voxel::IndexBox> earlier;  // those that overlap this one
            for (size_t j = 0; j < i; ++j)
                if (glm::all(glm::lessThanEqual(boxes[j].min, b.max)) && glm::all(glm::lessThanEqual(b.min, boxes[j].max)))
                    earlier.push_back(boxes[j]);
            for (int z = b.min.z; z <= b.max.z; ++z)
                for (int y = b.min.y; y <= b.max.y; ++y)
                    for (int x = b.min.x; x <= b.max.x; ++x) {
                        const glm::ivec3 c(x, y, z);
                        if (std::none_of(earlier.begin(), earlier.end(), [&](const voxel::IndexBox& e) { return contains(e, c); }))
                            cells.push_back(c);
                    }
        }
        const Agreement a = compare(w, cells, query.solid(*scene.gpu().occupancy(), cells, pending), what);
        EXPECT_EQ(a.mismatches, 0u) << what;
    };

    // Round 1: random edits inside the world (a quarter as many under the sanitizers); the
    // empty tile gets voxels (a new tile near the others); far boxes make new tiles, more
    // than the hash table has room for at half load (it is rebuilt) and than the bricks
    // buffer has spare room for (it grows), and a large fill grows the masks buffer.
    const size_t masksBefore = scene.gpu().occupancy()->masks().size, bricksBefore = scene.gpu().occupancy()->bricks().size;
    const uint32_t hashBefore = scene.gpu().occupancy()->hashMask();
    randomEdits(test::underSanitizers(40, 10));
    apply(voxel::Edit::fillSphere(w.origin() + glm::dvec3(-30, 20, 30) * w.voxelSize(), 6.0 * w.voxelSize(), 2));
    apply(voxel::Edit::fillBox({{-60, 50, -60}, {60, 90, 60}}, 1));  // above the world: new tiles, many bricks
    for (int k = 0; k < 30; ++k) {
        const glm::ivec3 c(20000 - 4099 * k, -3000 + 613 * (k % 7), 11000 - 1500 * k);
        apply(voxel::Edit::fillBox({c, c + glm::ivec3(k % 5, 3, 9 - k % 4)}, 1 + k % 3));
    }
    EXPECT_GT(scene.gpu().occupancy()->hashMask(), hashBefore);
    EXPECT_GT(scene.gpu().occupancy()->bricks().size, bricksBefore);
    EXPECT_GT(scene.gpu().occupancy()->masks().size, masksBefore);
    ASSERT_TRUE(scene.gpu().uploadsPending());
    check("edited world, uploads recorded with the query", &scene.gpu());

    // Round 2: more edits (carving most of the world away frees masks that later
    // fills reuse; a far cluster goes entirely), one undone; a renderer's frame
    // records the uploads.
    apply(voxel::Edit::carveBox({{-70, -40, -50}, {20, 30, 10}}));
    randomEdits(test::underSanitizers(40, 10));
    apply(voxel::Edit::carveBox({{20000 - 4099 * 3 - 2, -3000 + 613 * 3 - 2, 11000 - 1500 * 3 - 2},
                                 {20000 - 4099 * 3 + 12, -3000 + 613 * 3 + 12, 11000 - 1500 * 3 + 12}}));
    apply(voxel::Edit::fillBox({{-5000, 7000, 9000}, {-4990, 7003, 9070}}, 3));
    const voxel::EditResult undone = scene.undo();
    ASSERT_FALSE(undone.voxels.empty());
    touched.push_back(undone.voxels);
    {
        AoOptions noAo;
        noAo.estimator = estimatorPreset("high", 2.0);
        noAo.enabled = false;
        Renderer renderer(ctx(), scene.gpu(), w.desc().lighting, noAo, 64, 48);
        const Camera camera = makeCamera(test::lookAt({0, 60, 60}, {0, 0, 0}), 64, 48);
        renderer.render(camera);
        EXPECT_FALSE(scene.gpu().uploadsPending());
        check("edited again, uploads recorded by a frame", nullptr);
    }
}

// ---------------------------------------------------------------------------
// Sun shadows against exact CPU rays.

struct ShadowCheck {
    size_t surface = 0;       // surface pixels
    size_t facingAway = 0;    // of them, faces turned from the sun (must be 0 in the AOV)
    size_t cpuShadowed = 0;   // sunward faces the CPU finds blocked
    size_t cpuLit = 0;
    size_t excused = 0;       // disagreements within a hair of a shadow edge
    size_t unexcused = 0;
    size_t skyWrong = 0;      // sky pixels not 1
};

// The tolerance of "within a hair of a shadow edge": a disagreement is excused
// when the CPU's own answer changes as the ray's origin moves this far (voxels)
// along either tangent axis of its face, either way. The GPU's point differs from
// the CPU's by float rounding (1e-5 voxel or less here), so this is far more than
// exact rays need; excused disagreements may be at most kExcusedShare of the surface
// pixels.
constexpr double kEdgeNudge = 0.005, kExcusedShare = 0.001;

ShadowCheck checkShadows(const voxel::World& world, const FrameImages& f, const Camera& camera, const char* what) {
    const double vs = world.voxelSize();
    const glm::dvec3 sun(glm::normalize(world.desc().lighting.sunDirection));  // the float direction the GPU gets
    const SurfacePoints pts = surfacePoints(f, camera, vs, world.origin());
    ShadowCheck c;
    for (size_t i = 0; i < f.surfaceIds.size(); ++i)
        if (f.surfaceIds[i] == 0) c.skyWrong += f.shadow[i] != 1.0f;
    const test::SunRays rays(world);
    c.surface = pts.points.size();
    for (size_t k = 0; k < pts.points.size(); ++k) {
        const glm::dvec3 n = pts.normals[k];
        const uint32_t pixel = pts.pixels[k];
        const float gpu = f.shadow[pixel];
        if (glm::dot(n, sun) <= 0.0) {
            ++c.facingAway;
            if (gpu != 0.0f && ++c.unexcused <= 10)
                ADD_FAILURE() << what << ": pixel " << pixel % f.width << ", " << pixel / f.width
                              << " faces away from the sun but its shadow is " << gpu;
            continue;
        }
        const glm::dvec3& p = pts.points[k];
        const bool cpuBlocked = rays.blocked(p, n, sun);
        ++(cpuBlocked ? c.cpuShadowed : c.cpuLit);
        EXPECT_TRUE(gpu == 0.0f || gpu == 1.0f) << what << ": shadow " << gpu;
        if ((gpu == 0.0f) == cpuBlocked) continue;
        // Within a hair of an edge: the CPU's answer changes under a small nudge.
        const int a = n.x != 0.0 ? 0 : n.y != 0.0 ? 1 : 2;
        bool edge = false;
        for (int t : {(a + 1) % 3, (a + 2) % 3})
            for (double s : {-kEdgeNudge, kEdgeNudge}) {
                glm::dvec3 q = p;
                q[t] += s * vs;
                edge |= rays.blocked(q, n, sun) != cpuBlocked;
            }
        if (edge) {
            ++c.excused;
        } else if (++c.unexcused <= 10) {
            ADD_FAILURE() << what << ": pixel " << pixel % f.width << ", " << pixel / f.width << " at ("
                          << pts.points[k].x << ", " << pts.points[k].y << ", " << pts.points[k].z << ") normal ("
                          << n.x << ", " << n.y << ", " << n.z << "): GPU " << (gpu == 0.0f ? "shadowed" : "lit")
                          << ", CPU " << (cpuBlocked ? "shadowed" : "lit") << ", and no nudge of "
                          << kEdgeNudge << " voxel changes that";
        }
    }
    std::printf("[ measured ] %s: %zu surface pixels, %zu facing away, %zu shadowed and %zu lit on the CPU; "
                "%zu disagreements within %.3f voxel of an edge (%.3f%%), %zu others\n",
                what, c.surface, c.facingAway, c.cpuShadowed, c.cpuLit, c.excused, kEdgeNudge,
                100.0 * double(c.excused) / double(std::max<size_t>(c.surface, 1)), c.unexcused);
    EXPECT_EQ(c.unexcused, 0u) << what;
    EXPECT_LE(double(c.excused), kExcusedShare * double(c.surface)) << what;
    EXPECT_EQ(c.skyWrong, 0u) << what;
    return c;
}

// One frame of `world` from `camera` with sun shadows, AO off, read back with AOVs.
FrameImages shadowFrame(vk::Context& ctx, const voxel::World& world, const Camera& camera) {
    auto scene = uploadScene(ctx, world);
    AoOptions noAo;
    noAo.estimator = estimatorPreset("high", 2.0);
    noAo.enabled = false;
    voxel::Lighting lighting = world.desc().lighting;
    lighting.sunShadows = true;
    Renderer renderer(ctx, *scene, lighting, noAo, camera.width, camera.height);
    renderer.render(camera);
    return renderer.readback(camera, true);
}

struct ShippedView {
    const char* world;
    const char* camera;
};
void PrintTo(const ShippedView& v, std::ostream* os) { *os << v.world << "/" << v.camera; }

class Shadows : public GpuTest, public ::testing::WithParamInterface<ShippedView> {};

TEST_P(Shadows, AgreeWithExactCpuRaysExceptWithinAHairOfEdges) {
    const ShippedView v = GetParam();
    const voxel::World world = voxel::World::load(test::worldsDir() / (std::string(v.world) + ".json"));
    const Camera camera = worldCamera(world, v.camera, 320, 180);
    const FrameImages f = shadowFrame(ctx(), world, camera);
    const std::string what = std::string(v.world) + "/" + v.camera;
    const ShadowCheck c = checkShadows(world, f, camera, what.c_str());
    // A meaningful view: mostly surface, with both shadowed and lit sunward faces
    // (more than 5% of them each).
    EXPECT_GT(c.surface, size_t(320 * 180) / 2);
    EXPECT_GT(double(c.cpuShadowed), 0.05 * double(c.cpuShadowed + c.cpuLit)) << what;
    EXPECT_GT(double(c.cpuLit), 0.05 * double(c.cpuShadowed + c.cpuLit)) << what;
}

INSTANTIATE_TEST_SUITE_P(ShippedWorlds, Shadows,
                         ::testing::Values(ShippedView{"rooms", "table"}, ShippedView{"caves", "walk"},
                                           ShippedView{"city", "street"}),
                         [](const auto& info) { return std::string(info.param.world) + "_" + info.param.camera; });

// A floor with a table, a pillar, a thin pole and a wall on it: is voxel (x, y, z)
// of the 48 x 16 x 48 scene solid?
bool floorScene(int x, int y, int z) {
    if (x < 0 || y < 0 || z < 0 || x >= 48 || y >= 16 || z >= 48) return false;
    if (y == 0) return true;                                                 // the floor
    if (y == 7 && x >= 10 && x < 24 && z >= 14 && z < 26) return true;      // a table top
    if (y < 7 && (x == 10 || x == 23) && (z == 14 || z == 25)) return true;  // its legs
    if (y < 12 && x >= 30 && x < 33 && z >= 30 && z < 34) return true;      // a pillar
    if (y < 14 && x == 36 && z == 12) return true;                           // a pole one voxel thick
    return y < 11 && x == 42 && z >= 6 && z < 42;                            // a wall
}

// The floor scene placed three ways: voxel (0, 0, 0) at the origin; voxel (0, 0, 0)
// 1e6 units away (World::fromDense: world positions are large, voxel indices small);
// and with voxel indices near 2e6 (voxel size 0.5), so large indices and their
// tiles' hashes are exercised too.
struct Placement {
    const char* name;
    voxel::World world;
    glm::ivec3 base;  // the index of the scene's voxel (0, 0, 0)
};
std::vector<Placement> floorPlacements(double vs) {
    const glm::ivec3 size(48, 16, 48);
    std::vector<uint8_t> dense(size_t(size.x) * size.y * size.z);
    for (int z = 0; z < size.z; ++z)
        for (int y = 0; y < size.y; ++y)
            for (int x = 0; x < size.x; ++x) dense[(size_t(z) * size.y + y) * size.x + x] = floorScene(x, y, z);
    const glm::ivec3 far(2000003, -1999997, 2000011);
    std::vector<Placement> p;
    p.push_back({"floor at the origin", voxel::World::fromDense(size, dense.data(), vs, glm::dvec3(0.0)), {0, 0, 0}});
    const glm::dvec3 away(1e6 + 0.37, 1e6 - 0.21, -1e6 + 0.13);
    p.push_back({"floor 1e6 away", voxel::World::fromDense(size, dense.data(), vs, away), {0, 0, 0}});
    p.push_back({"floor at indices 2e6", test::makeVoxelWorld(far, far + size - 1, [&](int x, int y, int z) {
                     return floorScene(x - far.x, y - far.y, z - far.z);
                 }, vs, glm::dvec3(0.13, -0.29, 0.41)), far});
    return p;
}

using FarShadows = GpuTest;

TEST_F(FarShadows, MatchTheCpuAsAtTheOrigin) {
    const double vs = 0.5;
    std::vector<std::vector<float>> shadows;
    for (const Placement& p : floorPlacements(vs)) {
        const glm::dvec3 centre = p.world.origin() + (glm::dvec3(p.base) + glm::dvec3(24, 0, 24)) * vs;
        if (p.base != glm::ivec3(0)) EXPECT_GT(glm::length(centre), 1.5e6);
        const Camera camera = makeCamera(test::lookAt(centre + glm::dvec3(-3.13, 16.27, 11.41), centre), 320, 180);
        const FrameImages f = shadowFrame(ctx(), p.world, camera);
        const ShadowCheck c = checkShadows(p.world, f, camera, p.name);
        EXPECT_GT(double(c.cpuShadowed), 0.05 * double(c.cpuShadowed + c.cpuLit)) << p.name;
        EXPECT_GT(double(c.cpuLit), 0.05 * double(c.cpuShadowed + c.cpuLit)) << p.name;
        shadows.push_back(f.shadow);
    }
    for (size_t k = 1; k < shadows.size(); ++k) {
        size_t differ = 0;
        for (size_t i = 0; i < shadows[0].size(); ++i) differ += shadows[0][i] != shadows[k][i];
        std::printf("[ measured ] floor: %zu of %zu shadow pixels differ between placements 0 and %zu\n", differ,
                    shadows[0].size(), k);
        EXPECT_LE(double(differ), kExcusedShare * double(shadows[0].size()));
    }
}

}  // namespace
}  // namespace grotto

