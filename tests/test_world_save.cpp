// Worlds from memory and back to files: fromDense and worldFromGrid, and
// World::save, whose file World::load reads as the same voxels, materials,
// placement and metadata, and which never leaves a half-written target.
#include "common/atomic_file.h"
#include "grotto/error.h"
#include "tests/test_util.h"
#include "voxel/world.h"
#include "voxel/world_from_grid.h"

#include <glm/geometric.hpp>
#include <glm/gtc/quaternion.hpp>
#include <gtest/gtest.h>
#include <openvdb/io/File.h>
#include "voxel/openvdb_grids.h"

#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <fcntl.h>

#include <chrono>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <random>
#include <thread>

extern char** environ;

namespace grotto::voxel {
namespace {

namespace fs = std::filesystem;

std::vector<uint8_t> randomIds(glm::ivec3 size, int palette, double fill, uint32_t seed) {
    std::mt19937 rng(seed);
    std::bernoulli_distribution on(fill);
    std::uniform_int_distribution<int> id(1, palette);
    std::vector<uint8_t> ids(size_t(size.x) * size.y * size.z);
    for (uint8_t& v : ids) v = on(rng) ? uint8_t(id(rng)) : 0;
    return ids;
}

void expectSameWorld(const World& got, const World& want, const std::string& what) {
    IndexBox b = want.bounds().merged(got.bounds());
    ASSERT_FALSE(b.empty()) << what;
    uint64_t wrong = 0;
    for (int x = b.min.x - 1; x <= b.max.x + 1; ++x)
        for (int y = b.min.y - 1; y <= b.max.y + 1; ++y)
            for (int z = b.min.z - 1; z <= b.max.z + 1; ++z) wrong += got.material({x, y, z}) != want.material({x, y, z});
    EXPECT_EQ(wrong, 0u) << what;
    EXPECT_EQ(got.stats().solidVoxels, want.stats().solidVoxels) << what;
    EXPECT_DOUBLE_EQ(got.voxelSize(), want.voxelSize()) << what;
    for (int a = 0; a < 3; ++a) EXPECT_NEAR(got.origin()[a], want.origin()[a], 1e-9 * std::abs(want.origin()[a]) + 1e-12) << what;
}

openvdb::GridBase::Ptr readSavedGrid(const fs::path& path) {
    openvdb::io::File file(path.string());
    file.open(false);
    openvdb::GridBase::Ptr grid = file.readGrid(file.beginName().gridName());
    file.close();
    return grid;
}

TEST(WorldFromDense, EveryVoxelRoundTrips) {
    const glm::ivec3 size(7, 5, 3);
    const std::vector<uint8_t> ids = randomIds(size, 8, 0.6, 1);
    const World w = World::fromDense(size, ids.data(), 0.25, {-3.0, 1.5, 100.0});
    EXPECT_DOUBLE_EQ(w.voxelSize(), 0.25);
    EXPECT_NEAR(w.origin().x, -3.0, 1e-12);
    EXPECT_NEAR(w.origin().z, 100.0, 1e-12);
    size_t i = 0;
    for (int z = 0; z < size.z; ++z)
        for (int y = 0; y < size.y; ++y)
            for (int x = 0; x < size.x; ++x, ++i) ASSERT_EQ(w.material({x, y, z}), ids[i]) << x << " " << y << " " << z;
    EXPECT_EQ(w.material({-1, 0, 0}), 0);
    EXPECT_EQ(w.material({7, 0, 0}), 0);
    // Voxel (0,0,0) spans [origin, origin + voxelSize): a ray from below meets it there.
    const World one = World::fromDense({1, 1, 1}, std::vector<uint8_t>{3}.data(), 2.0, {10, 20, 30});
    const auto hit = one.raycast({11.0, 0.0, 31.0}, {0, 1, 0}, 100.0);
    ASSERT_TRUE(hit.has_value());
    EXPECT_NEAR(hit->distance, 20.0, 1e-9);
    EXPECT_EQ(one.material({0, 0, 0}), 3);
}

TEST(WorldFromDense, BadInputIsRefused) {
    const std::vector<uint8_t> ids(8, 1);
    const double nan = std::numeric_limits<double>::quiet_NaN();
    EXPECT_THROW(World::fromDense({0, 2, 2}, ids.data(), 1.0, {}), Error);
    EXPECT_THROW(World::fromDense({2, -2, 2}, ids.data(), 1.0, {}), Error);
    EXPECT_THROW(World::fromDense({2, 2, kMaxVoxelIndex + 1}, ids.data(), 1.0, {}), Error);
    EXPECT_THROW(World::fromDense({2, 2, 2}, nullptr, 1.0, {}), Error);
    EXPECT_THROW(World::fromDense({2, 2, 2}, ids.data(), 0.0, {}), Error);
    EXPECT_THROW(World::fromDense({2, 2, 2}, ids.data(), nan, {}), Error);
    EXPECT_THROW(World::fromDense({2, 2, 2}, ids.data(), 1.0, {nan, 0, 0}), Error);
    EXPECT_THROW(World::fromDense({2, 2, 2}, ids.data(), 1.0, {0, 0, 1e13}), Error);
    std::vector<uint8_t> beyond = ids;
    beyond[5] = uint8_t(defaultMaterials().size() + 1);
    try {
        World::fromDense({2, 2, 2}, beyond.data(), 1.0, {});
        ADD_FAILURE() << "an id beyond the palette was accepted";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("(1, 0, 1)"), std::string::npos) << e.what();
    }
    // A palette of its own: ids up to its size only.
    WorldDesc two;
    two.materials.resize(2);
    EXPECT_THROW(World::fromDense({2, 2, 2}, std::vector<uint8_t>(8, 3).data(), 1.0, {}, two), Error);
    EXPECT_NO_THROW(World::fromDense({2, 2, 2}, std::vector<uint8_t>(8, 2).data(), 1.0, {}, two));
}

TEST(WorldFromGrid, CopiesTheGridAndChecksIt) {
    openvdb::initialize();
    auto grid = openvdb::Int32Grid::create(0);
    grid->tree().setValueOn({1, 2, 3}, 2);
    World w = worldFromGrid(*grid);
    grid->tree().setValueOn({4, 4, 4}, 1);  // the game's later change stays its own
    EXPECT_EQ(w.material({1, 2, 3}), 2);
    EXPECT_EQ(w.material({4, 4, 4}), 0);
    w.apply(Edit::setVoxel({1, 2, 3}, 0));
    EXPECT_EQ(grid->tree().getValue({1, 2, 3}), 2);
    grid->tree().setValueOn({0, 0, 0}, 99);
    EXPECT_THROW(worldFromGrid(*grid), Error);
    auto vec = openvdb::Vec3SGrid::create();
    EXPECT_THROW(worldFromGrid(*vec), Error);
}

TEST(WorldSave, Int32WorldRoundTripsWithMetadata) {
    openvdb::initialize();
    grotto::test::ScratchDir dir;
    const glm::ivec3 size(40, 20, 33);
    const std::vector<uint8_t> ids = randomIds(size, 8, 0.4, 2);
    const World source = World::fromDense(size, ids.data(), 0.125, {-7.5, 3.0, 1e5});
    source.save(dir / "a.vdb");
    // Through worldFromGrid, to carry a name and metadata as a file's grid would.
    openvdb::GridBase::Ptr named = readSavedGrid(dir / "a.vdb");
    named->setName("terrain");
    named->insertMeta("author", openvdb::StringMetadata("grotto tests"));
    named->insertMeta("grotto_seed", openvdb::Int64Metadata(42));
    World w = worldFromGrid(*named);
    w.apply(Edit::carveSphere(w.origin() + glm::dvec3(2.0, 1.0, 2.0), 0.6));
    w.apply(Edit::fillBox({{-3, -3, -3}, {2, 2, 2}}, 5));
    w.save(dir / "b.vdb");
    const World back = World::load(dir / "b.vdb");
    expectSameWorld(back, w, "int32 world");
    EXPECT_TRUE(back.editLog().empty());
    const openvdb::GridBase::Ptr saved = readSavedGrid(dir / "b.vdb");
    EXPECT_EQ(saved->getName(), "terrain");
    EXPECT_TRUE(saved->isType<openvdb::Int32Grid>());
    EXPECT_EQ(saved->metaValue<std::string>("author"), "grotto tests");
    EXPECT_EQ(saved->metaValue<int64_t>("grotto_seed"), 42);
}

// A save onto a full disk throws an internal error naming the file and the
// reason (it once read "KeyError: Map"), and leaves the old file whole.
TEST(WorldSave, AFullDiskIsReportedAndLeavesTheOldFile) {
    grotto::test::SmallDisk disk(1 << 20);
    if (!disk.mounted()) GTEST_SKIP() << disk.reason();
    const glm::ivec3 size(40, 40, 40);
    const World small = World::fromDense({2, 2, 2}, std::vector<uint8_t>(8, 1).data(), 1.0, {});
    small.save(disk / "world.vdb");
    disk.fillLeaving(8192);
    const World large = World::fromDense(size, randomIds(size, 8, 0.5, 3).data(), 1.0, {});
    try {
        large.save(disk / "world.vdb");
        FAIL() << "saved onto a full disk";
    } catch (const Error& e) {
        EXPECT_EQ(e.kind(), Error::Kind::Internal) << e.what();
        EXPECT_EQ(e.where(), (disk / "world.vdb").string());
        EXPECT_NE(std::string(e.what()).find("No space left on device"), std::string::npos) << e.what();
    }
    expectSameWorld(World::load(disk / "world.vdb"), small, "the file a failed save was replacing");
    for (const auto& entry : fs::directory_iterator(disk.path()))
        EXPECT_EQ(entry.path().filename().string().find(".tmp"), std::string::npos) << entry.path();
}

TEST(WorldSave, MaskWorldsKeepTheirKindUnlessPainted) {
    openvdb::initialize();
    grotto::test::ScratchDir dir;
    for (const bool boolGrid : {false, true}) {
        openvdb::GridBase::Ptr grid;
        if (boolGrid) {
            auto g = openvdb::BoolGrid::create(false);
            g->fill(openvdb::CoordBBox({-5, 0, -5}, {20, 3, 9}), true, true);
            g->tree().addTile(1, openvdb::Coord(32, 0, 0), true, true);
            grid = g;
        } else {
            auto g = openvdb::MaskGrid::create();
            g->fill(openvdb::CoordBBox({-5, 0, -5}, {20, 3, 9}), true, true);
            grid = g;
        }
        grid->setTransform(openvdb::math::Transform::createLinearTransform(0.5));
        grid->setName("solid");
        World w = worldFromGrid(*grid);
        w.apply(Edit::carveBox({{0, 2, 0}, {3, 3, 3}}));
        const std::string kind = boolGrid ? "bool" : "mask";
        w.save(dir / "plain.vdb");
        expectSameWorld(World::load(dir / "plain.vdb"), w, kind + " world");
        EXPECT_EQ(readSavedGrid(dir / "plain.vdb")->type(), grid->type()) << kind;
        // Painted: the materials need an int32 grid to round-trip.
        w.apply(Edit::paintSphere(w.origin() + glm::dvec3(5.0, 1.0, 2.0), 1.5, 4));
        w.save(dir / "painted.vdb");
        const World painted = World::load(dir / "painted.vdb");
        expectSameWorld(painted, w, "painted " + kind + " world");
        EXPECT_EQ(painted.material({10, 1, 4}), 4);
        EXPECT_TRUE(readSavedGrid(dir / "painted.vdb")->isType<openvdb::Int32Grid>()) << kind;
        // Undone, the paint leaves no material grid behind.
        w.undo();
        w.save(dir / "undone.vdb");
        EXPECT_EQ(readSavedGrid(dir / "undone.vdb")->type(), grid->type()) << kind;
    }
}

// Everything a world file says besides its grid, set away from every default.
WorldDesc everySetting(const fs::path& dir) {
    WorldDesc d;
    d.materials = {{"basalt", {0.1f, 0.12f, 0.15f}, 0.9f}, {"ochre", {0.8f, 0.5f, 0.1f}, 1.0f}, {"chalk", {0.95f, 0.94f, 0.9f}, 0.35f}};
    Lighting& l = d.lighting;
    l.sunDirection = glm::normalize(glm::vec3(-0.3f, 0.6f, 0.7f));
    l.sunColor = {0.9f, 0.7f, 0.5f};
    l.sunIntensity = 2.5f;
    l.sunShadows = false;
    l.sunAngle = 3.5f;
    l.ambientColor = {0.2f, 0.3f, 0.4f};
    l.ambientIntensity = 0.15f;
    l.skyZenith = {0.1f, 0.2f, 0.6f};
    l.skyHorizon = {0.9f, 0.6f, 0.4f};
    l.exposure = 1.7f;
    l.toneMap = ToneMap::Linear;
    d.ao = {.method = "voxel", .quality = "low", .radius = 2.5, .falloffRange = 0.4, .thinOccluder = 0.3,
            .slices = 2, .temporalHistory = 8, .rays = 5};
    d.detail = {.lodBias = 3.0, .occlusionCulling = false};
    d.cameras["door"] = {.position = {1, 2, 3}, .target = {4, 1, -2}, .fovDegrees = 35, .nearPlane = 0.01, .farPlane = 500};
    d.cameras["attic"] = {.position = {-5, 9, 0.5}, .target = {0, 0, 0}, .fovDegrees = 90, .nearPlane = 0.2};
    d.defaultCamera = "door";
    CameraPathDesc look;
    look.keys = {{.time = 0, .position = {0, 5, 9}, .target = glm::dvec3(2, 0, 2)},
                 {.time = 1.25, .position = {3, 5, 9}, .target = glm::dvec3(2, 1, 2), .fovDegrees = 40.0},
                 {.time = 2, .position = {8, 3, 1}, .rotation = glm::normalize(glm::dquat(0.9, 0.1, 0.4, 0.0)), .cut = true}};
    look.constantSpeed = true;
    look.fovDegrees = 70;
    look.nearPlane = 0.02;
    look.farPlane = 900;
    look.edits = {{.time = 0.5, .edit = Edit::carveSphere({2, 1, 2}, 1.5)},
                  {.time = 0.5, .edit = Edit::fillBox({{0, 0, 0}, {3, 1, 2}}, 3)},
                  {.time = 1.5, .edit = Edit::setVoxel({5, 1, 5}, 2)},
                  {.time = 1.75, .edit = Edit::paintSphere({1, 0, 1}, 2.0, 1)}};
    d.paths["look"] = look;
    d.paths["plain"] = {.keys = {{.time = 0, .position = {9, 9, 9}, .target = glm::dvec3(0.0)},
                                 {.time = 3, .position = {-9, 9, 9}, .target = glm::dvec3(0.0)}}};
    const glm::dquat quarter = glm::angleAxis(glm::radians(90.0), glm::dvec3(0, 1, 0));
    d.objects.push_back({.name = "crate", .material = 2, .generator = "box", .generatorOptions = {.voxelSize = 0.5},
                         .boxSize = {2, 3, 4}, .pivot = {1, 0, 1},
                         .keys = {{.time = 0, .position = {3, 1, 3}}, {.time = 2, .position = {5, 1, 3}, .rotation = quarter}}});
    d.objects.push_back({.name = "statue", .gridFile = dir / "models" / "statue.vdb", .gridName = "shape",
                         .rule = SolidRule::Fog, .threshold = 0.25, .material = 3, .keys = {{.time = 0, .position = {-2, 0, 4}}}});
    d.objects.push_back({.name = "rubble", .generator = "caves", .generatorOptions = {.seed = 7, .size = 16, .voxelSize = 0.25},
                         .keys = {{.time = 1, .position = {0, 0, -3}, .rotation = quarter}}});
    d.memoryBudgetBytes = size_t(640) << 20;
    return d;
}

void expectSameRotation(const glm::dquat& got, const glm::dquat& want, const std::string& what) {
    EXPECT_NEAR(std::abs(glm::dot(got, want)), 1.0, 1e-12) << what;
}

void expectSameSettings(const WorldDesc& got, const WorldDesc& want) {
    ASSERT_EQ(got.materials.size(), want.materials.size());
    for (size_t i = 0; i < want.materials.size(); ++i) {
        EXPECT_EQ(got.materials[i].name, want.materials[i].name);
        EXPECT_EQ(got.materials[i].albedo, want.materials[i].albedo) << want.materials[i].name;
        EXPECT_EQ(got.materials[i].ao, want.materials[i].ao) << want.materials[i].name;
    }
    const Lighting &a = got.lighting, &b = want.lighting;
    for (int k = 0; k < 3; ++k) EXPECT_NEAR(a.sunDirection[k], b.sunDirection[k], 1e-6);  // normalised again on load
    EXPECT_EQ(a.sunColor, b.sunColor);
    EXPECT_EQ(a.sunIntensity, b.sunIntensity);
    EXPECT_EQ(a.sunShadows, b.sunShadows);
    EXPECT_EQ(a.sunAngle, b.sunAngle);
    EXPECT_EQ(a.ambientColor, b.ambientColor);
    EXPECT_EQ(a.ambientIntensity, b.ambientIntensity);
    EXPECT_EQ(a.skyZenith, b.skyZenith);
    EXPECT_EQ(a.skyHorizon, b.skyHorizon);
    EXPECT_EQ(a.exposure, b.exposure);
    EXPECT_EQ(a.toneMap, b.toneMap);
    const AoDesc &x = got.ao, &y = want.ao;
    EXPECT_EQ(x.method, y.method);
    EXPECT_EQ(x.quality, y.quality);
    EXPECT_TRUE(x.radius == y.radius && x.radiusMultiplier == y.radiusMultiplier && x.falloffRange == y.falloffRange &&
                x.sampleDistributionPower == y.sampleDistributionPower && x.thinOccluder == y.thinOccluder &&
                x.finalValuePower == y.finalValuePower && x.depthMipOffset == y.depthMipOffset &&
                x.strength == y.strength && x.denoiseBlurBeta == y.denoiseBlurBeta && x.maxDistance == y.maxDistance);
    EXPECT_TRUE(x.slices == y.slices && x.steps == y.steps && x.denoisePasses == y.denoisePasses &&
                x.temporalHistory == y.temporalHistory && x.rays == y.rays);
    EXPECT_EQ(got.detail.lodBias, want.detail.lodBias);
    EXPECT_EQ(got.detail.occlusionCulling, want.detail.occlusionCulling);
    ASSERT_EQ(got.cameras.size(), want.cameras.size());
    for (const auto& [name, c] : want.cameras) {
        ASSERT_TRUE(got.cameras.count(name)) << name;
        const CameraDesc& g = got.cameras.at(name);
        EXPECT_TRUE(g.position == c.position && g.target == c.target && g.fovDegrees == c.fovDegrees &&
                    g.nearPlane == c.nearPlane && g.farPlane == c.farPlane) << name;
    }
    EXPECT_EQ(got.defaultCamera, want.defaultCamera);
    ASSERT_EQ(got.paths.size(), want.paths.size());
    for (const auto& [name, p] : want.paths) {
        ASSERT_TRUE(got.paths.count(name)) << name;
        const CameraPathDesc& g = got.paths.at(name);
        EXPECT_TRUE(g.constantSpeed == p.constantSpeed && g.fovDegrees == p.fovDegrees && g.nearPlane == p.nearPlane &&
                    g.farPlane == p.farPlane) << name;
        ASSERT_EQ(g.keys.size(), p.keys.size()) << name;
        for (size_t i = 0; i < p.keys.size(); ++i) {
            const PathKey &k = g.keys[i], &w = p.keys[i];
            EXPECT_TRUE(k.time == w.time && k.position == w.position && k.target == w.target &&
                        k.fovDegrees == w.fovDegrees && k.cut == w.cut) << name << " key " << i;
            ASSERT_EQ(k.rotation.has_value(), w.rotation.has_value()) << name << " key " << i;
            if (w.rotation) expectSameRotation(*k.rotation, *w.rotation, name);
        }
        ASSERT_EQ(g.edits.size(), p.edits.size()) << name;
        for (size_t i = 0; i < p.edits.size(); ++i) {
            const Edit &e = g.edits[i].edit, &f = p.edits[i].edit;
            EXPECT_EQ(g.edits[i].time, p.edits[i].time);
            EXPECT_EQ(describe(e), describe(f));
            EXPECT_TRUE(e.op == f.op && e.shape == f.shape && e.material == f.material) << describe(f);
            if (f.shape == Edit::Shape::Sphere) EXPECT_TRUE(e.centre == f.centre && e.radius == f.radius) << describe(f);
            else EXPECT_TRUE(e.box.min == f.box.min && e.box.max == f.box.max) << describe(f);
        }
    }
    ASSERT_EQ(got.objects.size(), want.objects.size());
    auto same = [](const fs::path& p, const fs::path& q) { return fs::absolute(p).lexically_normal() == fs::absolute(q).lexically_normal(); };
    for (size_t i = 0; i < want.objects.size(); ++i) {
        const ObjectDesc &o = got.objects[i], &w = want.objects[i];
        EXPECT_EQ(o.name, w.name);
        EXPECT_EQ(o.generator, w.generator) << w.name;
        if (w.generator.empty()) {
            EXPECT_TRUE(same(o.gridFile, w.gridFile)) << o.gridFile << " for " << w.gridFile;
            EXPECT_TRUE(o.gridName == w.gridName && o.rule == w.rule && o.threshold == w.threshold) << w.name;
        }
        EXPECT_EQ(o.material, w.material) << w.name;
        EXPECT_EQ(o.boxSize, w.boxSize) << w.name;
        EXPECT_TRUE(o.generatorOptions.seed == w.generatorOptions.seed && o.generatorOptions.size == w.generatorOptions.size &&
                    o.generatorOptions.voxelSize == w.generatorOptions.voxelSize) << w.name;
        EXPECT_EQ(o.pivot, w.pivot) << w.name;
        ASSERT_EQ(o.keys.size(), w.keys.size()) << w.name;
        for (size_t k = 0; k < w.keys.size(); ++k) {
            EXPECT_TRUE(o.keys[k].time == w.keys[k].time && o.keys[k].position == w.keys[k].position) << w.name;
            expectSameRotation(o.keys[k].rotation, w.keys[k].rotation, w.name);
        }
    }
    EXPECT_EQ(got.memoryBudgetBytes, want.memoryBudgetBytes);
}

// A saved world is the same world: its voxels as edited, and beside them a world
// file with the palette, lighting, AO, detail, cameras, paths and objects.
TEST(WorldSave, AWorldFileBesideTheGridKeepsEverySetting) {
    openvdb::initialize();
    grotto::test::ScratchDir dir;
    const glm::ivec3 size(12, 6, 10);
    const WorldDesc desc = everySetting(dir.path);
    World w = World::fromDense(size, randomIds(size, 3, 0.5, 9).data(), 0.5, {1.0, -2.0, 3.5}, desc);
    w.apply(Edit::carveSphere(w.origin() + glm::dvec3(3.0, 1.5, 2.5), 1.2));
    fs::create_directories(dir / "saved");
    w.save(dir / "saved" / "house.vdb");
    ASSERT_TRUE(fs::exists(dir / "saved" / "house.json")) << "the world file beside the grid";
    const World back = World::load(dir / "saved" / "house.json");
    expectSameWorld(back, w, "saved world");
    expectSameSettings(back.desc(), desc);
    EXPECT_EQ(back.desc().gridFile, dir / "saved" / "house.vdb");
    // The grid alone is still a bare .vdb: the same voxels, default settings.
    expectSameWorld(World::load(dir / "saved" / "house.vdb"), w, "the grid alone");

    // Settings of the caller's (the viewer's panel, the engine's lighting), named by the .json.
    WorldDesc changed = desc;
    changed.lighting.exposure = 0.25f;
    changed.defaultCamera.clear();  // framed from the bounds, although there are cameras
    w.save(dir / "changed.json", changed);
    const World other = World::load(dir / "changed.json");
    expectSameWorld(other, w, "saved by its .json");
    expectSameSettings(other.desc(), changed);
    // Saved again from where it was loaded: nothing drifts.
    other.save(dir / "again.json");
    expectSameSettings(World::load(dir / "again.json").desc(), changed);
}

TEST(WorldSave, AUniformMaterialOtherThanOneIsKept) {
    openvdb::initialize();
    grotto::test::ScratchDir dir;
    auto grid = openvdb::MaskGrid::create();
    grid->fill(openvdb::CoordBBox({0, 0, 0}, {9, 9, 9}), true, true);
    WorldDesc desc;
    desc.material = 6;
    const World w = worldFromGrid(*grid, desc);
    ASSERT_EQ(w.material({1, 1, 1}), 6);
    w.save(dir / "six.vdb");
    expectSameWorld(World::load(dir / "six.vdb"), w, "material 6 world");
    EXPECT_THROW(w.save(dir / "six.png"), Error);
    EXPECT_THROW(w.save(dir / "missing" / "six.vdb"), Error);
}

// Run by InterruptedSaveLeavesTheOldFile in a child process: saves a large
// world to the path it is given, for the parent to kill mid-save.
TEST(WorldSave, ChildSavesALargeWorld) {
    const char* target = std::getenv("GROTTO_TEST_SAVE_TARGET");
    if (!target) GTEST_SKIP() << "a helper of InterruptedSaveLeavesTheOldFile";
    // Large enough that its save outlasts the parent's look for the temporary
    // file many times over (smaller under the sanitizers, which make it slower).
    const glm::ivec3 size(grotto::test::underSanitizers(256, 160));
    const World big = World::fromDense(size, randomIds(size, 8, 0.5, 3).data(), 1.0, {});
    big.save(target);
}

TEST(WorldSave, InterruptedSaveLeavesTheOldFile) {
    grotto::test::ScratchDir dir;
    const fs::path target = dir / "world.vdb";
    const glm::ivec3 size(12, 12, 12);
    const World old = World::fromDense(size, randomIds(size, 3, 0.5, 4).data(), 1.0, {});
    old.save(target);
    // A child saves over it and is killed once its temporary file exists.
    const std::string filter = "--gtest_filter=WorldSave.ChildSavesALargeWorld", env = "GROTTO_TEST_SAVE_TARGET=" + target.string();
    std::vector<char*> argv{const_cast<char*>("test_voxel"), const_cast<char*>(filter.c_str()), nullptr};
    std::vector<char*> envp;
    for (char** e = environ; *e; ++e) envp.push_back(*e);
    envp.push_back(const_cast<char*>(env.c_str()));
    envp.push_back(nullptr);
    posix_spawn_file_actions_t quiet;
    posix_spawn_file_actions_init(&quiet);
    posix_spawn_file_actions_addopen(&quiet, 1, "/dev/null", O_WRONLY, 0);
    pid_t child = 0;
    ASSERT_EQ(posix_spawn(&child, "/proc/self/exe", &quiet, nullptr, argv.data(), envp.data()), 0);
    posix_spawn_file_actions_destroy(&quiet);
    auto temporary = [&] {
        for (const auto& entry : fs::directory_iterator(dir.path))
            if (entry.path().filename().string().starts_with(".world.tmp")) return true;
        return false;
    };
    int status = 0;
    bool seen = false;
    for (auto start = std::chrono::steady_clock::now(); std::chrono::steady_clock::now() - start < std::chrono::minutes(5);) {
        if ((seen = temporary())) break;
        if (waitpid(child, &status, WNOHANG) == child) break;
        std::this_thread::sleep_for(std::chrono::microseconds(200));
    }
    if (seen) {
        kill(child, SIGKILL);
        waitpid(child, &status, 0);
    }
    ASSERT_TRUE(seen) << "the child ended (status " << status << ") before its save began";
    ASSERT_TRUE(WIFSIGNALED(status)) << "the child finished its save before it was killed";
    expectSameWorld(World::load(target), old, "the file a killed save was replacing");
    // The temporary stays hidden under its own name until a later run clears it.
    EXPECT_TRUE(temporary());
    EXPECT_EQ(removeAbandonedTemporaries(dir.path, [](const std::string& name) { return name == "world.vdb"; }), 1);
    EXPECT_FALSE(temporary());
}

}  // namespace
}  // namespace grotto::voxel
