// flythrough --video: the frames piped to ffmpeg make a video with every frame
// at the rendered size; without ffmpeg on PATH, or when ffmpeg fails, the run
// fails clearly and leaves no file. Skipped where ffmpeg is not installed.
#include "tests/cli_fixture.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <future>
#include <iterator>
#include <sstream>
#include <thread>

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

// What ffprobe counts in a video's first stream: frames decoded, width, height;
// its codec and the container's format.
struct Probe {
    int frames = -1, width = -1, height = -1;
    std::string pixelFormat, codec, container;
};
Probe probe(const fs::path& video) {
    const std::string cmd = onPath("ffprobe").string() + " -v error -count_frames -select_streams v:0 -show_entries "
                            "stream=nb_read_frames,width,height,pix_fmt,codec_name:format=format_name -of json '" +
                            video.string() + "'";
    std::FILE* p = popen(cmd.c_str(), "r");
    if (!p) return {};
    std::string text;
    char buf[4096];
    for (size_t n; (n = std::fread(buf, 1, sizeof buf, p)) > 0;) text.append(buf, n);
    pclose(p);
    const nlohmann::json j = nlohmann::json::parse(text, nullptr, false);
    if (j.is_discarded() || !j.contains("streams") || j["streams"].empty()) return {};
    const nlohmann::json& s = j["streams"][0];
    return {std::stoi(s.value("nb_read_frames", "-1")), s.value("width", -1), s.value("height", -1), s.value("pix_fmt", ""),
            s.value("codec_name", ""), j.contains("format") ? j["format"].value("format_name", "") : ""};
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
    // A PATH whose ffmpeg is this shell script.
    std::string fakeFfmpeg(const std::string& script) {
        fs::create_directory(dir_ / "bin");
        std::ofstream(dir_ / "bin" / "ffmpeg") << "#!/bin/sh\n" << script << "\n";
        fs::permissions(dir_ / "bin" / "ffmpeg", fs::perms::owner_all);
        return "PATH=" + (dir_ / "bin").string() + ":/usr/bin:/bin";
    }
    void expectNoTemporaries() {
        for (auto& e : fs::directory_iterator(dir_.path))
            EXPECT_EQ(e.path().filename().string().find(".tmp"), std::string::npos) << "left behind: " << e.path();
    }

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
    const std::string path = fakeFfmpeg("echo 'Unknown encoder libx264' >&2\nexit 1");
    const test::RunResult r = runGrotto(flythrough("--video " + video().string()), path);
    EXPECT_EQ(r.exitCode, 1) << r.err;
    EXPECT_NE(r.err.find("Unknown encoder libx264"), std::string::npos) << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    EXPECT_FALSE(fs::exists(video()));
    for (auto& e : fs::directory_iterator(dir_.path))
        EXPECT_EQ(e.path().filename().string().find(".tmp"), std::string::npos) << "left behind: " << e.path();
}

// The extension chooses the container and its codec: H.264 in .mp4, .mov and
// .mkv, VP9 in .webm; any other extension is refused, naming the ones accepted.
TEST_F(FlythroughVideo, TheExtensionChoosesTheContainer) {
    for (const char* refused : {"fly.gif", "fly.avi", "fly"})
        expectRefused(flythrough("--video " + (dir_ / refused).string()), "accepted extensions: .mp4, .mov, .mkv, .webm",
                      dir_ / refused);
    struct Case {
        const char* name;
        const char* codec;
        const char* container;
    };
    for (const Case& c : {Case{"fly.webm", "vp9", "matroska,webm"}, Case{"fly.MKV", "h264", "matroska,webm"},
                          Case{"fly.mov", "h264", "mov,mp4,m4a,3gp,3g2,mj2"}}) {
        const test::RunResult r = runGrotto(flythrough("--video " + (dir_ / c.name).string()));
        ASSERT_EQ(r.exitCode, 0) << c.name << ": " << r.err;
        const Probe p = probe(dir_ / c.name);
        EXPECT_EQ(p.frames, 9) << c.name;
        EXPECT_EQ(p.codec, c.codec) << c.name;
        EXPECT_EQ(p.container, c.container) << c.name;
        EXPECT_EQ(p.pixelFormat, "yuv420p") << c.name;
    }
}

// An ffmpeg that never reads its input gets GROTTO_VIDEO_TIMEOUT seconds to take
// a frame (a 320x240 frame is more than the pipe holds) or to finish (the 48x32
// frames all fit in the pipe), then the run fails with exit code 1.
TEST_F(FlythroughVideo, AnFfmpegThatNeverReadsIsGivenUp) {
    const std::string path = fakeFfmpeg("exec sleep 600");
    for (const char* size : {"320x240", "48x32"}) {
        const auto start = std::chrono::steady_clock::now();
        const test::RunResult r =
            runGrotto(flythrough("--video " + video().string(), size), path + " GROTTO_VIDEO_TIMEOUT=2", {.hangSeconds = 120});
        EXPECT_EQ(r.exitCode, 1) << size << ": " << r.err;
        EXPECT_NE(r.err.find("GROTTO_VIDEO_TIMEOUT"), std::string::npos) << r.err;
        EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
        EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(), 60.0) << size;
        EXPECT_FALSE(fs::exists(video()));
        expectNoTemporaries();
    }
    expectRefused(flythrough("--video " + video().string()), "GROTTO_VIDEO_TIMEOUT", video(), "GROTTO_VIDEO_TIMEOUT=soon");
}

// One that never reads at all is given up 10 s after it started, whatever
// GROTTO_VIDEO_TIMEOUT (300 s by default) allows an ffmpeg that is reading.
TEST_F(FlythroughVideo, AnFfmpegThatNeverStartsReadingIsGivenUpSoon) {
    const std::string path = fakeFfmpeg("exec sleep 600");
    // A write that waits; frames that all fit in the pipe. Both at once: each waits its 10 s.
    const std::string sizes[] = {"320x240", "48x32"};
    auto videoOf = [&](const std::string& size) { return dir_ / ("fly-" + size + ".mp4"); };
    std::vector<std::future<test::RunResult>> runs;
    for (const std::string& size : sizes)
        runs.push_back(std::async(std::launch::async, [&, size] {
            return runGrotto(flythrough("--video " + videoOf(size).string(), size), path, {.hangSeconds = 60});
        }));
    for (size_t k = 0; k < runs.size(); ++k) {
        const test::RunResult r = runs[k].get();
        EXPECT_EQ(r.exitCode, 1) << sizes[k] << ": " << r.err;
        EXPECT_NE(r.err.find("read none of its input in the 10 s after it started"), std::string::npos) << r.err;
        EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
        EXPECT_FALSE(fs::exists(videoOf(sizes[k])));
    }
    expectNoTemporaries();
}

// ffmpeg exiting 0 is not trusted: the video must read back with every frame.
TEST_F(FlythroughVideo, AVideoThatDoesNotReadBackIsNotCommitted) {
    // Writes a file that is not a video, and says all went well.
    const std::string path = fakeFfmpeg("cat >/dev/null\nfor last; do :; done\necho 'not a video' > \"$last\"\nexit 0");
    const test::RunResult r = runGrotto(flythrough("--video " + video().string()), path);
    EXPECT_EQ(r.exitCode, 1) << r.err;
    EXPECT_NE(r.err.find("does not read back"), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(video()));
    expectNoTemporaries();
}

// A run killed with SIGKILL leaves its hidden temporary video; the next run removes it.
TEST_F(FlythroughVideo, AKilledRunsTemporaryVideoIsRemovedByTheNextRun) {
    const int pid = test::startGrotto("flythrough " + world_.string() + " --path p --size 48x32 --fps 400 --video " +
                                      video().string());  // 401 frames
    auto temporary = [&] {
        for (auto& e : fs::directory_iterator(dir_.path))
            if (e.path().filename().string().rfind(".fly.tmp", 0) == 0) return true;
        return false;
    };
    bool killed = false;
    for (int k = 0; k < 60000 && !killed; ++k) {
        if (temporary()) killed = kill(pid, SIGKILL) == 0;
        else if (waitpid(pid, nullptr, WNOHANG) == pid) break;
        else std::this_thread::sleep_for(std::chrono::milliseconds(1));
    }
    if (killed) waitpid(pid, nullptr, 0);
    ASSERT_TRUE(killed) << "the run never started its video";
    ASSERT_TRUE(temporary());
    const test::RunResult r = runGrotto(flythrough("--video " + video().string()));
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_EQ(probe(video()).frames, 9);
    expectNoTemporaries();
}

TEST_F(FlythroughVideo, AKilledRunTakesItsEncoderWithIt) {
    // An encoder that never reads nor ends: left behind, it would outlive the run
    // (a real ffmpeg finishes the temporary, and with +faststart writes it again,
    // after the next run has cleared it).
    const std::string path = fakeFfmpeg("for last; do :; done\ntouch \"$last\"\nwhile :; do sleep 1; done");
    const int pid = test::startGrotto(flythrough("--video " + video().string()), path);
    auto encoders = [&] {  // processes running this test's fake ffmpeg
        int n = 0;
        for (auto& e : fs::directory_iterator("/proc")) {
            // A process can end between the open and the read; libstdc++'s filebuf
            // then throws (ESRCH), and such a process is no encoder any more.
            std::string line;
            try {
                std::ifstream in(e.path() / "cmdline");
                line.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
            } catch (const std::ios_base::failure&) {
                continue;
            }
            n += line.find((dir_ / "bin" / "ffmpeg").string()) != std::string::npos;
        }
        return n;
    };
    bool killed = false;
    for (int k = 0; k < 60000 && !killed; ++k) {
        if (encoders() > 0) killed = kill(pid, SIGKILL) == 0;
        else if (waitpid(pid, nullptr, WNOHANG) == pid) break;
        else std::this_thread::sleep_for(std::chrono::milliseconds(1));
    }
    if (killed) waitpid(pid, nullptr, 0);
    ASSERT_TRUE(killed) << "the run never started its encoder";
    for (int k = 0; k < 200 && encoders() > 0; ++k) std::this_thread::sleep_for(std::chrono::milliseconds(10));
    EXPECT_EQ(encoders(), 0) << "the encoder outlived the killed run";
}

}  // namespace
}  // namespace grotto
