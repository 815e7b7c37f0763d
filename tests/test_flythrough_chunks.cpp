// Flythroughs that share a directory: render-farm chunks running at the same
// time (--frames ranges and --chunk K/N), and runs that resume after one was
// killed mid-frame.
#include "tests/cli_fixture.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <fcntl.h>
#include <sys/file.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <fstream>
#include <future>
#include <map>
#include <thread>

namespace grotto {
namespace {

namespace fs = std::filesystem;
using test::CliErrors;
using test::runGrotto;

class FlythroughChunks : public CliErrors {
protected:
    void SetUp() override {
        CliErrors::SetUp();
        world_ = writeFlyWorld();  // 9 frames at --fps 8
    }
    std::string flythrough(const std::string& frames) const {
        return "flythrough " + world_.string() + " --path p --size 16x8 --fps 8 --frames " + frames + " -o " + seq().string();
    }
    fs::path seq() const { return dir_ / "seq"; }
    nlohmann::json stats() const {
        std::ifstream in(seq() / "stats.json");
        return nlohmann::json::parse(in);
    }
    void writeStats(const nlohmann::json& stats) const { std::ofstream(seq() / "stats.json") << stats.dump(); }

    // Starts `args` and kills it (SIGKILL) once `file` appears; false when the
    // run ended first or `file` never came.
    static bool killWhenThere(const std::string& args, const fs::path& file) {
        const pid_t pid = test::startGrotto(args);
        bool killed = false;
        for (int k = 0; k < 60000 && !killed; ++k) {
            if (fs::exists(file)) killed = kill(pid, SIGKILL) == 0;
            else if (waitpid(pid, nullptr, WNOHANG) == pid) return false;
            else std::this_thread::sleep_for(std::chrono::milliseconds(1));
        }
        int status = 0;
        waitpid(pid, &status, 0);
        return killed && WIFSIGNALED(status);
    }

    fs::path world_;
};

TEST_F(FlythroughChunks, ConcurrentChunksKeepEveryFrameInTheStats) {
    // Each chunk renders the frames before its range as warm-up: the second one
    // renders frames 1-4 too, but must not record the first one's as warm-up.
    auto first = std::async(std::launch::async, [&] { return runGrotto(flythrough("1-4")); });
    auto second = std::async(std::launch::async, [&] { return runGrotto(flythrough("5-9")); });
    const test::RunResult a = first.get(), b = second.get();
    ASSERT_EQ(a.exitCode, 0) << a.err;
    ASSERT_EQ(b.exitCode, 0) << b.err;
    std::ifstream in(seq() / "stats.json");
    const nlohmann::json stats = nlohmann::json::parse(in);
    std::map<int, bool> written;
    for (const nlohmann::json& f : stats["frames"]) written[f["frame"].get<int>()] = f["written"].get<bool>();
    ASSERT_EQ(written.size(), 9u) << stats.dump();
    for (auto [frame, w] : written) EXPECT_TRUE(w) << "frame " << frame << " recorded as warm-up";
    for (int i = 1; i <= 9; ++i) EXPECT_TRUE(fs::exists(seq() / ("frame.000" + std::to_string(i) + ".png")));
}

TEST_F(FlythroughChunks, AResumedRunRemovesTheTemporariesOfKilledRuns) {
    ASSERT_EQ(runGrotto(flythrough("1-2")).exitCode, 0);
    // What a run killed mid-frame leaves: a hidden temporary frame nobody holds.
    const fs::path abandoned = seq() / ".frame.0003.tmp4194000-0.png";
    std::ofstream(abandoned) << "half a frame";
    // One that a live run is still writing (it holds the lock) stays, and so do
    // files that are not the flythrough's.
    const fs::path live = seq() / ".frame.0009.tmp4194001-0.png";
    std::ofstream(live) << "being written";
    const int fd = open(live.c_str(), O_RDONLY);
    ASSERT_EQ(flock(fd, LOCK_EX), 0);
    const fs::path foreign = seq() / ".notes.tmp4194002-0.txt";
    std::ofstream(foreign) << "someone else's";

    const test::RunResult r = runGrotto(flythrough("3-4"));
    close(fd);
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_FALSE(fs::exists(abandoned));
    EXPECT_TRUE(fs::exists(live));
    EXPECT_TRUE(fs::exists(foreign));
    EXPECT_TRUE(fs::exists(seq() / "frame.0003.png"));
}

// A farm's tasks: three --chunk runs of one sequence at once into one directory
// against a single whole run. Caves' walk at --fps 8 has 177 frames, so chunk 3
// (frames 119-177) starts its 64 warm-up frames at 55, its history cut short,
// and must still land within docs/paths.md's 2/255 of the whole run. Under the
// sanitizers, 111 frames at --fps 5 and a smaller image: chunk 3 (75-111) starts
// its warm-up at 11, still cut short.
TEST_F(FlythroughChunks, ConcurrentChunksMatchASingleRun) {
    const int fps = test::underSanitizers(8, 5), frames = test::underSanitizers(177, 111);
    const std::string base = "flythrough " + (test::worldsDir() / "caves.json").string() + " --path walk --size " +
                             (test::kAddressSanitizer ? "96x54" : "160x90") + " --fps " + std::to_string(fps) + " ";
    const fs::path whole = dir_ / "whole";
    const test::RunResult single = runGrotto(base + "-o " + whole.string());
    ASSERT_EQ(single.exitCode, 0) << single.err;
    std::vector<std::future<test::RunResult>> chunks;
    for (int k = 1; k <= 3; ++k)
        chunks.push_back(std::async(std::launch::async, [&, k] {
            return runGrotto(base + "--chunk " + std::to_string(k) + "/3 -o " + seq().string());
        }));
    for (auto& c : chunks) {
        const test::RunResult r = c.get();
        ASSERT_EQ(r.exitCode, 0) << r.err;
    }
    std::ifstream in(seq() / "stats.json");
    const nlohmann::json stats = nlohmann::json::parse(in);
    std::map<int, bool> written;
    for (const nlohmann::json& f : stats["frames"]) written[f["frame"].get<int>()] = f["written"].get<bool>();
    ASSERT_EQ(written.size(), size_t(frames));
    int worst = 0;
    for (int i = 1; i <= frames; ++i) {
        EXPECT_TRUE(written[i]) << "frame " << i << " recorded as warm-up";
        char name[32];
        std::snprintf(name, sizeof name, "frame.%04d.png", i);
        const std::vector<uint8_t> a = test::readPixels8(whole / name), b = test::readPixels8(seq() / name);
        ASSERT_FALSE(a.empty()) << name;
        ASSERT_FALSE(b.empty()) << name;
        worst = std::max(worst, test::worstDifference(a, b));
    }
    EXPECT_LE(worst, 2) << "the worst frame's largest difference, in 8-bit levels";
    std::printf("[ measured ] 3 concurrent chunks against one run: largest difference %d/255\n", worst);
}

// With a bake (--ao cache) there is no history: chunks render no warm-up frames
// and are the single run bit for bit.
TEST_F(FlythroughChunks, BakedChunksNeedNoWarmUpAndAreOneRunExactly) {
    const fs::path bake = dir_ / "fly.gfc", whole = dir_ / "whole";
    ASSERT_EQ(runGrotto("bake " + world_.string() + " -o " + bake.string() + " --rays 8 --sun-rays 1").exitCode, 0);
    const std::string base = "flythrough " + world_.string() + " --path p --size 16x8 --fps 8 --bake " + bake.string() + " ";
    const test::RunResult single = runGrotto(base + "-o " + whole.string());
    ASSERT_EQ(single.exitCode, 0) << single.err;
    for (int k = 1; k <= 3; ++k) {
        const test::RunResult r = runGrotto(base + "--chunk " + std::to_string(k) + "/3 -o " + seq().string());
        ASSERT_EQ(r.exitCode, 0) << r.err;
    }
    const nlohmann::json s = stats();
    ASSERT_EQ(s["frames"].size(), 9u);
    for (const nlohmann::json& f : s["frames"]) {
        EXPECT_TRUE(f["written"].get<bool>()) << "frame " << f["frame"] << " rendered as warm-up";
        char name[32];
        std::snprintf(name, sizeof name, "frame.%04d.png", f["frame"].get<int>());
        const std::vector<uint8_t> a = test::readPixels8(whole / name), b = test::readPixels8(seq() / name);
        ASSERT_FALSE(a.empty()) << name;
        EXPECT_TRUE(a == b) << name;
    }
}

// kill -9 and the same command again: the frames the killed run wrote end up
// marked written in stats.json (docs/farm.md's completion check), every frame is
// there, and nothing the killed run was writing is left behind.
TEST_F(FlythroughChunks, AKilledRunRerunEndsWithEveryFrameRecorded) {
    const std::string run = "flythrough " + world_.string() + " --path p --size 16x8 --fps 200 -o " + seq().string();
    ASSERT_TRUE(killWhenThere(run, seq() / "frame.0010.png")) << "the run was not killed mid-way";
    ASSERT_FALSE(fs::exists(seq() / "frame.0201.png")) << "the run ended before it was killed";
    const test::RunResult r = runGrotto(run);
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const nlohmann::json recorded = stats();
    int written = 0;
    for (const nlohmann::json& f : recorded["frames"]) written += f["written"].get<bool>();
    EXPECT_EQ(written, 201);
    char name[32];
    for (int i = 1; i <= 201; ++i) {
        std::snprintf(name, sizeof name, "frame.%04d.png", i);
        EXPECT_TRUE(fs::exists(seq() / name)) << name;
    }
    for (const auto& e : fs::directory_iterator(seq()))
        EXPECT_EQ(e.path().filename().string().find(".tmp"), std::string::npos) << "left behind: " << e.path();
}

// A run killed before its first frame leaves flythrough.json alone in the
// directory: a run with other settings takes the directory, and the stats start afresh.
TEST_F(FlythroughChunks, ADirectoryWithoutFramesTakesOtherSettings) {
    const std::string run = "flythrough " + world_.string() + " --path p --fps 8 --frames 1-2 -o " + seq().string();
    ASSERT_TRUE(killWhenThere(run + " --size 16x8", seq() / "flythrough.json"));
    ASSERT_FALSE(fs::exists(seq() / "frame.0001.png")) << "killed too late: a frame is there";
    test::RunResult r = runGrotto(run + " --size 32x16");
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_EQ(test::readPixels8(seq() / "frame.0001.png").size(), 32u * 16u * 3u);

    // Frames deleted by hand, their stats kept: the same.
    fs::remove(seq() / "frame.0001.png");
    fs::remove(seq() / "frame.0002.png");
    r = runGrotto("flythrough " + world_.string() + " --path p --fps 8 --frames 2-2 --size 16x8 -o " + seq().string());
    ASSERT_EQ(r.exitCode, 0) << r.err;
    // Frame 1 is warm-up now: the entry of the run whose frame is gone is not kept.
    const nlohmann::json recorded = stats();
    ASSERT_EQ(recorded["frames"].size(), 2u);
    EXPECT_FALSE(recorded["frames"][0]["written"].get<bool>()) << recorded.dump();
    EXPECT_TRUE(recorded["frames"][1]["written"].get<bool>()) << recorded.dump();
}

// A directory of other settings is refused naming the setting, what it was and what it would be.
TEST_F(FlythroughChunks, TheRefusalOfOtherSettingsNamesTheSetting) {
    ASSERT_EQ(runGrotto(flythrough("1-2")).exitCode, 0);
    const std::string other = "flythrough " + world_.string() + " --path p --size 32x16 --fps 8 --frames 3 -o " + seq().string();
    expectRefused(other, R"(size was "16x8", this run's is "32x16")", seq() / "frame.0003.png");
    expectRefused(flythrough("3") + " --radius 2", "ao.radius was", seq() / "frame.0003.png");
}

// Times in stats.json: huge ones still merge into numbers; ones that are not
// times (negative, beyond a double) are refused before anything is rendered.
TEST_F(FlythroughChunks, StatsTimesMergeIntoNumbersOrAreRefused) {
    ASSERT_EQ(runGrotto(flythrough("1-3")).exitCode, 0);
    nlohmann::json doctored = stats();
    for (nlohmann::json& f : doctored["frames"]) {
        f["wall_ms"] = 1e308;
        for (auto& [pass, ms] : f["pass_ms"].items()) ms = 1e308;
    }
    writeStats(doctored);
    const test::RunResult r = runGrotto(flythrough("4"));
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const nlohmann::json median = stats()["median"];
    ASSERT_TRUE(median["wall_ms"].is_number()) << median.dump();
    EXPECT_EQ(median["wall_ms"].get<double>(), 1e308);
    for (auto& [pass, ms] : median["pass_ms"].items()) EXPECT_TRUE(ms.is_number()) << pass;

    doctored["frames"][1]["wall_ms"] = -1.0;
    writeStats(doctored);
    expectRefused(flythrough("5"), "frames[1] is not a frame entry", seq() / "frame.0005.png");
    std::string text = doctored.dump();
    text.replace(text.find("-1.0"), 4, "1e999");
    std::ofstream(seq() / "stats.json") << text;
    expectRefused(flythrough("5"), "stats.json", seq() / "frame.0005.png");
}

}  // namespace
}  // namespace grotto
