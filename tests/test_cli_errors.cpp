// Bad input gets one clear line naming the file and field, exit code 2 and no
// output file; the CLI runs with the validation layer on. (The commands that run
// paths and references: test_cli_runs.cpp.)
#include "tests/cli_fixture.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>
#include "voxel/openvdb_grids.h"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <map>
#include <random>

namespace grotto {
namespace {

namespace fs = std::filesystem;
using test::CliErrors;
using test::runGrotto;

TEST_F(CliErrors, GoodWorldRenders) {
    const test::RunResult r = runGrotto(render(good_));
    EXPECT_EQ(r.exitCode, 0) << r.err;
    EXPECT_TRUE(fs::exists(out()));
}

TEST_F(CliErrors, MissingVdb) { expectRefused(render(dir_ / "nope.vdb"), "nope.vdb", out()); }

TEST_F(CliErrors, TruncatedVdb) {
    const auto size = fs::file_size(good_);
    fs::copy_file(good_, dir_ / "cut.vdb");
    fs::resize_file(dir_ / "cut.vdb", size / 2);
    expectRefused(render(dir_ / "cut.vdb"), "cut.vdb", out());
}

// Found by fuzz_vdb: one byte of the shipped rooms grid changed, inside the grid's
// data, so OpenVDB throws partway through reading it and leaks the node it was
// reading. Refused like any damaged file; read in the child, the leak stays there.
TEST_F(CliErrors, VdbDamagedInsideAGrid) {
    std::ifstream in(test::worldsDir() / "rooms.vdb", std::ios::binary);
    std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    ASSERT_GT(bytes.size(), 71940u);
    bytes[71940] = 4;
    expectRefused(render(writeText("damaged.vdb", bytes)), "damaged.vdb", out());
}

TEST_F(CliErrors, RandomBytesVdb) {
    std::mt19937 rng(5);
    std::string bytes(4096, '\0');
    for (char& c : bytes) c = char(rng());
    expectRefused(render(writeText("noise.vdb", bytes)), "noise.vdb", out());
}

TEST_F(CliErrors, VdbWithoutGrids) {
    writeGrids(dir_ / "empty.vdb", {});
    expectRefused(render(dir_ / "empty.vdb"), "no grids", out());
}

TEST_F(CliErrors, WrongGridName) {
    const auto world = writeText("w.json", R"({"grid": {"file": "good.vdb", "name": "density"}})");
    expectRefused(render(world), "no grid named 'density'", out());
}

TEST_F(CliErrors, UnsupportedGridType) {
    auto vec = openvdb::Vec3SGrid::create();
    vec->setName("velocity");
    vec->tree().setValueOn(openvdb::Coord(0), openvdb::Vec3s(1));
    writeGrids(dir_ / "vec.vdb", {vec});
    expectRefused(render(dir_ / "vec.vdb"), "unsupported grid type", out());
}

TEST_F(CliErrors, NonUniformTransform) {
    auto grid = openvdb::BoolGrid::create(false);
    grid->setName("solid");
    grid->tree().setValueOn(openvdb::Coord(0), true);
    grid->setTransform(openvdb::math::Transform::createLinearTransform(openvdb::Mat4R(
        2, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1)));
    writeGrids(dir_ / "stretched.vdb", {grid});
    expectRefused(render(dir_ / "stretched.vdb"), "non-uniform voxel size", out());
}

TEST_F(CliErrors, GridOverMemoryBudget) {
    auto big = openvdb::FloatGrid::create(0.0f);
    big->setName("density");
    big->setGridClass(openvdb::GRID_FOG_VOLUME);
    big->denseFill(openvdb::CoordBBox(openvdb::Coord(0), openvdb::Coord(127)), 1.0f, true);
    writeGrids(dir_ / "big.vdb", {big});
    const auto world = writeText("b.json", R"({"grid": {"file": "big.vdb"}, "memory_budget_mib": 1})");
    expectRefused(render(world), "memory budget", out());
}

// One active tile is a few bytes in OpenVDB but 2^27 full bricks here: refused with
// the estimate before any brick is made (not by running out of memory).
TEST_F(CliErrors, HugeActiveTileOverMemoryBudget) {
    auto grid = openvdb::MaskGrid::create(false);
    grid->setName("solid");
    grid->tree().addTile(3, openvdb::Coord(0), true, true);  // a root child: 4096^3 voxels
    writeGrids(dir_ / "tile.vdb", {grid});
    expectRefused(render(dir_ / "tile.vdb"), "134217728 bricks", out());
}

// GROTTO_SHADER_DIR loads shaders from a directory instead of the built-in ones: a
// missing or malformed file there is bad input, named, not a bare driver error.
TEST_F(CliErrors, ShaderDirectoryWithoutUsableShaders) {
    const fs::path shaders = dir_ / "shaders";
    fs::create_directory(shaders);
    const std::string world = (test::worldsDir() / "rooms.json").string();
    expectRefused(render(world), "gbuffer.vert.spv", out(), "GROTTO_SHADER_DIR=" + shaders.string());
    std::ofstream(shaders / "gbuffer.vert.spv") << "not SPIR-V at all";
    expectRefused(render(world), "is not SPIR-V", out(), "GROTTO_SHADER_DIR=" + shaders.string());
}

TEST_F(CliErrors, MalformedJson) {
    expectRefused(render(writeText("bad.json", R"({"grid": {"file": "good.vdb"},)")), "malformed JSON", out());
}

TEST_F(CliErrors, UnknownField) {
    const auto world = writeText("u.json", R"({"grid": {"file": "good.vdb", "rule": "mask"}, "lighting": {"sun": {"colour": [1,1,1]}}})");
    expectRefused(render(world), "lighting.sun.colour", out());
}

TEST_F(CliErrors, WrongFieldType) {
    const auto world = writeText("t.json", R"({"grid": {"file": "good.vdb"}, "cameras": {"a": {"position": [0, 1], "target": [0, 0, 0]}}})");
    expectRefused(render(world), "cameras.a.position", out());
}

TEST_F(CliErrors, UnwritableOutput) {
    expectRefused("render " + good_.string() + " --size 8x8 -o " + (dir_ / "missing-dir" / "x.png").string(),
                  "missing-dir", dir_ / "missing-dir" / "x.png");
    writeText("file", "not a directory");
    expectRefused("render " + good_.string() + " --size 8x8 -o " + (dir_ / "file" / "x.png").string(), "file",
                  dir_ / "x.png");
}

TEST_F(CliErrors, NonsenseSettings) {
    expectRefused("render " + good_.string() + " --size 0x16 -o " + out().string(), "--size", out());
    // Sides read as 64-bit would wrap to 1 in 32 bits; a sign is not a digit.
    for (const char* size : {"4294967297x1", "1x4294967297", "18446744073709551617x8", "8x-1", "8x+8", " 8x8", "8x8x8"})
        expectRefused("render " + good_.string() + " --size \"" + size + "\" -o " + out().string(),
                      "--size: '" + std::string(size) + "' is not a valid size", out());
    expectRefused("render " + good_.string() + " --size 8x8 -o " + (dir_ / "out.tga").string(), ".tga",
                  dir_ / "out.tga");
    expectRefused("mkworld nonsense -o " + (dir_ / "n.vdb").string(), "nonsense", dir_ / "n.vdb");
}

TEST_F(CliErrors, ExportMeshWritesExactlyThePly) {
    const test::RunResult r = runGrotto("export-mesh " + good_.string() + " -o " + (dir_ / "m.ply").string());
    EXPECT_EQ(r.exitCode, 0) << r.err;
    EXPECT_TRUE(fs::exists(dir_ / "m.ply"));
    expectRefused("export-mesh " + (dir_ / "gone.vdb").string() + " -o " + (dir_ / "n.ply").string(), "gone.vdb",
                  dir_ / "n.ply");
}

}  // namespace
}  // namespace grotto

namespace grotto {
namespace {

TEST_F(CliErrors, NoVulkanDeviceNamesThePackage) {
    expectRefused(render(good_), "mesa-vulkan-drivers", out(),
                  // No device means no validation either; the loader would report its own search.
                  "GROTTO_VALIDATION=0 VK_DRIVER_FILES=/nonexistent/icd.json VK_ICD_FILENAMES=/nonexistent/icd.json");
}

TEST_F(CliErrors, UnknownDeviceNameListsDevices) {
    expectRefused(render(good_), "GROTTO_DEVICE", out(), "GROTTO_DEVICE=no-such-gpu");
}

TEST_F(CliErrors, ExrWithAovsCarriesChannelsAndCamera) {
    const fs::path exr = dir_ / "frame.exr";
    const auto world = writeText("cam.json", R"({"grid": {"file": "good.vdb"},
        "cameras": {"c": {"position": [8, 10, 30], "target": [8, 0, 8]}}})");
    const test::RunResult r = runGrotto("render " + world.string() + " --size 64x48 --aov -o " + exr.string());
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const std::optional<ImageFile> in = readImage(exr);
    ASSERT_TRUE(in);
    const ImageFile& spec = *in;
    const std::vector<std::string> expected = {"R", "G", "B", "A", "Z", "N.x", "N.y", "N.z",
                                               "albedo.R", "albedo.G", "albedo.B", "AO", "AO_raw", "AO_spatial", "AO_temporal", "AO_history", "edges", "shadow"};
    std::vector<std::string> names = spec.channelNames;
    std::sort(names.begin(), names.end());
    std::vector<std::string> sorted = expected;
    std::sort(sorted.begin(), sorted.end());
    EXPECT_EQ(names, sorted);
    ASSERT_TRUE(spec.worldToCamera);
    ASSERT_TRUE(spec.worldToScreen);
    // The camera sits at (8, 10, 30): worldtocamera takes it to the origin.
    const float* m = spec.worldToCamera->data();
    const float p[4] = {8, 10, 30, 1};
    for (int col = 0; col < 3; ++col) {
        float v = 0;
        for (int row = 0; row < 4; ++row) v += p[row] * m[row * 4 + col];
        EXPECT_NEAR(v, 0.0f, 1e-4f);
    }
    const std::vector<float>& px = spec.floats;
    ASSERT_EQ(px.size(), size_t(spec.width) * spec.height * spec.channels());
    const int z = spec.channelIndex("Z"), ny = spec.channelIndex("N.y");
    // The centre pixel looks at the floor's top: up normal, depth along the view axis.
    const size_t centre = (size_t(spec.height / 2) * spec.width + spec.width / 2) * spec.channels();
    EXPECT_FLOAT_EQ(px[centre + ny], 1.0f);
    EXPECT_GT(px[centre + z], 5.0f);
    EXPECT_LT(px[centre + z], 40.0f);
    for (float v : px) ASSERT_TRUE(std::isfinite(v));
}

}  // namespace
}  // namespace grotto

namespace grotto {
namespace {

TEST_F(CliErrors, RuleThatDoesNotFitTheGrid) {
    auto ints = openvdb::Int32Grid::create(0);
    ints->setName("material");
    ints->tree().setValueOn(openvdb::Coord(0), 1);
    writeGrids(dir_ / "ints.vdb", {ints});
    const auto world = writeText("r.json", R"({"grid": {"file": "ints.vdb", "rule": "mask"}})");
    expectRefused(render(world), "does not apply", out());
}

TEST_F(CliErrors, NumberOutOfRange) {
    const auto world = writeText("n.json", R"({"grid": {"file": "good.vdb", "threshold": 1e400}})");
    expectRefused(render(world), "n.json", out());
}

}  // namespace
}  // namespace grotto

namespace grotto {
namespace {

TEST_F(CliErrors, NonsenseAoSettings) {
    expectRefused(render(good_) + " --radius -1", "--radius", out());
    expectRefused(render(good_) + " --thin-occluder 0.9", "--thin-occluder", out());
    expectRefused(render(good_) + " --denoise 9", "--denoise", out());
    expectRefused(render(good_) + " --quality extreme", "--quality", out());
    expectRefused(render(good_) + " --max-distance -5", "--max-distance", out());
    expectRefused(render(good_) + " --radius-multiplier 9", "--radius-multiplier", out());
    expectRefused(render(good_) + " --quality custom --slices 0", "--slices", out());
    expectRefused(render(good_) + " --temporal -1", "--temporal", out());
    const auto world = writeText("ao.json", R"({"grid": {"file": "good.vdb"}, "ao": {"thin_occluder": 0.9}})");
    expectRefused(render(world), "ao.thin_occluder", out());
    const auto preset = writeText("q.json", R"({"grid": {"file": "good.vdb"}, "ao": {"quality": "extreme"}})");
    expectRefused(render(preset), "ao.quality", out());
    const auto far = writeText("far.json", R"({"grid": {"file": "good.vdb"}, "ao": {"max_distance": -5}})");
    expectRefused(render(far), "ao.max_distance", out());
    const auto sun = writeText("sun.json", R"({"grid": {"file": "good.vdb"}, "lighting": {"sun": {"angle": 45}}})");
    expectRefused(render(sun), "lighting.sun.angle", out());
    // A count is a whole number: 2.7 slices is refused, not truncated to 2.
    const auto slices = writeText("slices.json", R"({"grid": {"file": "good.vdb"}, "ao": {"slices": 2.7}})");
    expectRefused(render(slices), "field 'ao.slices': value 2.7 is not a whole number", out());
}

TEST_F(CliErrors, ShowWritesOneAovAsPng) {
    const test::RunResult r = runGrotto(render(good_) + " --show ao");
    EXPECT_EQ(r.exitCode, 0) << r.err;
    EXPECT_TRUE(fs::exists(out()));
    expectRefused("render " + good_.string() + " --size 8x8 --show ao -o " + (dir_ / "x.exr").string(), "--show",
                  dir_ / "x.exr");
}

}  // namespace
}  // namespace grotto
