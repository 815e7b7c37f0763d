// `grotto view` in a real window, under Xvfb, validation layer on: a
// scripted flight that ends on a named camera gives the same image as `render` of
// that camera; resizing, minimising and restoring mid-run stay valid; a bad script
// is refused; recorded paths, played paths and digging. Skipped, saying why, only
// where Xvfb is missing.
#include "common/printable.h"
#include "tests/cli_fixture.h"
#include "tests/display_checks.h"
#include "tests/virtual_display.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <chrono>
#include <csignal>
#include <cstdlib>
#include <fstream>
#include <thread>

#include <fcntl.h>
#include <sys/wait.h>
#include <unistd.h>

namespace grotto {
namespace {

namespace fs = std::filesystem;
using test::CliErrors;
using test::runGrotto;

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

// The command line's AO settings outlast a script's change of another setting:
// the world saved after it still has them (they were dropped from the viewer's settings).
TEST_F(CliErrors, ViewerKeepsCommandLineAoSettingsAfterAScriptChange) {
    REQUIRE_XVFB();
    const fs::path script = writeText("keep.json", R"({"actions": [
        {"frame": 1, "set": {"lighting.exposure": 0.8}}, {"frame": 2, "save_world": "kept.json"}]})");
    const test::RunResult v = runGrotto("view " + good_.string() + " --size 64x48 --thin-occluder 0.45 --temporal 3 " +
                                            "--ao-full-res --script " + script.string() + " --frames 3", kUnderXvfb);
    ASSERT_EQ(v.exitCode, 0) << v.err;
    std::ifstream in(dir_ / "kept.json");
    const nlohmann::json world = nlohmann::json::parse(in, nullptr, false);
    ASSERT_TRUE(world.is_object());
    EXPECT_NEAR(world["lighting"]["exposure"].get<double>(), 0.8, 1e-6);
    EXPECT_NEAR(world["ao"].value("thin_occluder", 0.0), 0.45, 1e-9) << world["ao"].dump();
    EXPECT_EQ(world["ao"].value("temporal_history", 0), 3) << world["ao"].dump();
    EXPECT_EQ(world["ao"].value("full_resolution", false), true) << world["ao"].dump();
}

}  // namespace
}  // namespace grotto

namespace grotto {
namespace {

// The mean absolute difference of two 8-bit images of the same size.
double meanDifference(const std::vector<uint8_t>& a, const std::vector<uint8_t>& b) {
    double sum = 0.0;
    for (size_t i = 0; i < a.size(); ++i) sum += std::abs(int(a[i]) - int(b[i]));
    return a.empty() ? 0.0 : sum / double(a.size());
}

TEST_F(CliErrors, ViewerRecordsAPathThatFlythroughPlaysThroughTheSameCameras) {
    REQUIRE_XVFB();
    // Keys at frames 4, 12 and 20 of a flight (1/60 s a frame), each with a screenshot.
    const fs::path script = writeText("record.json", R"({"actions": [
        {"frame": 0, "key": "W", "down": true}, {"frame": 6, "look": [60, 0]}, {"frame": 14, "look": [-30, 20]},
        {"frame": 4, "record": true}, {"frame": 4, "screenshot": "k1.png"},
        {"frame": 12, "record": true}, {"frame": 12, "screenshot": "k2.png"},
        {"frame": 20, "record": true}, {"frame": 20, "screenshot": "k3.png"},
        {"frame": 22, "save_path": "flight.json"}]})");
    const std::string world = (test::worldsDir() / "rooms.json").string();
    const test::RunResult v =
        runGrotto("view " + world + " --size 320x180 --script " + script.string() + " --frames 24", kUnderXvfb);
    ASSERT_EQ(v.exitCode, 0) << v.err;
    const fs::path out = dir_ / "frames";
    const test::RunResult f = runGrotto("flythrough " + world + " --path " + (dir_ / "flight.json").string() +
                                        " --fps 60 --size 320x180 -o " + out.string());
    ASSERT_EQ(f.exitCode, 0) << f.err;
    // Path time 0, 8/60 and 16/60 s: flythrough frames 1, 9 and 17.
    const char* frames[3] = {"frame.0001.png", "frame.0009.png", "frame.0017.png"};
    const char* keys[3] = {"k1.png", "k2.png", "k3.png"};
    for (int k = 0; k < 3; ++k) {
        const std::vector<uint8_t> shown = test::readPixels8(dir_ / keys[k]), played = test::readPixels8(out / frames[k]);
        ASSERT_EQ(shown.size(), played.size());
        // The same camera; only the AO's history behind it differs (a flight against the path's warm-up).
        const double same = meanDifference(shown, played);
        const double other = meanDifference(shown, test::readPixels8(out / frames[(k + 1) % 3]));
        std::printf("[ measured ] key %d: mean |viewer - flythrough| %.3f /255 (%.3f against another key's frame)\n",
                    k + 1, same, other);
        EXPECT_LT(same, 0.2) << keys[k];  // measured 0.02 to 0.03
        EXPECT_GT(other, 5.0 * same) << "the keys must show different views";
    }
}

TEST_F(CliErrors, ViewerDigsUndoesAndSavesTheWorld) {
    REQUIRE_XVFB();
    // A click at the window's centre digs a sphere out of the 16 x 16 floor; the
    // undo puts it back. Each state is saved as a world file and its .vdb, with
    // the settings the panel has then.
    const fs::path script = writeText("dig.json", R"({"actions": [
        {"frame": 1, "set": {"edit.mode": "dig", "edit.radius": 3, "lighting.exposure": 0.8, "ao.quality": "low"}},
        {"frame": 2, "click": [32, 24]},
        {"frame": 3, "save_world": "dug.vdb"}, {"frame": 4, "undo": true}, {"frame": 5, "save_world": "undone.json"}]})");
    const test::RunResult v = runGrotto("view " + good_.string() + " --size 64x48 --script " + script.string() +
                                            " --frames 6", kUnderXvfb);
    ASSERT_EQ(v.exitCode, 0) << v.err;
    EXPECT_NE(v.out.find("wrote " + (dir_ / "dug.json").string() + " and " + (dir_ / "dug.vdb").string()),
              std::string::npos) << v.out;
    for (const char* saved : {"dug.json", "undone.json"}) {
        std::ifstream in(dir_ / saved);
        const nlohmann::json world = nlohmann::json::parse(in, nullptr, false);
        ASSERT_TRUE(world.is_object()) << saved;
        EXPECT_EQ(world["grid"]["file"], std::string(saved).substr(0, std::string(saved).size() - 5) + ".vdb") << saved;
        EXPECT_NEAR(world["lighting"]["exposure"].get<double>(), 0.8, 1e-6) << saved;
        EXPECT_EQ(world["ao"]["quality"], "low") << saved;
        EXPECT_EQ(world["default_camera"], "") << saved << ": framed from the bounds, as the bare .vdb was";
    }
    auto activeVoxels = [&](const fs::path& file) {
        const test::RunResult r = runGrotto("info " + file.string());
        EXPECT_EQ(r.exitCode, 0) << r.err;
        const size_t at = r.out.find("active voxels");
        return at == std::string::npos ? -1L : std::stol(r.out.substr(at + 13));
    };
    const long dug = activeVoxels(dir_ / "dug.json"), undone = activeVoxels(dir_ / "undone.vdb");
    EXPECT_EQ(undone, 256);
    // A sphere of radius 3 voxels removes the floor voxels within 3 of its centre: 25 to 29 of them.
    EXPECT_GE(256 - dug, 20);
    EXPECT_LE(256 - dug, 37);
}

}  // namespace
}  // namespace grotto

namespace grotto {
namespace {

TEST_F(CliErrors, ViewerPlaysAWorldPathAsFlythroughRendersIt) {
    REQUIRE_XVFB();
    // Played from frame 0 at 1/60 s a frame, frame 29 shows the path at 29/60 s:
    // flythrough's frame 30 at --fps 60.
    const fs::path script = writeText("play.json", R"({"actions": [
        {"frame": 0, "set": {"play": "orbit"}}, {"frame": 29, "screenshot": "played.png"}]})");
    const std::string world = (test::worldsDir() / "rooms.json").string();
    const test::RunResult v =
        runGrotto("view " + world + " --size 320x180 --script " + script.string() + " --frames 30", kUnderXvfb);
    ASSERT_EQ(v.exitCode, 0) << v.err;
    const fs::path out = dir_ / "frames";
    const test::RunResult f =
        runGrotto("flythrough " + world + " --path orbit --fps 60 --frames 30-30 --size 320x180 -o " + out.string());
    ASSERT_EQ(f.exitCode, 0) << f.err;
    const std::vector<uint8_t> shown = test::readPixels8(dir_ / "played.png"), played = test::readPixels8(out / "frame.0030.png");
    ASSERT_EQ(shown.size(), played.size());
    const double diff = meanDifference(shown, played);
    std::printf("[ measured ] path orbit at 29/60 s: mean |viewer - flythrough| %.3f /255\n", diff);
    EXPECT_LT(diff, 0.05);  // measured 0.003
    const test::RunResult bad = runGrotto("view " + world + " --size 64x48 --frames 2 --script " +
                                              writeText("nopath.json", R"({"actions": [{"frame": 0, "set": {"play": "nope"}}]})").string(),
                                          kUnderXvfb);
    EXPECT_EQ(bad.exitCode, 2);
    EXPECT_NE(bad.err.find("set.play"), std::string::npos) << bad.err;
}

// The largest difference of two 8-bit images of the same size, in 1/255 steps.
int maxDifference(const std::vector<uint8_t>& a, const std::vector<uint8_t>& b) {
    int most = 0;
    for (size_t i = 0; i < a.size(); ++i) most = std::max(most, std::abs(int(a[i]) - int(b[i])));
    return most;
}

TEST_F(CliErrors, ViewerPlaysAPathsEditsAsFlythroughDoes) {
    REQUIRE_XVFB();
    // caves' carve path digs a sphere at 0.15 s: frame 29 (29/60 s) shows the dug
    // cave, as flythrough's frame 30 at --fps 60 does, to within one 8-bit step.
    const fs::path script = writeText("carve.json", R"({"actions": [
        {"frame": 0, "set": {"play": "carve"}}, {"frame": 29, "screenshot": "carved.png"}]})");
    const std::string world = (test::worldsDir() / "caves.json").string();
    const test::RunResult v =
        runGrotto("view " + world + " --size 160x90 --script " + script.string() + " --frames 30", kUnderXvfb);
    ASSERT_EQ(v.exitCode, 0) << v.err;
    const fs::path out = dir_ / "frames";
    const test::RunResult f =
        runGrotto("flythrough " + world + " --path carve --fps 60 --frames 30-30 --size 160x90 -o " + out.string());
    ASSERT_EQ(f.exitCode, 0) << f.err;
    const std::vector<uint8_t> shown = test::readPixels8(dir_ / "carved.png"), played = test::readPixels8(out / "frame.0030.png");
    ASSERT_EQ(shown.size(), played.size());
    const int most = maxDifference(shown, played);
    std::printf("[ measured ] caves/carve at 29/60 s: max |viewer - flythrough| %d/255, mean %.4f\n", most,
                meanDifference(shown, played));
    EXPECT_LE(most, 1);
}

TEST_F(CliErrors, ViewerRecordsTheEditsMadeWhileRecording) {
    REQUIRE_XVFB();
    // A still camera: a key at frame 2, a dig at the window's centre at frame 10,
    // a key at frame 20. The path saved carries the dig at 8/60 s; flythrough of it
    // shows the dug view the viewer showed, and without its edits it does not.
    const fs::path script = writeText("record-dig.json", R"({"actions": [
        {"frame": 1, "set": {"edit.mode": "dig", "edit.radius": 6}},
        {"frame": 2, "record": true}, {"frame": 10, "click": [80, 45]},
        {"frame": 20, "record": true}, {"frame": 20, "screenshot": "dug.png"},
        {"frame": 22, "save_path": "dig.json"}]})");
    const std::string world = (test::worldsDir() / "rooms.json").string();
    const test::RunResult v = runGrotto("view " + world + " --camera table --size 160x90 --script " +
                                            script.string() + " --frames 24", kUnderXvfb);
    ASSERT_EQ(v.exitCode, 0) << v.err;
    std::ifstream in(dir_ / "dig.json");
    nlohmann::json path = nlohmann::json::parse(in, nullptr, false);
    ASSERT_TRUE(path.is_object());
    ASSERT_EQ(path["edits"].size(), 1u) << path.dump();
    EXPECT_EQ(path["edits"][0]["op"], "carve");
    EXPECT_NEAR(path["edits"][0]["time"].get<double>(), 8.0 / 60.0, 1e-9);
    // Frame 19 of flythrough at --fps 60 is path time 18/60 s: the second key.
    auto play = [&](const fs::path& pathFile, const std::string& name) {
        const fs::path out = dir_ / name;
        const test::RunResult f = runGrotto("flythrough " + world + " --path " + pathFile.string() +
                                            " --fps 60 --frames 19-19 --size 160x90 -o " + out.string());
        EXPECT_EQ(f.exitCode, 0) << f.err;
        return test::readPixels8(out / "frame.0019.png");
    };
    const std::vector<uint8_t> shown = test::readPixels8(dir_ / "dug.png"), replayed = play(dir_ / "dig.json", "replayed");
    path.erase("edits");
    const std::vector<uint8_t> undug = play(writeText("undug.json", path.dump()), "undug");
    ASSERT_EQ(shown.size(), replayed.size());
    ASSERT_EQ(shown.size(), undug.size());
    const double same = meanDifference(shown, replayed), other = meanDifference(shown, undug);
    std::printf("[ measured ] recorded dig: mean |viewer - flythrough| %.3f /255, without the edit %.3f\n", same, other);
    EXPECT_LT(same, 0.2);
    EXPECT_GT(other, 10.0 * same + 0.5) << "the dig must show";
}

}  // namespace
}  // namespace grotto

namespace grotto {
namespace {

// A screenshot onto a full disk: exit code 1 and one line naming it, no
// truncated image under its name (once, the viewer reported it written).
TEST_F(CliErrors, ViewerScreenshotOnAFullDiskIsRefusedNotTruncated) {
    test::SmallDisk disk(256 << 10);
    if (!disk.mounted()) GTEST_SKIP() << disk.reason();
    REQUIRE_XVFB();
    disk.fillLeaving(0);
    const fs::path shot = disk / "shot.png";
    const test::RunResult v =
        runGrotto("view " + good_.string() + " --size 64x48 --frames 3 --screenshot " + shot.string(), kUnderXvfb);
    EXPECT_EQ(v.exitCode, 1) << v.err;
    EXPECT_EQ(std::count(v.err.begin(), v.err.end(), '\n'), 1) << v.err;
    EXPECT_NE(v.err.find(shot.string() + ": cannot be written: No space left on device"), std::string::npos) << v.err;
    EXPECT_FALSE(fs::exists(shot));
}

// Every pixel grey: R = G = B, as an AO view draws it.
bool grey(const std::vector<uint8_t>& rgb) {
    for (size_t i = 0; i + 2 < rgb.size(); i += 3)
        if (rgb[i] != rgb[i + 1] || rgb[i] != rgb[i + 2]) return false;
    return !rgb.empty();
}

TEST_F(CliErrors, ViewerScreenshotsWriteWhatTheViewShows) {
    REQUIRE_XVFB();
    // The AO view: the script's screenshot, --screenshot at exit and the window
    // captured at the last frame all show that frame's AO, not its colour.
    const fs::path script = writeText("ao.json", R"({"actions": [
        {"frame": 1, "set": {"view": "ao"}}, {"frame": 4, "screenshot": "shot.png"}]})");
    const fs::path shot = dir_ / "shot.png", atExit = dir_ / "exit.png", window = dir_ / "window.png";
    const test::RunResult v = runGrotto("view " + (test::worldsDir() / "rooms.json").string() +
                                            " --camera table --size 96x64 --hide-panel --script " + script.string() +
                                            " --frames 5 --screenshot " + atExit.string() + " --capture-window " +
                                            window.string(),
                                        kUnderXvfb);
    ASSERT_EQ(v.exitCode, 0) << v.err;
    EXPECT_NE(v.out.find("wrote " + window.string()), std::string::npos) << v.out;
    const std::vector<uint8_t> a = test::readPixels8(shot), b = test::readPixels8(atExit), w = test::readPixels8(window);
    EXPECT_TRUE(grey(a)) << "the screenshot is not the AO view";
    EXPECT_EQ(a, b) << "--screenshot at exit shows the same frame as the script's last screenshot";
    // The window blits the same values; the GPU's sRGB encoding may round the other way.
    EXPECT_LE(test::worstDifference(a, w), 1);
}

TEST_F(CliErrors, ViewerShowsToneMappedColourAndWritesSceneLinearExr) {
    REQUIRE_XVFB();
    // The final view of a bright world: the window (the display pass) and a PNG
    // screenshot (the CPU's tone map) agree, and an EXR of the same frame is its
    // scene-linear colour.
    const fs::path world = writeText("bright.json", test::brightWorld("filmic"));
    const fs::path script = writeText("final.json", R"({"actions": [{"frame": 3, "screenshot": "shot.png"}]})");
    const fs::path shot = dir_ / "shot.png", exr = dir_ / "shot.exr", window = dir_ / "window.png";
    const test::RunResult v = runGrotto("view " + world.string() + " --camera c --size 96x64 --hide-panel --script " +
                                            script.string() + " --frames 4 --screenshot " + exr.string() +
                                            " --capture-window " + window.string(),
                                        kUnderXvfb);
    ASSERT_EQ(v.exitCode, 0) << v.err;
    test::expectSceneLinear(test::compareExrWithPng(exr, shot), "viewer screenshot");
    // The display image is half floats: a value may round across an 8-bit step.
    EXPECT_LE(test::worstDifference(test::readPixels8(shot), test::readPixels8(window)), 1);
}

TEST_F(CliErrors, ViewerPrintsTheNamesOfWhatItWritesEscaped) {
    REQUIRE_XVFB();
    // Names from a script with a terminal escape and a newline in them: written
    // under those names, printed escaped, one line each.
    const fs::path script = writeText("names.json", R"({"actions": [
        {"frame": 1, "save_world": "a\u001b[2Jb\nc.vdb"}, {"frame": 2, "screenshot": "s\u001b]0;t\u0007.png"}]})");
    const test::RunResult v =
        runGrotto("view " + good_.string() + " --size 32x24 --script " + script.string() + " --frames 3", kUnderXvfb);
    ASSERT_EQ(v.exitCode, 0) << v.err;
    const fs::path world = dir_ / "a\x1b[2Jb\nc.vdb", worldFile = dir_ / "a\x1b[2Jb\nc.json", shot = dir_ / "s\x1b]0;t\x07.png";
    EXPECT_TRUE(fs::exists(world));
    EXPECT_TRUE(fs::exists(worldFile));
    EXPECT_TRUE(fs::exists(shot));
    EXPECT_EQ(v.out.find('\x1b'), std::string::npos) << printable(v.out);
    EXPECT_EQ(v.out.find('\x07'), std::string::npos) << printable(v.out);
    EXPECT_EQ(std::count(v.out.begin(), v.out.end(), '\n'), 2) << printable(v.out);
    EXPECT_NE(v.out.find("wrote " + printable(worldFile.string()) + " and " + printable(world.string()) + "\n"),
              std::string::npos)
        << printable(v.out);
    EXPECT_NE(v.out.find("wrote " + printable(shot.string()) + " (32x24)\n"), std::string::npos) << printable(v.out);
}

}  // namespace
}  // namespace grotto
