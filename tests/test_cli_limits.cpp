// Limits that must not lie: a refusal names what the user set and the real
// accepted range (voxel size, --fps over a long path, --size beyond the device,
// NaN in floating options, a malformed shader), and a run that measured nothing
// (sky only, an empty world, a 1x1 image) is refused rather than scored perfect.
#include "tests/cli_fixture.h"

#include <gtest/gtest.h>
#include "voxel/openvdb_grids.h"

#include <cmath>
#include <cstring>
#include <fstream>
#include <random>

namespace grotto {
namespace {

namespace fs = std::filesystem;
using test::CliErrors;
using test::runGrotto;

// The fixture's 16x16 slab with voxels of `voxelSize` world units.
fs::path scaledSlab(const fs::path& file, double voxelSize) {
    auto grid = openvdb::BoolGrid::create(false);
    grid->setName("solid");
    grid->setTransform(openvdb::math::Transform::createLinearTransform(voxelSize));
    for (int x = 0; x < 16; ++x)
        for (int z = 0; z < 16; ++z) grid->tree().setValueOn(openvdb::Coord(x, 0, z), true);
    grid->tree().setValueOn(openvdb::Coord(8, 1, 8), true);  // a bump, so AO has something to darken
    openvdb::io::File(file.string()).write({grid});
    return file;
}

// A world of voxels a million units wide is fine (the default AO radius, four
// voxels, is 4e6): it renders, and the same as the unit-voxel world, since
// everything scales together.
TEST_F(CliErrors, HugeVoxelsRenderLikeSmallOnes) {
    std::vector<std::vector<uint8_t>> images;
    for (double voxelSize : {1.0, 1e6}) {
        const fs::path world = scaledSlab(dir_ / ("slab" + std::to_string(int(std::log10(voxelSize))) + ".vdb"), voxelSize);
        const fs::path png = dir_ / "slab.png";
        const test::RunResult r = runGrotto("render " + world.string() + " --size 64x48 -o " + png.string());
        ASSERT_EQ(r.exitCode, 0) << r.err;
        images.push_back(test::readPixels8(png));
        ASSERT_FALSE(images.back().empty());
    }
    EXPECT_LE(test::worstDifference(images[0], images[1]), 2);
}

// Past the float range the shaders work in, the refusal names the voxel size
// (what the world sets) and its range, not a radius nobody set.
TEST_F(CliErrors, VoxelSizeBeyondItsRangeIsNamed) {
    const fs::path world = scaledSlab(dir_ / "vast.vdb", 1e20);
    const test::RunResult r = expectRefused(render(world), "voxel size 1e+20, outside the supported range", out());
    EXPECT_NE(r.err.find("0.0001 to 1e+06"), std::string::npos) << r.err;
    EXPECT_EQ(r.err.find("radius"), std::string::npos) << r.err;
    expectRefused(render(good_) + " --radius 1e16", "--radius", out());
}

// 1e7 seconds at 1000 fps is 1e10 frames: refused, naming --fps and the duration,
// not reported as a negative count.
TEST_F(CliErrors, FrameCountBeyondTheMaximumIsRefused) {
    const fs::path world = writeText("long.json", R"({"grid": {"file": "good.vdb"}, "paths": {"p": {"keys": [
        {"time": 0, "position": [8, 10, 30], "target": [8, 0, 8]}, {"time": 1e7, "position": [9, 10, 30], "target": [8, 0, 8]}]}}})");
    const fs::path seq = dir_ / "seq";
    expectRefused("flythrough " + world.string() + " --path p --fps 1000 --size 16x8 -o " + seq.string(), "--fps", seq);
    const test::RunResult r = runGrotto("flythrough " + world.string() + " --path p --fps 1000 --size 16x8 -o " + seq.string());
    EXPECT_NE(r.err.find("10000000001 frames"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("1e+07 s"), std::string::npos) << r.err;
    EXPECT_EQ(r.err.find("-2147483647"), std::string::npos) << r.err;
    const fs::path json = dir_ / "s.json";
    expectRefused("stability " + world.string() + " --path p --fps 1000 --size 16x8 --json " + json.string(), "--fps", json);
}

// A size whose colour target exceeds what the device can allocate is refused up
// front with the estimate, not by a driver error naming a source file.
TEST_F(CliErrors, SizeBeyondTheDeviceIsRefusedWithTheEstimate) {
    expectRefused("render " + good_.string() + " --size 16384x16384 -o " + out().string(), "--size: 16384x16384 is too large", out());
    const test::RunResult r = runGrotto("render " + good_.string() + " --size 16384x16384 -o " + out().string());
    EXPECT_NE(r.err.find("GiB"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("accepted here: up to about"), std::string::npos) << r.err;
    EXPECT_EQ(r.err.find(".cpp"), std::string::npos) << r.err;
    const fs::path seq = dir_ / "seq";
    const fs::path world = writeText("fly.json", R"({"grid": {"file": "good.vdb"}, "paths": {"p": {"keys": [
        {"time": 0, "position": [8, 10, 30], "target": [8, 0, 8]}, {"time": 1, "position": [9, 10, 30], "target": [8, 0, 8]}]}}})");
    expectRefused("flythrough " + world.string() + " --path p --size 16384x16384 -o " + seq.string(), "--size", seq);
}

TEST_F(CliErrors, FloatingOptionsRefuseNanInfinityAndNegatives) {
    for (const char* bad : {"nan", "inf"})
        for (const char* flag : {"--radius", "--strength", "--max-distance", "--falloff-range", "--thin-occluder",
                                 "--radius-multiplier", "--final-value-power", "--depth-mip-offset",
                                 "--denoise-blur-beta", "--sample-distribution-power"})
            expectRefused(render(good_) + " " + flag + " " + bad, flag, out());
    const fs::path json = dir_ / "s.json", baseline = writeText("b.json", "{}");
    const std::string stability = "stability " + (test::worldsDir() / "rooms.json").string() +
                                  " --path orbit --size 16x8 --json " + json.string() + " --baseline " + baseline.string();
    for (const char* bad : {"nan", "inf", "-1"}) {
        expectRefused(stability + " --tolerance " + bad, "--tolerance", json);
        expectRefused(stability + " --tolerance-absolute " + bad, "--tolerance-absolute", json);
    }
    expectRefused("mkworld sphere --voxel-size nan -o " + (dir_ / "n.vdb").string(), "--voxel-size", dir_ / "n.vdb");
    const fs::path exr = dir_ / "r.exr";
    expectRefused("reference " + good_.string() + " --size 8x8 --spp 4 --require-stderr nan -o " + exr.string(),
                  "--require-stderr", exr);
}

// SPIR-V words: a header and the few instructions the structure check looks at.
std::vector<uint32_t> spirvHeader() { return {0x07230203u, 0x00010000u, 0u, 16u, 0u}; }

void writeWords(const fs::path& file, const std::vector<uint32_t>& words) {
    std::ofstream(file, std::ios::binary).write(reinterpret_cast<const char*>(words.data()), std::streamsize(4 * words.size()));
}

// In a directory of otherwise good shaders, the right magic with garbage after it,
// or a well-formed module for another stage, is bad input naming the file: not a
// driver error (exit 1) or a crash.
TEST_F(CliErrors, MalformedSpirvIsBadInput) {
    const fs::path shaders = dir_ / "shaders";
    fs::create_directory(shaders);
    for (const auto& e : fs::directory_iterator(GROTTO_BUILT_SHADERS))
        if (e.path().extension() == ".spv") fs::copy_file(e.path(), shaders / e.path().filename());
    const std::string env = "GROTTO_SHADER_DIR=" + shaders.string();
    ASSERT_EQ(runGrotto(render(good_), env).exitCode, 0) << "the built shaders load from the directory";
    fs::remove(out());
    std::mt19937 rng(7);
    std::vector<uint32_t> garbage = {0x07230203u};
    for (int i = 0; i < 64; ++i) garbage.push_back(rng());
    writeWords(shaders / "gbuffer.vert.spv", garbage);
    expectRefused(render(good_), "gbuffer.vert.spv", out(), env);

    std::vector<uint32_t> compute = spirvHeader();
    for (uint32_t w : {(2u << 16) | 17u, 1u,                     // OpCapability Shader
                       (3u << 16) | 14u, 0u, 1u,                 // OpMemoryModel Logical GLSL450
                       (5u << 16) | 15u, 5u, 1u, 0u, 0u})        // OpEntryPoint GLCompute %1 "main"
        compute.push_back(w);
    std::memcpy(&compute[compute.size() - 2], "main", 4);
    writeWords(shaders / "gbuffer.vert.spv", compute);
    expectRefused(render(good_), "no \"main\" entry point for a .vert shader", out(), env);

    compute.push_back((9u << 16) | 54u);  // an OpFunction claiming words past the end
    writeWords(shaders / "gbuffer.vert.spv", compute);
    expectRefused(render(good_), "overruns", out(), env);
}

// Stability over nothing: an all-sky path and an empty world measured no surface
// pixels, and a 1x1 image next to none; each would otherwise score perfectly.
TEST_F(CliErrors, StabilityOfNothingIsRefused) {
    const fs::path json = dir_ / "s.json";
    const fs::path sky = writeText("sky.json", R"({"grid": {"file": "good.vdb"}, "paths": {"up": {"keys": [
        {"time": 0, "position": [8, 10, 30], "target": [8, 50, 30.5]}, {"time": 1, "position": [9, 10, 30], "target": [9, 50, 30.5]}]}}})");
    const std::string run = " --path up --fps 4 --spp 4 --reference-every 2 --json " + json.string();
    expectRefused("stability " + sky.string() + " --size 32x16" + run, "no surface pixels", json);
    auto empty = openvdb::BoolGrid::create(false);
    empty->setName("solid");
    writeGrids(dir_ / "empty.vdb", {empty});
    const fs::path nothing = writeText("nothing.json", R"({"grid": {"file": "empty.vdb"}, "paths": {"up": {"keys": [
        {"time": 0, "position": [8, 10, 30], "target": [8, 0, 8]}, {"time": 1, "position": [9, 10, 30], "target": [8, 0, 8]}]}}})");
    expectRefused("stability " + nothing.string() + " --size 32x16" + run, "no solid voxels", json);
    // 1x1 is refused up front: one AO pixel has no neighbours to search, so GTAO
    // reads it open and "matches" a reference that happens to be open too.
    const std::string rooms = "stability " + (test::worldsDir() / "rooms.json").string() +
                              " --path orbit --frames 4 --spp 4 --reference-every 2 --json " + json.string();
    expectRefused(rooms + " --size 1x1", "--size", json);
    expectRefused(rooms + " --size 14x64", "at least 8x8", json);
    expectRefused(rooms + " --size 64x13", "at least 8x8", json);
    expectRefused(rooms + " --size 7x64 --ao-full-res", "at least 8x8", json);
}

// compare, tradeoff and tune measure error against the reference: a view with no
// surface has none to measure.
TEST_F(CliErrors, ErrorOfAnEmptyViewIsRefused) {
    const fs::path world = writeText("sky.json", R"({"grid": {"file": "good.vdb"},
        "cameras": {"up": {"position": [8, 10, 30], "target": [8, 50, 30.5]}}})");
    const std::string view = world.string() + " --camera up --size 16x8 --spp 4";
    const std::string env = "GROTTO_CACHE_DIR=" + (dir_ / "cache").string();
    expectRefused("compare " + view + " --frames 1 --warmup 0", "sees no surface", dir_ / "none", env);
    const fs::path csv = dir_ / "t.csv";
    expectRefused("tradeoff " + view + " --frames 1 --warmup 0 --csv " + csv.string(), "sees no surface", csv, env);
    expectRefused("tune " + view + " --rounds 1", "sees no surface", dir_ / "none", env);
}

}  // namespace
}  // namespace grotto
