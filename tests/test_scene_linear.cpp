// EXR outputs hold scene-linear colour (radiance x exposure, no tone map), PNGs the
// same frame made display-referred: render and flythrough write both from one
// world and camera, and each PNG must equal its EXR through the documented tone
// map and sRGB encoding (docs/lighting.md), with values above 1 in a sunlit scene.
#include "tests/cli_fixture.h"
#include "tests/display_checks.h"

#include <gtest/gtest.h>

namespace grotto {
namespace {

namespace fs = std::filesystem;
using test::CliErrors;
using test::runGrotto;

TEST_F(CliErrors, RenderWritesSceneLinearExrAndToneMappedPng) {
    for (const char* curve : {"filmic", "linear"}) {
        const fs::path world = writeText(std::string(curve) + ".json", test::brightWorld(curve));
        const std::string args = "render " + world.string() + " --camera c --size 48x32 -o ";
        const fs::path exr = dir_ / (std::string(curve) + ".exr"), png = dir_ / (std::string(curve) + ".png");
        for (const fs::path& out : {exr, png}) {
            const test::RunResult r = runGrotto(args + out.string());
            ASSERT_EQ(r.exitCode, 0) << r.err;
        }
        const uint32_t toneMap = curve == std::string("filmic") ? GROTTO_TONE_MAP_FILMIC : GROTTO_TONE_MAP_CLAMP;
        test::expectSceneLinear(test::compareExrWithPng(exr, png, toneMap), curve);
    }
}

TEST_F(CliErrors, FlythroughWritesSceneLinearExrAndToneMappedPngFrames) {
    const fs::path world = writeText("bright.json", test::brightWorld("filmic"));
    for (const char* format : {"exr", "png"}) {
        const test::RunResult r = runGrotto("flythrough " + world.string() + " --path p --fps 4 --frames 2-2 --warmup 2 " +
                                            "--size 40x24 --format " + format + " -o " + (dir_ / format).string());
        ASSERT_EQ(r.exitCode, 0) << r.err;
    }
    test::expectSceneLinear(test::compareExrWithPng(dir_ / "exr" / "frame.0002.exr", dir_ / "png" / "frame.0002.png"),
                            "flythrough frame 2");
}

}  // namespace
}  // namespace grotto
