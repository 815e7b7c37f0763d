// What the docs promise of a world that leaves things unset: the default camera
// is the first one in the file, and a bare .vdb is lit like the shipped worlds;
// and of flythrough's output flags: the defaults docs/paths.md states.
#include "tests/cli_fixture.h"

#include <gtest/gtest.h>

#include <fstream>
#include <map>
#include <regex>

namespace grotto {
namespace {

namespace fs = std::filesystem;
using test::CliErrors;
using test::runGrotto;

TEST_F(CliErrors, DefaultCameraIsTheFirstInTheFile) {
    // "zeta" comes first in the file but last in the alphabet.
    const fs::path world = writeText("cams.json", R"({"grid": {"file": "good.vdb"}, "cameras": {
        "zeta": {"position": [30, 20, 30], "target": [8, 0, 8]},
        "alpha": {"position": [-10, 12, 4], "target": [8, 0, 8]}}})");
    std::vector<uint8_t> images[3];
    const char* cameras[3] = {"", " --camera zeta", " --camera alpha"};
    for (int k = 0; k < 3; ++k) {
        const fs::path png = dir_ / ("view" + std::to_string(k) + ".png");
        const test::RunResult r = runGrotto("render " + world.string() + " --size 48x32" + cameras[k] + " -o " + png.string());
        ASSERT_EQ(r.exitCode, 0) << r.err;
        images[k] = test::readPixels8(png);
    }
    EXPECT_EQ(test::worstDifference(images[0], images[1]), 0);
    EXPECT_GT(test::worstDifference(images[0], images[2]), 32) << "the two cameras must see different things";
}

TEST_F(CliErrors, BareVdbIsLitLikeTheShippedWorlds) {
    // The daylight every shipped world sets, spelled out; a bare .vdb must match it.
    const fs::path sphere = test::worldsDir() / "sphere.vdb";
    const fs::path world = writeText("lit.json", R"({"grid": {"file": ")" + sphere.string() + R"("},
        "lighting": {"sun": {"color": [1.0, 0.95, 0.85], "intensity": 1.0},
                     "ambient": {"color": [0.55, 0.65, 0.85], "intensity": 0.7}}})");
    const fs::path bare = dir_ / "bare.png", lit = dir_ / "lit.png";
    ASSERT_EQ(runGrotto("render " + sphere.string() + " --size 96x64 -o " + bare.string()).exitCode, 0);
    ASSERT_EQ(runGrotto("render " + world.string() + " --size 96x64 -o " + lit.string()).exitCode, 0);
    const std::vector<uint8_t> pixels = test::readPixels8(bare);
    ASSERT_FALSE(pixels.empty());
    EXPECT_EQ(test::worstDifference(pixels, test::readPixels8(lit)), 0);
    // Not washed out: hardly any channel clips to white.
    size_t clipped = 0;
    for (uint8_t c : pixels) clipped += c == 255;
    EXPECT_LT(double(clipped) / double(pixels.size()), 0.01) << clipped << " clipped channels";
}

// docs/paths.md's table of flythrough output flags states each default; --help
// must state the same.
TEST(CliUsage, FlythroughOutputDefaultsMatchTheDocs) {
    std::ifstream in(test::worldsDir().parent_path() / "docs" / "paths.md");
    ASSERT_TRUE(in) << "docs/paths.md";
    std::map<std::string, std::string> documented;  // flag -> default, from rows "| `--flag ...` | meaning | default |"
    const std::regex row(R"(^\| `(--[a-z-]+)[^`]*` \|.*\| `?([^`|]+?)`? \|\s*$)");
    std::smatch m;
    for (std::string line; std::getline(in, line);)
        if (std::regex_match(line, m, row)) documented[m[1]] = m[2];
    const test::RunResult help = runGrotto("flythrough --help");
    ASSERT_EQ(help.exitCode, 0);
    for (const char* flag : {"--name", "--start-number", "--png-level", "--exr-type"}) {
        ASSERT_TRUE(documented.count(flag)) << flag << " has no row in docs/paths.md";
        const std::regex stated(std::string(flag) + R"( [^\n]*=)" + documented[flag] + R"((\s|$))");
        EXPECT_TRUE(std::regex_search(help.out, stated)) << flag << " default " << documented[flag] << ":\n" << help.out;
    }
}

}  // namespace
}  // namespace grotto
