// Flythroughs that share a directory: render-farm chunks running at the same
// time (--frames ranges and --chunk K/N), and runs that resume after one was
// killed mid-frame.
#include "tests/cli_fixture.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <future>
#include <map>

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
// and must still land within docs/paths.md's 2/255 of the whole run.
TEST_F(FlythroughChunks, ConcurrentChunksMatchASingleRun) {
    const std::string base = "flythrough " + (test::worldsDir() / "caves.json").string() + " --path walk --size 160x90 --fps 8 ";
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
    ASSERT_EQ(written.size(), 177u);
    int worst = 0;
    for (int i = 1; i <= 177; ++i) {
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

}  // namespace
}  // namespace grotto
