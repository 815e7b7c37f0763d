// Full light through the command line: a closed room lit by one glowing voxel,
// baked and rendered with lighting.ambient.from full, measured against the
// path-traced light (the sky's light leaves it black); a bake of the old format
// refused, and a farm's chunks refused for a world whose bounces need it whole.
#include "cli_fixture.h"
#include "engine/image_input.h"
#include "shaders/shared/tone_map.h"
#include "tests/virtual_display.h"
#include "vox_writer.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>

namespace grotto::test {
namespace {

class CliFullLight : public CliErrors {
protected:
    // A closed room of 12 x 12 x 7 voxels (shell of colour 1) with one voxel of
    // colour 2 on its floor, in MagicaVoxel's z-up (centred on the origin, as
    // MagicaVoxel places a model).
    fs::path writeRoomVox() {
        std::array<voxel::VoxColor, 256> palette{};
        palette[0] = {188, 188, 188, 255};  // sRGB 188: linear 0.5
        palette[1] = {255, 255, 255, 255};
        std::vector<std::array<uint8_t, 4>> voxels;
        for (uint8_t x = 0; x < 12; ++x)
            for (uint8_t y = 0; y < 12; ++y)
                for (uint8_t z = 0; z < 7; ++z)
                    if (x == 0 || y == 0 || z == 0 || x == 11 || y == 11 || z == 6) voxels.push_back({x, y, z, 1});
        voxels.push_back({6, 5, 1, 2});
        voxel::test::VoxWriter w;
        w.model({12, 12, 7}, voxels).palette(palette);
        const std::vector<uint8_t> bytes = w.bytes();
        const fs::path file = dir_ / "room.vox";
        std::ofstream(file, std::ios::binary).write(reinterpret_cast<const char*>(bytes.data()), std::streamsize(bytes.size()));
        return file;
    }
    // The room with the lamp glowing at radiance 20, lit as `from` says; `fields`
    // (JSON members with a trailing comma) added at the top.
    fs::path writeRoomWorld(const std::string& name, const std::string& from, const std::string& fields = "") {
        writeRoomVox();
        return writeText(name, "{" + fields + R"("grid": {"file": "room.vox"}, "materials": [
            {"name": "walls", "albedo": [0.5, 0.5, 0.5]},
            {"name": "lamp", "albedo": [0.5, 0.5, 0.5], "emission": {"color": [1, 0.8, 0.6], "intensity": 20}}],
            "lighting": {"ambient": {"from": ")" + from + R"(", "intensity": 0.7}, "sun": {"intensity": 1}},
            "ao": {"method": "cache"},
            "cameras": {"in": {"position": [-3.5, 0.5, -3.5], "target": [2.5, -2, 2.5], "fov": 70}}})");
    }
    struct LightFigures {
        double psnr = 0, rmse = 0, bias = 0, median = 0;
        long black = -1;
    };
    LightFigures compareLight(const fs::path& world) {
        const RunResult r = runGrotto("compare " + world.string() + " --camera in --size 48x32 --spp 8 --light-spp 256 "
                                      "--frames 1 --warmup 0");
        EXPECT_EQ(r.exitCode, 0) << r.err;
        LightFigures f;
        // "(256 paths a pixel, traced)" or "(..., from the cache)": what follows is the same.
        const size_t line = r.out.find("light against the path-traced light (256 paths a pixel, ");
        const size_t at = line == std::string::npos ? line : r.out.find("psnr ", line);
        EXPECT_NE(at, std::string::npos) << r.out;
        if (at == std::string::npos) return f;
        EXPECT_EQ(std::sscanf(r.out.c_str() + at, "psnr %lf dB (tone-mapped), relative rmse %lf%%, bias %lf%%", &f.psnr,
                              &f.rmse, &f.bias), 3) << r.out;
        const size_t dim = r.out.find("relative error median ", at);
        EXPECT_NE(dim, std::string::npos) << r.out;
        if (dim != std::string::npos) {
            double p95 = 0;
            EXPECT_EQ(std::sscanf(r.out.c_str() + dim, "relative error median %lf%%, 95th percentile %lf%%, %ld black",
                                  &f.median, &p95, &f.black), 3) << r.out;
        }
        return f;
    }
};

TEST_F(CliFullLight, AClosedRoomLitByOneGlowingVoxelMatchesThePathTracedLight) {
    // The sky's light cannot enter a closed room: the lamp's light, and its
    // bounces off the walls, are all there is. With full light the image holds
    // them, unbiased; with sky light the room is black.
    const LightFigures full = compareLight(writeRoomWorld("full.json", "full"));
    EXPECT_LT(std::abs(full.bias), 3.0) << "mean light against the path tracer's";
    EXPECT_EQ(full.black, 0);
    EXPECT_GT(full.psnr, 28.0);  // 30.4 dB: the reference's own noise at 256 paths is most of the rest
    EXPECT_LT(full.median, 12.0);
    const LightFigures sky = compareLight(writeRoomWorld("sky.json", "sky"));
    EXPECT_LT(sky.bias, -30.0) << "only the lamp's own faces glow";
    EXPECT_GT(sky.black, 1000) << "of 1536 pixels";
}

TEST_F(CliFullLight, ABakeFileCarriesTheLightAndRendersAsTheBakeAtLoad) {
    const fs::path world = writeRoomWorld("full.json", "full");
    const fs::path bake = dir_ / "room.gfc";
    const RunResult b = runGrotto("bake " + world.string() + " -o " + bake.string());
    ASSERT_EQ(b.exitCode, 0) << b.err;
    EXPECT_NE(b.out.find("full light in "), std::string::npos) << b.out;
    const fs::path a = dir_ / "loaded.png", c = dir_ / "baked.png";
    ASSERT_EQ(runGrotto("render " + world.string() + " --camera in --size 48x32 --bake " + bake.string() + " -o " + a.string()).exitCode, 0);
    ASSERT_EQ(runGrotto("render " + world.string() + " --camera in --size 48x32 -o " + c.string()).exitCode, 0);
    const std::vector<uint8_t> loaded = readPixels8(a), baked = readPixels8(c);
    ASSERT_FALSE(loaded.empty());
    EXPECT_EQ(worstDifference(loaded, baked), 0);
    // The same voxels lit by the sky alone ask for a bake without light: this one is refused.
    const fs::path sky = writeRoomWorld("sky.json", "sky");
    expectRefused("render " + sky.string() + " --camera in --size 48x32 --bake " + bake.string() + " -o " + out().string(),
                  "full light", out());
    // Under a memory budget the world fits (4.7 MiB) and the bounces' remembered
    // hits at 4 x 4 texels (about 9 MiB) do not: refused before the bake.
    const fs::path tight = writeRoomWorld("tight.json", "full", R"("memory_budget_mib": 5, )");
    expectRefused("bake " + tight.string() + " --texels 4 -o " + (dir_ / "tight.gfc").string(), "full light's bake of",
                  dir_ / "tight.gfc");
    // And a farm's chunk of it: its bounces need the whole world.
    expectRefused("bake " + world.string() + " --chunk 1/2 -o " + (dir_ / "part.gfc").string(), "baked whole",
                  dir_ / "part.gfc");
}

TEST_F(CliFullLight, AnOpenWorldsBakeReadsBack) {
    // Pillars on a floor under the sky: with full light the sky's weights come
    // from the light's 128 rays, so a texel may see more sky than its 64 AO rays
    // found open within R; the bake must still read back (caves' did not).
    writeSolid(dir_ / "pillars.vdb", 24, 6, [](int x, int y, int z) { return y == 0 || (x % 4 == 1 && z % 3 == 1); });
    const fs::path world = writeText("pillars.json", R"({"grid": {"file": "pillars.vdb"},
        "lighting": {"ambient": {"from": "full"}}, "ao": {"method": "cache"},
        "cameras": {"c": {"position": [12, 9, -6], "target": [12, 0, 12], "fov": 60}}})");
    const fs::path bake = dir_ / "pillars.gfc";
    ASSERT_EQ(runGrotto("bake " + world.string() + " -o " + bake.string()).exitCode, 0);
    const RunResult r = runGrotto("render " + world.string() + " --camera c --size 32x24 --bake " + bake.string() + " -o " +
                                  out().string());
    EXPECT_EQ(r.exitCode, 0) << r.err;
    EXPECT_TRUE(fs::exists(out()));
}

TEST_F(CliFullLight, ABakeOfTheFormerFormatIsRefusedByItsVersion) {
    // A version 2 file (before the light was stored): its magic, then version 2.
    const fs::path world = writeRoomWorld("full.json", "full");
    const fs::path old = dir_ / "old.gfc";
    std::string bytes = "GROTTOFC";
    const uint32_t version = 2;
    bytes.append(reinterpret_cast<const char*>(&version), 4);
    bytes.resize(104, '\0');
    std::ofstream(old, std::ios::binary) << bytes;
    expectRefused("render " + world.string() + " --camera in --size 48x32 --bake " + old.string() + " -o " + out().string(),
                  "version 2 is not this Grotto's", out());
}

TEST_F(CliFullLight, TheReferenceLightAsAPngIsItsExrAsADisplayShowsIt) {
    // The same paths (same seed) to both: the PNG is the EXR's radiance times the
    // exposure, tone-mapped (filmic, the default) and encoded as 8-bit sRGB.
    const fs::path world = writeRoomWorld("full.json", "full");
    const fs::path exr = dir_ / "light.exr", png = dir_ / "light.png";
    const std::string view = "reference " + world.string() + " --camera in --size 24x16 --light full --spp 16 -o ";
    ASSERT_EQ(runGrotto(view + exr.string()).exitCode, 0);
    ASSERT_EQ(runGrotto(view + png.string()).exitCode, 0);
    const std::optional<ImageFile> linear = readImage(exr);
    ASSERT_TRUE(linear);
    const std::vector<uint8_t> shown = readPixels8(png);
    ASSERT_EQ(shown.size(), size_t(24 * 16 * 3));
    const std::vector<float> r = linear->channel("R"), g = linear->channel("G"), b = linear->channel("B");
    const float exposure = 0.6f;  // the default
    auto srgb8 = [](float v) {  // IEC 61966-2-1's encoding
        const float e = v <= 0.0031308f ? 12.92f * v : 1.055f * std::pow(v, 1.0f / 2.4f) - 0.055f;
        return int(std::lround(std::clamp(e, 0.0f, 1.0f) * 255.0f));
    };
    int lit = 0;
    for (size_t i = 0; i < r.size(); ++i) {
        const float rgb[3] = {r[i], g[i], b[i]};
        for (int c = 0; c < 3; ++c) {
            const int want = srgb8(gpu::toneMap(rgb[c] * exposure, GROTTO_TONE_MAP_FILMIC));
            ASSERT_NEAR(int(shown[3 * i + size_t(c)]), want, 1) << "pixel " << i << " channel " << c;
            lit += want > 8;
        }
    }
    EXPECT_GT(lit, 300) << "the room is lit by its lamp";
    // The AO reference has no display image to give.
    expectRefused("reference " + world.string() + " --camera in --size 24x16 --spp 4 -o " + out().string(), "needs an .exr output",
                  out());
}

TEST_F(CliFullLight, TheViewersLightViewIsTheLightAovRenderDraws) {
    REQUIRE_XVFB();
    // The room lit by its lamp: the viewer's light view is `render --bake --show
    // light` pixel for pixel (and the window shows what it does), and
    // warm where the lamp's light falls. The viewer has no bake: its GPU tracer
    // gives the room the sky's light alone (none), and the room's light is baked
    // on a thread of its own, which a script's frames wait for.
    const fs::path world = writeRoomWorld("room.json", "full"), bake = dir_ / "room.gfc";
    const RunResult baked = runGrotto("bake " + world.string() + " -o " + bake.string());
    ASSERT_EQ(baked.exitCode, 0) << baked.err;
    // Then a light placed with a click (edit mode "light": a voxel of the lamp's
    // material in front of the face clicked) adds its light in the next frame.
    const fs::path script = writeText("light.json", R"({"actions": [
        {"frame": 1, "set": {"view": "light"}}, {"frame": 3, "screenshot": "shot.png"},
        {"frame": 4, "set": {"edit.mode": "light"}}, {"frame": 5, "click": [32, 24]},
        {"frame": 6, "screenshot": "placed.png"}]})");
    const fs::path shot = dir_ / "shot.png", window = dir_ / "window.png", still = dir_ / "render.png";
    const RunResult v = runGrotto("view " + world.string() + " --camera in --size 64x48 --hide-panel --script " +
                                      script.string() + " --frames 7 --capture-window " + window.string(),
                                  kUnderXvfb);
    ASSERT_EQ(v.exitCode, 0) << v.err;
    const RunResult r = runGrotto("render " + world.string() + " --bake " + bake.string() +
                                  " --camera in --size 64x48 --show light -o " + still.string());
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const std::vector<uint8_t> a = readPixels8(shot), b = readPixels8(still), w = readPixels8(window);
    ASSERT_EQ(a.size(), 64u * 48u * 3u);
    EXPECT_EQ(a, b) << "the viewer's light view is not render's";
    const std::vector<uint8_t> placed = readPixels8(dir_ / "placed.png");
    ASSERT_EQ(placed.size(), a.size());
    double before = 0.0, after = 0.0;
    for (size_t i = 0; i < a.size(); ++i) before += a[i], after += placed[i];
    EXPECT_GT(after, 1.1 * before) << "the light placed adds its light in the next frame";
    EXPECT_LE(worstDifference(placed, w), 1);  // the window blits the same values
    size_t warm = 0;
    for (size_t i = 0; i + 2 < a.size(); i += 3) warm += a[i] > a[i + 2] + 8;
    EXPECT_GT(warm, a.size() / 3 / 2) << "the lamp's warm light is missing";
}

}  // namespace
}  // namespace grotto::test
