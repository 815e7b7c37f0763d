// One consistent command line: --version and bare usage, --size defaults stated
// everywhere, one --frames syntax, info listing what --camera and --path accept
// and the objects, costs never negative, stability's and flythrough's progress and
// --quiet, and the reference's standard-error verdict with --require-stderr.
#include "tests/json_file.h"
#include "tests/cli_fixture.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <fstream>
#include <regex>

namespace grotto {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;
using test::CliErrors;
using test::runGrotto;

TEST(CliUsage, VersionAndBareUsage) {
    const test::RunResult version = runGrotto("--version");
    EXPECT_EQ(version.exitCode, 0) << version.err;
    EXPECT_EQ(version.out, "grotto " GROTTO_VERSION "\n");
    // No subcommand: the usage on stdout, one error line, the usage-error code.
    const test::RunResult bare = runGrotto("");
    EXPECT_EQ(bare.exitCode, 2);
    EXPECT_NE(bare.out.find("Usage: grotto [OPTIONS] SUBCOMMAND"), std::string::npos) << bare.out;
    EXPECT_NE(bare.out.find("Subcommands:"), std::string::npos) << bare.out;
    EXPECT_NE(bare.out.find("stability"), std::string::npos) << bare.out;
    EXPECT_EQ(std::count(bare.err.begin(), bare.err.end(), '\n'), 1) << bare.err;
    EXPECT_NE(bare.err.find("subcommand"), std::string::npos) << bare.err;
}

// A mistyped subcommand is named, with the one it was likely meant to be.
TEST(CliUsage, MistypedSubcommandIsNamed) {
    const std::pair<const char*, const char*> cases[] = {
        {"rendr", "unknown subcommand 'rendr' (did you mean 'render'? subcommands: render, info, "},
        {"Flythrogh", "unknown subcommand 'Flythrogh' (did you mean 'flythrough'? subcommands: render, "},
        {"stabilty", "did you mean 'stability'?"},
        {"paint", "unknown subcommand 'paint' (subcommands: render, info, "},
    };
    for (const auto& [word, expected] : cases) {
        const test::RunResult r = runGrotto(std::string(word) + " world.json");
        EXPECT_EQ(r.exitCode, 2) << word;
        EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
        EXPECT_NE(r.err.find(expected), std::string::npos) << r.err;
    }
}

// Every command that renders states its --size default in --help.
TEST(CliUsage, EverySizeDefaultIsStated) {
    const std::regex stated(R"(--size TEXT=\d+x\d+ )");
    for (const char* command : {"render", "bench", "flythrough", "reference", "stability", "compare", "tradeoff", "tune"}) {
        const test::RunResult r = runGrotto(std::string(command) + " --help");
        EXPECT_EQ(r.exitCode, 0) << command;
        EXPECT_TRUE(std::regex_search(r.out, stated)) << command << ":\n" << r.out;
    }
}

// The reference needs no --size, like every other command, and says on its last
// line whether every pixel's standard error met the target; --require-stderr
// makes a miss exit 3, the EXR written all the same.
TEST_F(CliErrors, ReferenceDefaultSizeAndStderrTarget) {
    const std::string env = "GROTTO_CACHE_DIR=" + (dir_ / "cache").string();
    const fs::path exr = dir_ / "ref.exr";
    test::RunResult r = runGrotto("reference " + good_.string() + " --spp 1 -o " + exr.string(), env);
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_NE(r.out.find("(640x360,"), std::string::npos) << r.out;
    const auto lastLine = [](const std::string& out) {
        const size_t end = out.find_last_not_of('\n'), start = out.rfind('\n', end);
        return out.substr(start == std::string::npos ? 0 : start + 1, end - (start == std::string::npos ? 0 : start + 1) + 1);
    };
    // The open slab seen from above: no pixel is ever occluded, so no error at all.
    EXPECT_EQ(lastLine(r.out), "standard error target (every pixel <= 0.005): met");

    const std::string rooms = "reference " + (test::worldsDir() / "rooms.json").string() + " --camera table --size 32x18 --spp 16 -o ";
    r = runGrotto(rooms + exr.string(), env);
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_EQ(lastLine(r.out).rfind("standard error target (every pixel <= 0.005): NOT met at ", 0), 0u) << r.out;
    fs::remove(exr);
    r = runGrotto(rooms + exr.string() + " --require-stderr 0.005", env);
    EXPECT_EQ(r.exitCode, 3) << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    EXPECT_NE(r.err.find("--require-stderr"), std::string::npos) << r.err;
    EXPECT_TRUE(fs::exists(exr));
    r = runGrotto(rooms + exr.string() + " --require-stderr 0.5", env);
    EXPECT_EQ(r.exitCode, 0) << r.err;
    EXPECT_EQ(lastLine(r.out), "standard error target (every pixel <= 0.5): met");
}

// One second over the test floor: 9 frames at --fps 8.
constexpr const char* kPath = R"({"keys": [{"time": 0, "position": [8, 10, 30], "target": [8, 0, 8]},
    {"time": 0.5, "position": [20, 8, 24], "target": [8, 0, 8]}, {"time": 1, "position": [26, 6, 12], "target": [8, 0, 6]}]})";

// --frames N means the first N frames in flythrough as in stability; A-B means
// frames A to B in both.
TEST_F(CliErrors, FramesMeanTheSameInEveryCommand) {
    const fs::path world = writeText("fly.json", std::string(R"({"grid": {"file": "good.vdb"}, "paths": {"p": )") + kPath + "}}");
    const fs::path seq = dir_ / "seq";
    test::RunResult r = runGrotto("flythrough " + world.string() + " --path p --fps 8 --size 16x8 --frames 2 -o " + seq.string());
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_TRUE(fs::exists(seq / "frame.0001.png"));
    EXPECT_TRUE(fs::exists(seq / "frame.0002.png"));
    EXPECT_FALSE(fs::exists(seq / "frame.0003.png"));

    const fs::path out = dir_ / "s.json";
    const std::string stability = "stability " + world.string() + " --path p --fps 8 --size 32x16 --spp 4 --reference-every 2 --json ";
    r = runGrotto(stability + out.string() + " --frames 3-6");
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const json j = test::readJsonFile(out);
    EXPECT_EQ(j["frames"], "3-6");
    ASSERT_EQ(j["error"].size(), 4u);
    EXPECT_EQ(j["error"][0]["frame"].get<int>(), 3);
    EXPECT_EQ(j["error"][3]["frame"].get<int>(), 6);
    r = runGrotto(stability + out.string() + " --frames 3");
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_EQ(test::readJsonFile(out)["frames"], 3);
    EXPECT_EQ(test::readJsonFile(out)["error"][0]["frame"].get<int>(), 1);
    const fs::path none = dir_ / "none.json";
    for (const char* single : {"1", "5-5"}) expectRefused(stability + none.string() + " --frames " + single, "at least 2", none);
    for (const char* bad : {"0", "3-2", "1-10", "x"}) expectRefused(stability + none.string() + " --frames " + bad, "--frames", none);
}

TEST_F(CliErrors, InfoListsCamerasPathsAndMaterials) {
    const fs::path world = writeText("w.json", std::string(R"({"grid": {"file": "good.vdb"},
        "materials": [{"name": "moss", "albedo": [0.2, 0.5, 0.1]}],
        "cameras": {"top": {"position": [8, 20, 8.5], "target": [8, 0, 8]}, "side": {"position": [30, 2, 8], "target": [8, 0, 8]}},
        "default_camera": "side", "paths": {"p": )") + kPath + "}}");
    const test::RunResult r = runGrotto("info " + world.string());
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_NE(r.out.find("camera         side (default): position (30 2 8), target (8 0 8), fov 60"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("camera         top: position (8 20 8.5)"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("path           p: 3 keys over 1 s, 1 shot"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("material 1     moss: albedo (0.2 0.5 0.1)"), std::string::npos) << r.out;
    const test::RunResult bare = runGrotto("info " + good_.string());
    ASSERT_EQ(bare.exitCode, 0) << bare.err;
    EXPECT_NE(bare.out.find("cameras        none"), std::string::npos) << bare.out;
    EXPECT_NE(bare.out.find("paths          none"), std::string::npos) << bare.out;
}

// Stability shows progress with an ETA (a line per frame off a terminal) unless
// --quiet, and its wall-time differences are never negative: below their noise
// they read 0, with the noise beside them.
TEST_F(CliErrors, StabilityProgressQuietAndCostsNeverNegative) {
    const fs::path world = writeText("fly.json", std::string(R"({"grid": {"file": "good.vdb"}, "paths": {"p": )") + kPath + "}}");
    const fs::path out = dir_ / "s.json";
    const std::string run = "stability " + world.string() + " --path p --fps 8 --size 32x16 --spp 4 --frames 4 --json " + out.string();
    test::RunResult r = runGrotto(run);
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_NE(r.out.find("1/4 frame 1 + reference (ETA "), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("4/4 frame 4"), std::string::npos) << r.out;
    const json cost = test::readJsonFile(out)["cost_ms"];
    for (const char* difference : {"ao_chain_wall", "temporal_wall"}) {
        ASSERT_TRUE(cost.contains(difference)) << difference;
        EXPECT_GE(cost[difference].get<double>(), 0.0) << difference;
        EXPECT_GE(cost[std::string(difference) + "_noise"].get<double>(), 0.0) << difference;
    }
    EXPECT_EQ(r.out.find("-0."), std::string::npos) << r.out;
    r = runGrotto(run + " --quiet");
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_EQ(r.out.find("ETA"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("flicker raw"), std::string::npos) << r.out;
}

// flythrough takes --quiet as stability does: no progress lines, only the results.
TEST_F(CliErrors, FlythroughQuietPrintsOnlyTheResults) {
    const fs::path world = writeText("fly.json", std::string(R"({"grid": {"file": "good.vdb"}, "paths": {"p": )") + kPath + "}}");
    const std::string run = "flythrough " + world.string() + " --path p --fps 2 --size 16x8 -o ";
    test::RunResult r = runGrotto(run + (dir_ / "loud").string());
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_NE(r.out.find("frame 0001 written"), std::string::npos) << r.out;
    r = runGrotto(run + (dir_ / "quiet").string() + " --quiet");
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_EQ(r.out.find("frame 000"), std::string::npos) << r.out;
    EXPECT_EQ(r.out.rfind("wrote 3 frames", 0), 0u) << r.out;
    EXPECT_EQ(std::count(r.out.begin(), r.out.end(), '\n'), 1) << r.out;
    EXPECT_TRUE(fs::exists(dir_ / "quiet" / "frame.0003.png"));
}

// info lists each object: where its voxels come from, how many, its quads (a box
// is its six faces, a one-voxel slab of 16 x 16 its two sides and four edges), where
// it is and how it moves.
TEST_F(CliErrors, InfoListsObjects) {
    const fs::path world = writeText("objects.json", R"({"grid": {"file": "good.vdb"}, "objects": [
        {"name": "door", "generator": {"kind": "box", "size": [1, 10, 6], "material": 4}, "pivot": [0, -0.5, -0.5],
         "keys": [{"time": 0, "position": [15, -0.5, 9]}, {"time": 1.5, "position": [15, -0.5, 9], "angle_degrees": -100, "axis": [0, 1, 0]}]},
        {"name": "slab", "grid": {"file": "good.vdb", "name": "solid"}, "keys": [{"time": 0, "position": [2, 3, 4]}]}]})");
    const test::RunResult r = runGrotto("info " + world.string());
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_NE(r.out.find("object         door: generator box 1x10x6, material 4, 60 voxels, 6 quads, own bounds (-0.5 -0.5 -0.5)..(0.5 9.5 5.5), "
                         "moves: 2 keys from 0 to 1.5 s"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("object         slab: grid " + good_.string() + " (name solid, rule auto), 256 voxels, 6 quads, own bounds "
                         "(-0.5 -0.5 -0.5)..(15.5 0.5 15.5), still at (2 3 4)"), std::string::npos) << r.out;
    const test::RunResult bare = runGrotto("info " + good_.string());
    ASSERT_EQ(bare.exitCode, 0) << bare.err;
    EXPECT_NE(bare.out.find("objects        none"), std::string::npos) << bare.out;
}

TEST_F(CliErrors, BenchCostsNeverNegative) {
    const fs::path out = dir_ / "b.json";
    const test::RunResult r = runGrotto("bench " + good_.string() + " --size 32x16 --frames 5 --warmup 0 --json " + out.string());
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const json j = test::readJsonFile(out);
    for (const char* difference : {"ao_chain_wall_ms", "temporal_wall_ms"}) {
        EXPECT_GE(j[std::string(difference) + "_median"].get<double>(), 0.0) << difference;
        EXPECT_GE(j[std::string(difference) + "_noise"].get<double>(), 0.0) << difference;
    }
    EXPECT_EQ(r.out.find("-0."), std::string::npos) << r.out;
}

}  // namespace
}  // namespace grotto
