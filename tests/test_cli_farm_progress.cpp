// --progress jsonl: one JSON object a line on stdout per frame (flythrough) or
// run of faces (bake), which a farm manager can read; nothing else on stdout
// starts with '{'.
#include "tests/cli_fixture.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <sstream>

namespace grotto::test {
namespace {

// The lines of `out` that start with '{', parsed (a test failure for one that
// does not parse).
std::vector<nlohmann::json> jsonLines(const std::string& out) {
    std::vector<nlohmann::json> lines;
    std::istringstream in(out);
    for (std::string line; std::getline(in, line);)
        if (!line.empty() && line[0] == '{') {
            const nlohmann::json j = nlohmann::json::parse(line, nullptr, false);
            EXPECT_FALSE(j.is_discarded()) << line;
            lines.push_back(j);
        }
    return lines;
}

class FarmProgress : public CliErrors {};

TEST_F(FarmProgress, FlythroughWritesALinePerFrame) {
    // Chunk 2/3 of 9 frames, two warm-up frames: 2 and 3 rendered, 4 to 6 written.
    const RunResult r = runGrotto("flythrough " + writeFlyWorld().string() +
                                  " --path p --size 16x8 --fps 8 --chunk 2/3 --warmup 2 --progress jsonl -o " +
                                  (dir_ / "walk").string());
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const std::vector<nlohmann::json> lines = jsonLines(r.out);
    ASSERT_EQ(lines.size(), 5u) << r.out;
    for (size_t k = 0; k < lines.size(); ++k) {
        const nlohmann::json& l = lines[k];
        EXPECT_EQ(l["done"], k + 1);
        EXPECT_EQ(l["total"], 5);
        EXPECT_EQ(l["frame"], k + 2);
        EXPECT_EQ(l["state"], k < 2 ? "warm-up" : "written");
        EXPECT_EQ(l["chunk"], "2/3");
        EXPECT_GE(l["wall_ms"].get<double>(), 0.0);
        EXPECT_GE(l["eta_s"].get<double>(), 0.0);
    }
    EXPECT_NE(r.out.find("wrote 3 frames"), std::string::npos) << r.out;  // the summary stays
}

TEST_F(FarmProgress, BakeWritesALinePerRunOfFaces) {
    const RunResult r = runGrotto("bake " + good_.string() + " --rays 4 --sun-rays 1 --texels 1 --chunk 1/2 "
                                  "--progress jsonl -o " + (dir_ / "part.gfc").string());
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const std::vector<nlohmann::json> lines = jsonLines(r.out);
    ASSERT_GE(lines.size(), 2u) << r.out;
    uint64_t faces = 0;
    for (size_t k = 0; k < lines.size(); ++k) {
        EXPECT_EQ(lines[k]["done"], k + 1);
        EXPECT_EQ(lines[k]["chunk"], "1/2");
        EXPECT_GE(lines[k]["faces_done"].get<uint64_t>(), faces);
        faces = lines[k]["faces_done"].get<uint64_t>();
    }
    EXPECT_EQ(lines.back()["done"], lines.back()["total"]);
    EXPECT_EQ(lines.back()["faces_done"], lines.back()["faces_total"]);
    EXPECT_GT(faces, 0u);
}

TEST_F(FarmProgress, RefusesQuietAndUnknownFormats) {
    const fs::path out = dir_ / "walk";
    const std::string fly = "flythrough " + writeFlyWorld().string() + " --path p --size 16x8 --fps 8 -o " + out.string();
    expectRefused(fly + " --quiet --progress jsonl", "--progress", out);
    expectRefused(fly + " --progress json", "--progress", out);
}

}  // namespace
}  // namespace grotto::test
