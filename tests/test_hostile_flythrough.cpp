// A flythrough's output directory under hostile use: runs refused for a bad bake
// or a damaged file in the directory leave it as it was; chunks of one sequence
// given other bakes are refused; and two chunks of other settings started at once
// never both write into one directory.
#include "tests/hostile_fixture.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <fcntl.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

#include <chrono>
#include <fstream>
#include <future>
#include <set>
#include <sstream>
#include <thread>
#include <utility>

namespace grotto::test {
namespace {

// The names in a directory; {"(absent)"} for none there.
std::set<std::string> listing(const fs::path& dir) {
    if (!fs::exists(dir)) return {"(absent)"};
    std::set<std::string> names;
    for (const auto& e : fs::directory_iterator(dir)) names.insert(e.path().filename().string());
    return names;
}

// Processes waiting for a flock on `file` (Linux's /proc/locks marks them "->");
// -1 when /proc/locks cannot be read.
int lockWaiters(const fs::path& file) {
    std::ifstream locks("/proc/locks");
    if (!locks) return -1;
    struct stat st{};
    if (stat(file.c_str(), &st) != 0) return -1;
    const std::string inode = ":" + std::to_string(st.st_ino) + " ";
    int waiters = 0;
    for (std::string line; std::getline(locks, line);)
        waiters += line.find("->") != std::string::npos && line.find(inode) != std::string::npos;
    return waiters;
}

class HostileFlythrough : public HostileInputs {
protected:
    void SetUp() override {
        HostileInputs::SetUp();
        world_ = writeFlyWorld();  // a 16 x 16 floor, path p: 9 frames at --fps 8
    }
    std::string flythrough(const fs::path& out, const std::string& more) const {
        return "flythrough " + world_.string() + " --path p --fps 8 " + more + " -o " + out.string();
    }
    fs::path bake(const std::string& name, const fs::path& world, const std::string& settings = "--rays 8") {
        const fs::path file = dir_ / name;
        const RunResult r = runGrotto("bake " + world.string() + " -o " + file.string() + " --sun-rays 1 " + settings);
        EXPECT_EQ(r.exitCode, 0) << r.err;
        return file;
    }
    // Refused with one line naming `mention`, and `out` just as it was.
    void expectRefusedLeavingAsItWas(const std::string& args, const std::string& mention, const fs::path& out) {
        SCOPED_TRACE(args);
        const std::set<std::string> before = listing(out);
        expectRefused(args, mention, out / "frame.0001.png", "", {.hangSeconds = 60});
        EXPECT_EQ(listing(out), before);
    }
    fs::path world_;
};

// Every kind of bad bake, into an absent directory and an empty one by turns: the
// bake is read before the directory is touched.
TEST_F(HostileFlythrough, ARunRefusedForABadBakeLeavesTheDirectoryAsItWas) {
    const fs::path good = bake("good.gfc", world_);
    const std::string bytes = bytesOf(good);
    ASSERT_GT(bytes.size(), 88u + 24u);
    auto changed = [&](size_t at) { std::string b = bytes; b[at] = char(b[at] ^ 0x40); return b; };
    std::string nanTexel = bytes;
    std::fill(nanTexel.end() - 24, nanTexel.end(), char(0xFF));  // the last texel's sky sums are NaN
    fs::create_directory(dir_ / "folder.gfc");
    writeSolid(dir_ / "other.vdb", 12, 1, [](int, int, int) { return true; });
    const fs::path sunWorld = writeText("sun.json", R"({"grid": {"file": "good.vdb"},
        "lighting": {"sun": {"direction": [1, 1, 0]}}})");
    const std::vector<fs::path> bad = {
        dir_ / "missing.gfc",
        dir_ / "folder.gfc",
        writeBytes("empty.gfc", ""),
        writeBytes("short.gfc", bytes.substr(0, 40)),
        writeBytes("magic.gfc", changed(0)),
        writeBytes("version.gfc", changed(8)),
        writeBytes("cut.gfc", bytes.substr(0, bytes.size() - 1)),
        writeBytes("long.gfc", bytes + "x"),
        writeBytes("texel.gfc", nanTexel),
        bake("other-world.gfc", dir_ / "other.vdb"),
        bake("radius.gfc", world_, "--rays 8 --radius 2.5"),
        bake("sun.gfc", sunWorld),
    };
    for (size_t k = 0; k < bad.size(); ++k) {
        const fs::path out = dir_ / ("out" + std::to_string(k));
        if (k % 2) fs::create_directory(out);
        expectRefusedLeavingAsItWas(flythrough(out, "--size 16x8 --frames 1 --bake " + bad[k].string()),
                                    bad[k].filename().string(), out);
    }
    // Nothing left to hold a run of other settings off.
    const RunResult r = runGrotto(flythrough(dir_ / "out1", "--size 32x16 --frames 1"));
    EXPECT_EQ(r.exitCode, 0) << r.err;
}

// A damaged stats.json, one that is a directory or a FIFO, and a manifest that is
// a FIFO: refused before the lock or the manifest is written; once the file is
// gone, a run of other settings takes the directory.
TEST_F(HostileFlythrough, ARunRefusedForTheDirectorysFilesLeavesItAsItWas) {
    const std::string refused = "--size 16x8 --frames 1";
    const fs::path damaged = dir_ / "damaged";
    fs::create_directory(damaged);
    std::ofstream(damaged / "stats.json") << "{\"frames\": [{\"frame\": 1}]}";
    expectRefusedLeavingAsItWas(flythrough(damaged, refused), "frames[0] is not a frame entry", damaged);
    const fs::path folder = dir_ / "folder";
    fs::create_directories(folder / "stats.json");
    expectRefusedLeavingAsItWas(flythrough(folder, refused), "stats.json: is a directory", folder);
    for (const char* name : {"stats.json", "flythrough.json"}) {
        const fs::path fifo = dir_ / (std::string("fifo-") + name);
        fs::create_directory(fifo);
        ASSERT_EQ(mkfifo((fifo / name).c_str(), 0644), 0);
        expectRefusedLeavingAsItWas(flythrough(fifo, refused), name + std::string(": is a FIFO"), fifo);
    }
    fs::remove(damaged / "stats.json");
    const RunResult r = runGrotto(flythrough(damaged, "--size 32x16 --frames 1"));
    EXPECT_EQ(r.exitCode, 0) << r.err;
}

// Farm chunks given bakes of other rays, or of another version of the world at
// the same path, are refused naming the bake's setting; a copy of the same bake
// elsewhere is the same bake.
TEST_F(HostileFlythrough, ChunksOfOtherBakesAreRefused) {
    const fs::path a = bake("a.gfc", world_), fewer = bake("fewer.gfc", world_, "--rays 4");
    const std::string chunk = "--size 16x8 --chunk ";
    const fs::path seq = dir_ / "seq";
    ASSERT_EQ(runGrotto(flythrough(seq, chunk + "1/3 --bake " + a.string())).exitCode, 0);
    expectRefused(flythrough(seq, chunk + "2/3 --bake " + fewer.string()), "bake.rays was 8, this run's is 4",
                  seq / "frame.0004.png");
    fs::copy_file(a, dir_ / "copy.gfc");
    const RunResult same = runGrotto(flythrough(seq, chunk + "2/3 --bake " + (dir_ / "copy.gfc").string()));
    EXPECT_EQ(same.exitCode, 0) << same.err;

    // The world's grid changed under the same world file: its bake changes too.
    const fs::path grid = dir_ / "v.vdb", world = writeText("v.json", R"({"grid": {"file": "v.vdb"}, "paths": {"p": {"keys": [
        {"time": 0, "position": [8, 10, 30], "target": [8, 0, 8]}, {"time": 1, "position": [26, 6, 12], "target": [8, 0, 6]}]}}})");
    writeSolid(grid, 16, 1, [](int, int, int) { return true; });
    const fs::path v1 = bake("v1.gfc", world), versions = dir_ / "versions";
    const std::string run = "flythrough " + world.string() + " --path p --fps 8 --size 16x8 -o " + versions.string();
    ASSERT_EQ(runGrotto(run + " --chunk 1/3 --bake " + v1.string()).exitCode, 0);
    writeSolid(grid, 16, 2, [](int x, int y, int) { return y == 0 || x == 3; });  // a wall on the floor
    const fs::path v2 = bake("v2.gfc", world);
    expectRefused(run + " --chunk 2/3 --bake " + v2.string(), "bake.", versions / "frame.0004.png");
}

// Two chunks of other sizes started at once into one directory (the study's
// 25 frames at 320x180 beside 24 at 64x36): exactly one renders, the other is
// refused naming the size, and every frame has the manifest's size. The test
// holds the directory's lock until both runs wait for it, so the second takes it
// the moment the first lets it go, before the first has written any frame.
TEST_F(HostileFlythrough, ChunksOfOtherSizesStartedTogetherNeverBothWrite) {
    for (int round = 0; round < 3; ++round) {
        SCOPED_TRACE("round " + std::to_string(round));
        const fs::path seq = dir_ / ("race" + std::to_string(round)), lockFile = seq / ".flythrough.lock";
        fs::create_directory(seq);
        // Not inherited: a run holding the test's lock would wait for itself.
        const int held = open(lockFile.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644);
        ASSERT_EQ(flock(held, LOCK_EX), 0);
        if (lockWaiters(lockFile) < 0) {
            close(held);
            GTEST_SKIP() << "/proc/locks cannot be read: the runs cannot be lined up";
        }
        const std::string sizes[2] = {"32x16", "16x8"};
        std::future<RunResult> runs[2];
        for (int k = 0; k < 2; ++k)
            runs[k] = std::async(std::launch::async, [&, k] {
                return runGrotto(flythrough(seq, "--size " + sizes[k] + " --chunk " + std::to_string(k + 1) + "/2"), "",
                                 {.hangSeconds = 60});
            });
        int waiting = 0;
        for (int polls = 0; polls < 30000 && waiting < 2; ++polls) {  // at most a minute: the runs' hang guard
            std::this_thread::sleep_for(std::chrono::milliseconds(2));
            waiting = lockWaiters(lockFile);
        }
        close(held);
        EXPECT_EQ(waiting, 2) << "the runs never both waited for the lock";
        const RunResult r[2] = {runs[0].get(), runs[1].get()};
        ASSERT_EQ((r[0].exitCode == 0) + (r[1].exitCode == 0), 1) << r[0].err << r[1].err;
        const RunResult& refused = r[0].exitCode == 0 ? r[1] : r[0];
        EXPECT_EQ(refused.exitCode, 2) << refused.err;
        EXPECT_NE(refused.err.find("size was"), std::string::npos) << refused.err;
        std::ifstream in(seq / "flythrough.json");
        const std::string size = nlohmann::json::parse(in)["size"].get<std::string>();
        const size_t pixels = size == "32x16" ? 32 * 16 : 16 * 8;
        int frames = 0;
        for (const auto& e : fs::directory_iterator(seq))
            if (e.path().extension() == ".png") {
                EXPECT_EQ(readPixels8(e.path()).size(), pixels * 3) << e.path() << " in a directory of " << size;
                ++frames;
            }
        EXPECT_GE(frames, 4) << "the chunk that ran wrote its frames";
    }
}

}  // namespace
}  // namespace grotto::test
