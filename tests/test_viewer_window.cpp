// `grotto view` in a real window, under Xvfb (xvfb-run), validation layer on: a
// scripted flight that ends on a named camera gives the same image as `render` of
// that camera; resizing, minimising and restoring mid-run stay valid; a bad script
// is refused. Skipped, saying why, only where xvfb-run is missing.
#include "tests/cli_fixture.h"

#include <gtest/gtest.h>

#include <cstdlib>

namespace grotto {
namespace {

namespace fs = std::filesystem;
using test::CliErrors;
using test::runGrotto;

// The environment prefix that runs grotto inside a fresh virtual X server.
const char* kUnderXvfb = "GROTTO_VALIDATION=1 xvfb-run -a -s '-screen 0 1280x800x24'";

bool haveXvfb() { return std::system("command -v xvfb-run >/dev/null 2>&1") == 0; }

#define REQUIRE_XVFB() \
    if (!haveXvfb()) GTEST_SKIP() << "xvfb-run is not installed (Debian: xvfb): no X server for the viewer's window"

TEST_F(CliErrors, ViewerFlightEndingOnACameraMatchesRender) {
    REQUIRE_XVFB();
    // Fly forward and turn for 8 frames, then cut to the table camera and stay 16
    // frames: the cut restarts the history and the noise, as `render` starts them.
    const fs::path script = writeText("fly.json", R"({"actions": [
        {"frame": 0, "key": "W", "down": true}, {"frame": 2, "look": [40, 10]}, {"frame": 8, "key": "W", "down": false},
        {"frame": 10, "camera": "table"}]})");
    const fs::path shot = dir_ / "view.png", still = dir_ / "render.png";
    const std::string world = (test::worldsDir() / "rooms.json").string();
    const test::RunResult v = runGrotto("view " + world + " --size 320x180 --script " + script.string() +
                                            " --frames 26 --screenshot " + shot.string(), kUnderXvfb);
    ASSERT_EQ(v.exitCode, 0) << v.err;
    const test::RunResult r = runGrotto("render " + world + " --camera table --size 320x180 --accumulate 16 -o " +
                                        still.string());
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const std::vector<uint8_t> a = test::readPixels8(shot), b = test::readPixels8(still);
    ASSERT_EQ(a.size(), b.size());
    // The same frames through the same renderer: identical but for float rounding.
    EXPECT_LE(test::worstDifference(a, b), 1);
}

TEST_F(CliErrors, ViewerResizesMinimisesAndRestoresWithoutValidationMessages) {
    REQUIRE_XVFB();
    const fs::path script = writeText("resize.json", R"({"actions": [
        {"frame": 2, "resize": [400, 240]}, {"frame": 4, "set": {"view": "ao", "ao.method": "voxel"}},
        {"frame": 5, "minimize": true}, {"frame": 7, "restore": true}, {"frame": 9, "set": {"view": "final"}}]})");
    const fs::path shot = dir_ / "after.png", window = dir_ / "window.png";
    const test::RunResult v = runGrotto("view " + (test::worldsDir() / "rooms.json").string() +
                                            " --size 320x180 --script " + script.string() + " --frames 12 --screenshot " +
                                            shot.string() + " --capture-window " + window.string(),
                                        kUnderXvfb);
    ASSERT_EQ(v.exitCode, 0) << v.err;
    EXPECT_EQ(v.err.find("validation"), std::string::npos) << v.err;
    // The frame follows the window's new size; the capture is the window as shown.
    EXPECT_EQ(test::readPixels8(shot).size(), size_t(400 * 240 * 3));
    EXPECT_EQ(test::readPixels8(window).size(), size_t(400 * 240 * 3));
}

TEST_F(CliErrors, ViewerRefusesABadScriptSetting) {
    REQUIRE_XVFB();
    const fs::path script = writeText("bad.json", R"({"actions": [{"frame": 1, "set": {"ao.method": "magic"}}]})");
    expectRefused("view " + good_.string() + " --size 64x48 --frames 3 --script " + script.string() +
                      " --screenshot " + (dir_ / "x.png").string(),
                  "ao.method", dir_ / "x.png", kUnderXvfb);
}

}  // namespace
}  // namespace grotto
