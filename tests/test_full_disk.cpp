// Outputs onto a full disk: a small tmpfs the test fills up (skipped, saying
// why, where it cannot be mounted), and a file-size limit (RLIMIT_FSIZE) that
// fails writes the same way anywhere. Every writer must fail with exit code 1
// and one line saying the disk is full, leave no file under the target's name
// and no temporary file, and a flythrough resumed with room again must repair
// what the failed run could not write.
#include "tests/cli_fixture.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <unistd.h>

#include <algorithm>
#include <fstream>
#include <map>

namespace grotto {
namespace {

namespace fs = std::filesystem;
using test::CliErrors;
using test::runGrotto;

// No file under `dir` (recursively) with a temporary's name.
void expectNoTemporaries(const fs::path& dir) {
    for (const auto& e : fs::recursive_directory_iterator(dir))
        EXPECT_EQ(e.path().filename().string().find(".tmp"), std::string::npos) << "left behind: " << e.path();
}

// Exit code 1 and one stderr line naming `target` and saying why.
void expectDiskFull(const test::RunResult& r, const fs::path& target, const std::string& why = "No space left on device") {
    EXPECT_EQ(r.exitCode, 1) << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    EXPECT_NE(r.err.find(target.string()), std::string::npos) << r.err;
    EXPECT_NE(r.err.find(why), std::string::npos) << r.err;
}

class FullDisk : public CliErrors {
protected:
    void SetUp() override {
        if (!disk_.mounted()) GTEST_SKIP() << disk_.reason();
        CliErrors::SetUp();
    }
    std::string renderTo(const fs::path& out, const std::string& flags = "") const {
        return "render " + (test::worldsDir() / "rooms.json").string() + " --size 64x32 --accumulate 1 " + flags +
               " -o " + out.string();
    }

    test::SmallDisk disk_{256 << 10};
};

TEST_F(FullDisk, ImagesAndGridsAreRefusedNotTruncated) {
    disk_.fillLeaving(0);
    for (const char* name : {"out.png", "out.exr"}) {
        const fs::path out = disk_ / name;
        expectDiskFull(runGrotto(renderTo(out)), out);
        EXPECT_FALSE(fs::exists(out)) << "a truncated image under its name";
    }
    const fs::path world = disk_ / "world.vdb";
    expectDiskFull(runGrotto("mkworld rooms --size 32 -o " + world.string()), world);
    EXPECT_FALSE(fs::exists(world));
    expectNoTemporaries(disk_.path());
}

TEST_F(FullDisk, AnImageThatFillsTheDiskHalfWayIsRefused) {
    // Room for the EXR's first bytes, not for all of them.
    disk_.fillLeaving(4096);
    const fs::path out = disk_ / "out.exr";
    expectDiskFull(runGrotto(renderTo(out, "--aov")), out);
    EXPECT_FALSE(fs::exists(out));
    expectNoTemporaries(disk_.path());
}

TEST_F(FullDisk, AFlythroughStopsAtTheFullDiskAndAResumeWithRoomFinishesIt) {
    const std::string run = "flythrough " + writeFlyWorld().string() + " --path p --size 48x32 --fps 8 -o " + (disk_ / "seq").string();
    disk_.fillLeaving(16 << 10);  // the manifest and a few frames
    const test::RunResult full = runGrotto(run);
    EXPECT_EQ(full.exitCode, 1) << full.err;
    EXPECT_NE(full.err.find("No space left on device"), std::string::npos) << full.err;
    for (const auto& e : fs::directory_iterator(disk_ / "seq"))
        if (e.path().extension() == ".png") EXPECT_FALSE(test::readPixels8(e.path()).empty()) << "damaged: " << e.path();
    expectNoTemporaries(disk_.path());

    disk_.makeRoom();
    const test::RunResult resumed = runGrotto(run);
    ASSERT_EQ(resumed.exitCode, 0) << resumed.err;
    for (int i = 1; i <= 9; ++i)
        EXPECT_FALSE(test::readPixels8(disk_ / "seq" / ("frame.000" + std::to_string(i) + ".png")).empty()) << i;
    std::ifstream in(disk_ / "seq" / "stats.json");
    const nlohmann::json stats = nlohmann::json::parse(in);
    EXPECT_EQ(std::count_if(stats["frames"].begin(), stats["frames"].end(), [](const nlohmann::json& f) { return f["written"].get<bool>(); }),
              9);
}

TEST_F(FullDisk, AVideoThatDoesNotFitIsRefused) {
    if (std::system("command -v ffmpeg >/dev/null && command -v ffprobe >/dev/null") != 0)
        GTEST_SKIP() << "ffmpeg is not installed (apt-get install ffmpeg, or scripts/setup.sh)";
    // Room for the video's header, not its frames: ffmpeg itself exits 0 here.
    disk_.fillLeaving(4096);
    const fs::path video = disk_ / "v.mp4";
    const test::RunResult r = runGrotto("flythrough " + (test::worldsDir() / "rooms.json").string() +
                                        " --path orbit --size 48x32 --fps 8 --frames 9 --video " + video.string());
    expectDiskFull(r, video);
    EXPECT_FALSE(fs::exists(video));
    expectNoTemporaries(disk_.path());
}

// The same failure without a filesystem of its own: writes beyond a file-size
// limit fail (EFBIG) as writes onto a full disk do. Runs wherever the tests run.
TEST_F(CliErrors, AnImageBeyondTheFileSizeLimitIsRefusedNotTruncated) {
    for (const char* name : {"big.png", "big.exr"}) {
        const fs::path out = dir_ / name;
        const test::RunResult r = runGrotto("render " + (test::worldsDir() / "rooms.json").string() +
                                                " --size 256x128 --accumulate 1 -o " + out.string(),
                                            "", {.fileBytes = 1024});
        expectDiskFull(r, out, "File too large");
        EXPECT_FALSE(fs::exists(out));
    }
    expectNoTemporaries(dir_.path);
}

// A resume decodes the frames it would skip: one a failed write left damaged
// (by an earlier version, or a disk that lied) is rendered again, to the same pixels.
TEST_F(CliErrors, AResumeRendersDamagedFramesAgain) {
    const fs::path seq = dir_ / "seq";
    const std::string run = "flythrough " + writeFlyWorld().string() + " --path p --size 32x16 --fps 8 -o " + seq.string();
    ASSERT_EQ(runGrotto(run).exitCode, 0);
    const std::vector<uint8_t> third = test::readPixels8(seq / "frame.0003.png"),
                               fifth = test::readPixels8(seq / "frame.0005.png");
    ASSERT_FALSE(third.empty());
    fs::resize_file(seq / "frame.0003.png", fs::file_size(seq / "frame.0003.png") / 2);
    std::ofstream(seq / "frame.0005.png", std::ios::trunc);  // empty, as a full disk left it before
    ASSERT_TRUE(test::readPixels8(seq / "frame.0003.png").empty());

    const test::RunResult r = runGrotto(run);
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_EQ(test::readPixels8(seq / "frame.0003.png"), third);
    EXPECT_EQ(test::readPixels8(seq / "frame.0005.png"), fifth);
}

}  // namespace
}  // namespace grotto
