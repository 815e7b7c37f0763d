// Glowing materials through the command line: a world file's emission and a
// MagicaVoxel _emit material read, listed by `info` with their power, refused
// when malformed, and lighting `reference --light full`.
#include "tests/cli_fixture.h"
#include "tests/vox_writer.h"

#include <cmath>
#include <cstdio>
#include <fstream>

namespace grotto::test {
namespace {

// An EXR's pixels as floats, every channel interleaved (empty if it cannot be read).
ImageFile readFloats(const fs::path& exr) { return readImage(exr).value_or(ImageFile{}); }

class CliEmitters : public CliErrors {
protected:
    // A 3 x 3 floor of colour 1 with one voxel of colour 2 on it (MagicaVoxel
    // is z-up), with `lamp`'s MATL for colour 2 when given.
    fs::path writeLampVox(const voxel::test::VoxDict& lamp = {}) {
        std::array<voxel::VoxColor, 256> palette{};
        palette[0] = {128, 128, 128, 255};
        palette[1] = {255, 188, 0, 255};  // sRGB 188 is linear 0.5
        std::vector<std::array<uint8_t, 4>> voxels;
        for (uint8_t x = 0; x < 3; ++x)
            for (uint8_t y = 0; y < 3; ++y) voxels.push_back({x, y, 0, 1});
        voxels.push_back({1, 1, 1, 2});
        voxel::test::VoxWriter w;
        w.model({3, 3, 2}, voxels).palette(palette);
        if (!lamp.empty()) w.material(2, lamp);
        const std::vector<uint8_t> bytes = w.bytes();
        const fs::path file = dir_ / "lamp.vox";
        std::ofstream(file, std::ios::binary).write(reinterpret_cast<const char*>(bytes.data()), std::streamsize(bytes.size()));
        return file;
    }
    fs::path writeLampWorld(const std::string& lampMaterial) {
        writeLampVox();
        return writeText("lamp.json", R"({"grid": {"file": "lamp.vox"}, "materials": [
            {"name": "floor", "albedo": [0.5, 0.5, 0.5]}, )" + lampMaterial + "]}");
    }
};

TEST_F(CliEmitters, InfoListsEachEmitterWithItsAreaAndPower) {
    const fs::path world = writeLampWorld(
        R"({"name": "lamp", "albedo": [0.8, 0.8, 0.8], "emission": {"color": [1, 0.5, 0.25], "intensity": 4}})");
    const RunResult r = runGrotto("info " + world.string());
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_NE(r.out.find("lamp: albedo (0.8 0.8 0.8), emits (1 0.5 0.25) x 4, 1 voxel"), std::string::npos) << r.out;
    // Five faces open to the air (its sixth is on the floor): pi x 4 x colour x 5.
    EXPECT_NE(r.out.find("emitter        material 2: radiance (4 2 1) over 5 square units, power (62.8319 31.4159 15.708)"),
              std::string::npos) << r.out;
    EXPECT_NE(r.out.find("emitters       1 materials, total power (62.8319 31.4159 15.708)"), std::string::npos) << r.out;
    // Without emission nothing glows.
    const fs::path dark = writeLampWorld(R"({"name": "lamp", "albedo": [0.8, 0.8, 0.8]})");
    const RunResult none = runGrotto("info " + dark.string());
    ASSERT_EQ(none.exitCode, 0) << none.err;
    EXPECT_NE(none.out.find("emitters       none"), std::string::npos) << none.out;
}

TEST_F(CliEmitters, AMagicaVoxelEmitMaterialGlowsInItsColour) {
    // _emit 0.5 at _flux 2: intensity 0.5 x 2^2 = 2, in the palette colour made linear.
    const fs::path vox = writeLampVox({{"_type", "_emit"}, {"_emit", "0.5"}, {"_flux", "2"}, {"_ldr", "0.3"}});
    const RunResult r = runGrotto("info " + vox.string());
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_NE(r.out.find("colour 2 (emit): albedo (1 0.502886 0), emits (1 0.502886 0) x 2"), std::string::npos) << r.out;
    // Converted, the world file written keeps the glow.
    const RunResult converted = runGrotto("convert " + vox.string() + " -o " + (dir_ / "converted.vdb").string());
    ASSERT_EQ(converted.exitCode, 0) << converted.err;
    const RunResult again = runGrotto("info " + (dir_ / "converted.json").string());
    EXPECT_NE(again.out.find("emits (1 0.502886 0) x 2"), std::string::npos) << again.out;
    // A diffuse MATL with _emit set (MagicaVoxel ignores it there) does not glow.
    writeLampVox({{"_type", "_diffuse"}, {"_emit", "0.5"}});
    const RunResult diffuse = runGrotto("info " + vox.string());
    ASSERT_EQ(diffuse.exitCode, 0) << diffuse.err;
    EXPECT_NE(diffuse.out.find("emitters       none"), std::string::npos) << diffuse.out;
}

TEST_F(CliEmitters, MalformedEmissionIsRefusedNamingTheField) {
    const std::pair<std::string, std::string> cases[] = {
        {R"({"emission": {"color": [1, 1, 1], "intensity": -1}})", "materials[1].emission.intensity"},
        {R"({"emission": {"intensity": 1e9}})", "materials[1].emission.intensity"},
        {R"({"emission": {"color": [1, 2, 1]}})", "materials[1].emission.color"},
        {R"({"emission": {"color": [1, 1]}})", "materials[1].emission.color"},
        {R"({"emission": 3})", "materials[1].emission"},
        {R"({"emission": {"colour": [1, 1, 1]}})", "colour"},
    };
    for (const auto& [material, field] : cases) {
        const fs::path world = writeLampWorld(material);
        expectRefused("info " + world.string(), field, dir_ / "none");
    }
}

TEST_F(CliEmitters, ReferenceFullLightWritesRadianceAndRefusesAoOnlyFlags) {
    const fs::path world = writeLampWorld(
        R"({"name": "lamp", "albedo": [0.8, 0.8, 0.8], "emission": {"color": [1, 0.5, 0.25], "intensity": 4}})");
    const fs::path exr = dir_ / "light.exr";
    const RunResult r = runGrotto("reference " + world.string() + " --light full --spp 8 --size 48x32 -o " + exr.string());
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const ImageFile image = readFloats(exr);
    ASSERT_FALSE(image.floats.empty());
    const std::vector<float>& pixels = image.floats;
    ASSERT_EQ(image.channels(), 6);
    for (const char* name : {"R", "G", "B", "R_stderr", "G_stderr", "B_stderr"})
        EXPECT_GE(image.channelIndex(name), 0) << name;
    const int R = image.channelIndex("R"), G = image.channelIndex("G");
    float brightest = 0.0f;
    for (size_t i = 0; i < pixels.size(); i += 6) {
        for (int c = 0; c < 6; ++c) ASSERT_TRUE(std::isfinite(pixels[i + size_t(c)]) && pixels[i + size_t(c)] >= 0.0f);
        brightest = std::max(brightest, pixels[i + size_t(R)]);
        // The lamp's faces: emission (4 2 1) plus what they reflect.
        if (pixels[i + size_t(R)] >= 4.0f) EXPECT_GE(pixels[i + size_t(G)], 2.0f);
    }
    EXPECT_GE(brightest, 4.0f);  // the lamp is in view and shows its own light
    expectRefused("reference " + world.string() + " --bounces 2 --spp 8 -o " + (dir_ / "b.exr").string(), "--bounces",
                  dir_ / "b.exr");
    expectRefused("reference " + world.string() + " --light full --radius 3 --spp 8 -o " + (dir_ / "c.exr").string(),
                  "--radius", dir_ / "c.exr");
    expectRefused("reference " + world.string() + " --light sky --spp 8 -o " + (dir_ / "d.exr").string(), "--light",
                  dir_ / "d.exr");
}

TEST_F(CliEmitters, ARenderShowsAGlowingFaceAtItsEmissionTimesTheExposure) {
    // A black lamp reflects nothing: its faces show exactly emission x exposure (0.6).
    const fs::path world = writeLampWorld(
        R"({"name": "lamp", "albedo": [0, 0, 0], "emission": {"color": [1, 0.5, 0.25], "intensity": 4}})");
    const fs::path exr = dir_ / "lamp.exr";
    const RunResult r = runGrotto("render " + world.string() + " --ao off --size 48x32 -o " + exr.string());
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const ImageFile image = readFloats(exr);
    ASSERT_FALSE(image.floats.empty());
    const int channels = image.channels();
    const std::vector<float>& pixels = image.floats;
    int lamp = 0;
    for (size_t i = 0; i < pixels.size(); i += size_t(channels)) {
        if (pixels[i] < 1.0f) continue;  // the floor and the sky stay far below the lamp
        ++lamp;
        EXPECT_NEAR(pixels[i], 2.4f, 1e-4f);
        EXPECT_NEAR(pixels[i + 1], 1.2f, 1e-4f);
        EXPECT_NEAR(pixels[i + 2], 0.6f, 1e-4f);
    }
    EXPECT_GT(lamp, 4);
}

TEST_F(CliEmitters, CompareMeasuresTheImageAgainstThePathTracedLight) {
    // Open ground under a uniform sky of 1 and no sun: the constant ambient of the
    // same colour is the sky's exact light there, so the image matches the light.
    const fs::path world = writeText("open.json", R"({"grid": {"file": "good.vdb"}, "lighting": {
        "sun": {"intensity": 0}, "ambient": {"color": [1, 1, 1], "intensity": 0.7},
        "sky": {"zenith": [1, 1, 1], "horizon": [1, 1, 1]}},
        "cameras": {"down": {"position": [8, 12, 9], "target": [8, 0, 8], "fov": 40}}})");
    const RunResult r = runGrotto("compare " + world.string() + " --camera down --size 48x32 --spp 16 --light-spp 16 "
                                  "--frames 1 --warmup 0");
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const size_t at = r.out.find("light against the path-traced light (16 paths a pixel, traced): psnr ");
    ASSERT_NE(at, std::string::npos) << r.out;
    double psnr = 0.0, rmse = 0.0, bias = 0.0;
    ASSERT_EQ(std::sscanf(r.out.c_str() + at, "light against the path-traced light (16 paths a pixel, traced): psnr %lf dB "
                          "(tone-mapped), relative rmse %lf%%, bias %lf%%", &psnr, &rmse, &bias), 3) << r.out;
    EXPECT_GT(psnr, 40.0) << r.out;
    EXPECT_LT(rmse, 2.0) << r.out;
    EXPECT_LT(std::abs(bias), 1.0) << r.out;
    // A sky of 2 in the path tracer's light is twice what the composite's constant gives.
    const fs::path brighter = writeText("brighter.json", R"({"grid": {"file": "good.vdb"}, "lighting": {
        "sun": {"intensity": 0}, "ambient": {"color": [1, 1, 1], "intensity": 0.7},
        "sky": {"zenith": [2, 2, 2], "horizon": [2, 2, 2]}},
        "cameras": {"down": {"position": [8, 12, 9], "target": [8, 0, 8], "fov": 40}}})");
    const RunResult b = runGrotto("compare " + brighter.string() + " --camera down --size 48x32 --spp 16 --light-spp 16 "
                                  "--frames 1 --warmup 0");
    ASSERT_EQ(b.exitCode, 0) << b.err;
    EXPECT_NE(b.out.find("bias -50.0%"), std::string::npos) << b.out;
}

}  // namespace
}  // namespace grotto::test
