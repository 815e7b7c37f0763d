// flythrough --video: the frames piped to ffmpeg make a video with every frame
// at the rendered size; without ffmpeg on PATH, or when ffmpeg fails, the run
// fails clearly and leaves no file. Skipped where ffmpeg is not installed.
#include "tests/cli_fixture.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>

namespace grotto {
namespace {

namespace fs = std::filesystem;
using test::CliErrors;
using test::runGrotto;

// A program's path on PATH, or empty.
fs::path onPath(const std::string& program) {
    std::stringstream dirs(std::getenv("PATH") ? std::getenv("PATH") : "");
    for (std::string dir; std::getline(dirs, dir, ':');)
        if (!dir.empty() && access((fs::path(dir) / program).c_str(), X_OK) == 0) return fs::path(dir) / program;
    return {};
}

// What ffprobe counts in a video's first stream: frames decoded, width, height.
struct Probe {
    int frames = -1, width = -1, height = -1;
    std::string pixelFormat;
};
Probe probe(const fs::path& video) {
    const std::string cmd = onPath("ffprobe").string() + " -v error -count_frames -select_streams v:0 -show_entries "
                            "stream=nb_read_frames,width,height,pix_fmt -of json '" + video.string() + "'";
    std::FILE* p = popen(cmd.c_str(), "r");
    if (!p) return {};
    std::string text;
    char buf[4096];
    for (size_t n; (n = std::fread(buf, 1, sizeof buf, p)) > 0;) text.append(buf, n);
    pclose(p);
    const nlohmann::json j = nlohmann::json::parse(text, nullptr, false);
    if (j.is_discarded() || !j.contains("streams") || j["streams"].empty()) return {};
    const nlohmann::json& s = j["streams"][0];
    return {std::stoi(s.value("nb_read_frames", "-1")), s.value("width", -1), s.value("height", -1), s.value("pix_fmt", "")};
}

class FlythroughVideo : public CliErrors {
protected:
    void SetUp() override {
        if (onPath("ffmpeg").empty() || onPath("ffprobe").empty())
            GTEST_SKIP() << "ffmpeg is not installed (apt-get install ffmpeg, or scripts/setup.sh)";
        CliErrors::SetUp();
        world_ = writeFlyWorld();  // 9 frames at --fps 8
    }
    std::string flythrough(const std::string& flags, const std::string& size = "48x32") const {
        return "flythrough " + world_.string() + " --path p --size " + size + " --fps 8 " + flags;
    }
    fs::path video() const { return dir_ / "fly.mp4"; }

    fs::path world_;
};

TEST_F(FlythroughVideo, DecodesToEveryFrameAtTheRenderedSize) {
    test::RunResult r = runGrotto(flythrough("--video " + video().string()));
    ASSERT_EQ(r.exitCode, 0) << r.err;
    Probe p = probe(video());
    EXPECT_EQ(p.frames, 9);
    EXPECT_EQ(p.width, 48);
    EXPECT_EQ(p.height, 32);
    EXPECT_EQ(p.pixelFormat, "yuv420p");
    EXPECT_EQ(std::distance(fs::directory_iterator(dir_.path), fs::directory_iterator()), 3) << "a video and nothing more";

    // A range, with the frames written too.
    r = runGrotto(flythrough("--frames 3-7 --video " + video().string() + " -o " + (dir_ / "seq").string()));
    ASSERT_EQ(r.exitCode, 0) << r.err;
    p = probe(video());
    EXPECT_EQ(p.frames, 5);
    EXPECT_TRUE(fs::exists(dir_ / "seq" / "frame.0007.png"));
    EXPECT_FALSE(fs::exists(dir_ / "seq" / "frame.0002.png"));
}

TEST_F(FlythroughVideo, WithoutFfmpegOnPathTheRunIsRefused) {
    const test::RunResult r = expectRefused(flythrough("--video " + video().string()), "ffmpeg", video(), "PATH=/nonexistent");
    EXPECT_NE(r.err.find("apt-get install ffmpeg"), std::string::npos) << r.err;
    expectRefused(flythrough("--video " + video().string(), "47x32"), "--video", video());
}

TEST_F(FlythroughVideo, FfmpegFailingFailsTheRunWithItsMessage) {
    // An ffmpeg that refuses its input, as one without libx264 would.
    fs::create_directory(dir_ / "bin");
    std::ofstream(dir_ / "bin" / "ffmpeg") << "#!/bin/sh\necho 'Unknown encoder libx264' >&2\nexit 1\n";
    fs::permissions(dir_ / "bin" / "ffmpeg", fs::perms::owner_all);
    const std::string path = "PATH=" + (dir_ / "bin").string() + ":/usr/bin:/bin";
    const test::RunResult r = runGrotto(flythrough("--video " + video().string()), path);
    EXPECT_EQ(r.exitCode, 1) << r.err;
    EXPECT_NE(r.err.find("Unknown encoder libx264"), std::string::npos) << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    EXPECT_FALSE(fs::exists(video()));
    for (auto& e : fs::directory_iterator(dir_.path))
        EXPECT_EQ(e.path().filename().string().find(".tmp"), std::string::npos) << "left behind: " << e.path();
}

}  // namespace
}  // namespace grotto
