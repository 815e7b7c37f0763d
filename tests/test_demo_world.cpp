// The first image a new user sees (scripts/demo.sh) shows what Grotto is for: a
// coloured world lit by its face cache, with sky light and a soft sun, whose AO
// is plainly visible: at least 4% of the colour by compare's own figure, "AO in
// the image" (the grey rooms the demo showed before put 0.15% there). Baked with
// the flags demo.sh gives `grotto bake`, read from the script so the two agree.
#include "tests/test_util.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cstdio>
#include <fstream>
#include <regex>
#include <sstream>
#include <string>

namespace grotto {
namespace {

namespace fs = std::filesystem;

std::string readText(const fs::path& file) {
    std::ifstream in(file);
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
}

// The flags between the world and -o on demo.sh's `grotto bake` line.
std::string demoBakeFlags() {
    const std::string script = readText(test::worldsDir().parent_path() / "scripts" / "demo.sh");
    std::smatch m;
    if (!std::regex_search(script, m, std::regex(R"(grotto bake worlds/demo\.json ([^\n]*?)-o \S+)"))) return "?";
    return m[1].str();
}

TEST(DemoWorld, IsColouredAndLitByTheCacheWithSkyLightAndASoftSun) {
    const nlohmann::json world = nlohmann::json::parse(readText(test::worldsDir() / "demo.json"));
    EXPECT_EQ(world["ao"]["method"], "cache");
    EXPECT_EQ(world["lighting"]["ambient"]["from"], "sky");
    EXPECT_GT(world["lighting"]["sun"]["angle"].get<double>(), 0.0);
    EXPECT_NE(readText(test::worldsDir().parent_path() / "scripts" / "demo.sh").find("--bake"), std::string::npos);
    // Coloured: most of the model's materials are far from grey.
    const test::RunResult info = test::runGrotto("info " + (test::worldsDir() / "demo.json").string());
    ASSERT_EQ(info.exitCode, 0) << info.err;
    int materials = 0, coloured = 0;
    std::istringstream lines(info.out);
    for (std::string line; std::getline(lines, line);) {
        float r, g, b;
        const size_t at = line.find("albedo (");
        if (at == std::string::npos || std::sscanf(line.c_str() + at, "albedo (%f %f %f)", &r, &g, &b) != 3) continue;
        ++materials;
        if (std::max({r, g, b}) > 2.0f * std::min({r, g, b}) + 0.05f) ++coloured;
    }
    EXPECT_GE(materials, 8) << info.out;
    EXPECT_GE(coloured, materials * 2 / 3) << info.out;
}

TEST(DemoWorld, ShowsItsAoInTheImage) {
    const test::ScratchDir dir;
    const std::string world = (test::worldsDir() / "demo.json").string();
    const std::string flags = demoBakeFlags();
    ASSERT_NE(flags, "?") << "scripts/demo.sh has no 'grotto bake worlds/demo.json ... -o FILE' line";
    const test::RunResult bake = test::runGrotto("bake " + world + " " + flags + "-o " + (dir / "demo.gfc").string());
    ASSERT_EQ(bake.exitCode, 0) << bake.err;
    // The figure needs no reference worth the name: one ray a pixel, one frame.
    const test::RunResult c = test::runGrotto("compare " + world + " --bake " + (dir / "demo.gfc").string() +
                                              " --size 160x90 --spp 1 --sky-spp 1 --frames 1 --warmup 0");
    ASSERT_EQ(c.exitCode, 0) << c.err;
    double percent = -1.0;
    const size_t at = c.out.find("AO in the image: mean |colour change| ");
    ASSERT_NE(at, std::string::npos) << c.out;
    std::sscanf(c.out.c_str() + at, "AO in the image: mean |colour change| %lf%%", &percent);
    EXPECT_GE(percent, 4.0) << c.out;
}

}  // namespace
}  // namespace grotto
