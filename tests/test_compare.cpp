// `grotto compare`: one setting's error against the reference is the figure
// `grotto tradeoff` reports for the same setting, the reference is traced with
// the radius the method is given, and a setting with no AO is refused. Both draw
// the G-buffer at the world's or the flags' level of detail, against a reference
// of the exact voxels; `tradeoff --lod-biases` reports what each bias costs.
#include "tests/cli_fixture.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <map>
#include <sstream>
#include <string>

namespace grotto {
namespace {

namespace fs = std::filesystem;

// The "rmse" figure of compare's last line.
double compareRmse(const std::string& out) {
    const size_t at = out.rfind("rmse ");
    double rmse = -1.0;
    if (at != std::string::npos) std::sscanf(out.c_str() + at, "rmse %lf", &rmse);
    return rmse;
}

TEST(Compare, MeasuresWhatTradeoffMeasuresForTheSameSetting) {
    const test::ScratchDir dir;
    const std::string env = "GROTTO_CACHE_DIR=" + dir.path.string();
    const std::string world = (test::worldsDir() / "rooms.json").string();
    const test::RunResult t = test::runGrotto(
        "tradeoff " + world + " --size 96x54 --spp 128 --frames 2 --warmup 1 --methods gtao --csv " + (dir / "t.csv").string(),
        env);
    ASSERT_EQ(t.exitCode, 0) << t.err;
    std::ifstream csv(dir / "t.csv");
    std::string line;
    double tradeoffRmse = -1.0;
    std::vector<std::string> methods;  // of the rows --methods gtao gives
    std::getline(csv, line);          // the header
    while (std::getline(csv, line)) {
        methods.push_back(line.substr(0, line.find(',', line.find(',') + 1)));
        if (line.rfind("rooms,gtao,high,", 0) == 0) {
            std::stringstream fields(line);
            std::string field;
            for (int i = 0; i < 7; ++i) std::getline(fields, field, ',');  // world,method,quality,ms_ao,ms_frame,mae,rmse
            tradeoffRmse = std::stod(field);
        }
    }
    EXPECT_EQ(methods, (std::vector<std::string>{"rooms,gtao", "rooms,gtao", "rooms,gtao", "rooms,gtao",
                                                 "rooms,gtao+temporal"}));
    ASSERT_GT(tradeoffRmse, 0.0) << "no gtao high row";

    const test::RunResult c = test::runGrotto(
        "compare " + world + " --size 96x54 --spp 128 --frames 2 --warmup 1 --quality high --temporal 0", env);
    ASSERT_EQ(c.exitCode, 0) << c.err;
    EXPECT_NE(c.out.find("from the cache"), std::string::npos) << "tradeoff traced this reference already\n" << c.out;
    EXPECT_NEAR(compareRmse(c.out), tradeoffRmse, 1e-5) << c.out;
}

// The quads compare's G-buffer drew ("G-buffer: ..., N quads, ...").
long drawnQuads(const std::string& out) {
    const size_t at = out.find(" quads, ");
    const size_t start = out.rfind(", ", at);
    return at == std::string::npos || start == std::string::npos ? -1 : std::stol(out.substr(start + 2, at - start - 2));
}

TEST(Compare, DrawsAndTracesTheWorldsObjects) {
    // yard's three objects at time 0: compare and tradeoff draw them, and their
    // reference is the one `grotto reference --time 0` traces with the objects
    // (a cache hit: the key holds the objects' poses).
    const test::ScratchDir dir;
    const std::string env = "GROTTO_CACHE_DIR=" + dir.path.string(), view = " --size 96x54 --spp 16";
    const std::string yard = (test::worldsDir() / "yard.json").string();
    const test::RunResult c = test::runGrotto("compare " + yard + view + " --frames 1 --warmup 0", env);
    ASSERT_EQ(c.exitCode, 0) << c.err;
    const test::RunResult r = test::runGrotto("reference " + yard + view + " --time 0 -o " + (dir / "r.exr").string(), env);
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_NE(r.out.find("cache hit"), std::string::npos) << "compare traced another reference\n" << r.out;
    // Without its objects the same view draws fewer quads.
    std::ifstream in(yard);
    nlohmann::json bare = nlohmann::json::parse(in);
    bare.erase("objects");
    bare["grid"]["file"] = (test::worldsDir() / "rooms.vdb").string();
    const fs::path bareFile = dir / "bare.json";
    std::ofstream(bareFile) << bare.dump();
    const test::RunResult b = test::runGrotto("compare " + bareFile.string() + view + " --frames 1 --warmup 0", env);
    ASSERT_EQ(b.exitCode, 0) << b.err;
    std::printf("[ measured ] yard: %ld quads drawn with its objects, %ld without\n", drawnQuads(c.out), drawnQuads(b.out));
    EXPECT_GT(drawnQuads(c.out), drawnQuads(b.out)) << c.out << b.out;
    // tradeoff measures against the same reference.
    const test::RunResult t = test::runGrotto(
        "tradeoff " + yard + view + " --frames 1 --warmup 0 --methods gtao+temporal --csv " + (dir / "t.csv").string(), env);
    ASSERT_EQ(t.exitCode, 0) << t.err;
    EXPECT_NE(t.out.find("reference from the cache"), std::string::npos) << t.out;
}

TEST(Compare, TracesTheReferenceWithTheMethodsRadius) {
    // compare's reference lands in the cache under its radius: `grotto reference`
    // with that radius then finds it, and with the world's own radius does not.
    const test::ScratchDir dir;
    const std::string env = "GROTTO_CACHE_DIR=" + dir.path.string();
    const std::string world = (test::worldsDir() / "rooms.json").string(), view = " --size 48x27 --spp 16";
    const test::RunResult r = test::runGrotto("compare " + world + view + " --frames 1 --warmup 0 --radius 2.5", env);
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_NE(r.out.find("reference R 2.5,"), std::string::npos) << r.out;
    const test::RunResult same = test::runGrotto("reference " + world + view + " --radius 2.5 -o " + (dir / "a.exr").string(), env);
    EXPECT_NE(same.out.find("cache hit"), std::string::npos) << same.out;
    const test::RunResult other = test::runGrotto("reference " + world + view + " -o " + (dir / "b.exr").string(), env);
    EXPECT_EQ(other.out.find("cache hit"), std::string::npos) << other.out;
}

TEST(Compare, RefusesASettingWithoutAo) {
    const test::RunResult r = test::runGrotto("compare " + (test::worldsDir() / "rooms.json").string() + " --ao off");
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_NE(r.err.find("--ao"), std::string::npos) << r.err;
    EXPECT_EQ(r.out, "");
}

// A far view of 64 x 64 voxel columns, one or two voxels tall in a checkerboard:
// every top is a quad of its own in the exact mesh, while a coarse cell of 8
// voxels covers both heights, so coarse levels draw far fewer quads.
class LevelOfDetailCli : public test::CliErrors {
protected:
    void SetUp() override {
        CliErrors::SetUp();
        writeSolid(dir_ / "bumps.vdb", 64, 2, [](int x, int y, int z) { return y <= (x + z) % 2; });
    }
    // The world with `detail` as its "detail" block.
    std::filesystem::path world(const std::string& name, const std::string& detail) {
        return writeText(name, R"({"grid": {"file": "bumps.vdb"}, "detail": )" + detail + R"(,
            "cameras": {"far": {"position": [120, 80, 120], "target": [32, 0, 32], "fov": 40}}})");
    }
    std::string cache() const { return "GROTTO_CACHE_DIR=" + (dir_ / "cache").string(); }
};

// The CSV's rows, each as column name -> text.
std::vector<std::map<std::string, std::string>> readCsv(const std::filesystem::path& file) {
    std::ifstream in(file);
    std::string line, field;
    std::vector<std::string> names;
    std::vector<std::map<std::string, std::string>> rows;
    while (std::getline(in, line)) {
        std::stringstream fields(line);
        std::vector<std::string> values;
        while (std::getline(fields, field, ',')) values.push_back(field);
        if (names.empty()) {
            names = values;
            continue;
        }
        std::map<std::string, std::string>& row = rows.emplace_back();
        for (size_t i = 0; i < values.size() && i < names.size(); ++i) row[names[i]] = values[i];
    }
    return rows;
}

TEST_F(LevelOfDetailCli, TradeoffReportsWhatEachBiasCostsAgainstTheExactVoxels) {
    const std::filesystem::path csv = dir_ / "lod.csv", md = dir_ / "lod.md";
    const test::RunResult r = test::runGrotto("tradeoff " + world("bumps.json", "{}").string() +
                                                  " --size 96x54 --spp 16 --frames 1 --warmup 0 --lod-biases 16 --csv " +
                                                  csv.string() + " --markdown " + md.string(),
                                              cache());
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const auto rows = readCsv(csv);
    ASSERT_EQ(rows.size(), 2u) << "bias 0, the exact voxels, comes first whether listed or not\n" << r.out;
    const auto& exact = rows[0];
    const auto& coarse = rows[1];
    EXPECT_EQ(exact.at("world"), "bumps");
    EXPECT_EQ(exact.at("camera"), "far");
    EXPECT_EQ(std::stod(exact.at("lod_bias")), 0.0);
    EXPECT_EQ(std::stod(coarse.at("lod_bias")), 16.0);
    // Bias 0 is the exact rendering itself: identical colour, no change of AO error.
    EXPECT_TRUE(std::isinf(std::stod(exact.at("colour_psnr")))) << exact.at("colour_psnr");
    EXPECT_EQ(std::stod(exact.at("ao_psnr_change")), 0.0);
    EXPECT_EQ(std::stoi(exact.at("chunks_l1")) + std::stoi(exact.at("chunks_l2")) + std::stoi(exact.at("chunks_l3")), 0);
    // Bias 16 draws the far columns from coarse cells (the coarsest level that saves
    // quads): fewer quads, another image.
    EXPECT_GT(std::stoi(coarse.at("chunks_l1")) + std::stoi(coarse.at("chunks_l2")) + std::stoi(coarse.at("chunks_l3")), 0)
        << r.out;
    EXPECT_LT(std::stoull(coarse.at("quads")), std::stoull(exact.at("quads")) / 4) << r.out;
    const double colour = std::stod(coarse.at("colour_psnr"));
    EXPECT_TRUE(std::isfinite(colour) && colour > 0.0) << coarse.at("colour_psnr");
    // The change is the difference of the two AO errors against one reference.
    EXPECT_NEAR(std::stod(coarse.at("ao_psnr_change")),
                std::stod(coarse.at("ao_psnr")) - std::stod(exact.at("ao_psnr")), 2e-3);
    std::ifstream table(md);
    std::string header;
    std::getline(table, header);
    EXPECT_NE(header.find("colour PSNR dB"), std::string::npos) << header;
}

TEST_F(LevelOfDetailCli, CompareDrawsTheWorldsLevelOfDetailUnlessTheFlagSaysOtherwise) {
    const std::string coarse = world("coarse.json", R"({"lod_bias": 16})").string(),
                      view = " --size 96x54 --spp 8 --frames 1 --warmup 0 --temporal 0";
    auto quads = [](const std::string& out) {
        unsigned long long n = 0;
        const size_t at = out.find(" quads,");
        const size_t from = out.rfind(", ", at);
        if (at != std::string::npos && from != std::string::npos) n = std::stoull(out.substr(from + 2, at - from - 2));
        return n;
    };
    const test::RunResult file = test::runGrotto("compare " + coarse + view, cache());
    ASSERT_EQ(file.exitCode, 0) << file.err;
    EXPECT_NE(file.out.find("lod bias 16, occlusion culling on"), std::string::npos) << file.out;
    const test::RunResult flag = test::runGrotto("compare " + coarse + view + " --lod-bias 0", cache());
    ASSERT_EQ(flag.exitCode, 0) << flag.err;
    EXPECT_NE(flag.out.find("lod bias 0,"), std::string::npos) << flag.out;
    EXPECT_GT(quads(file.out), 0u) << file.out;
    EXPECT_LT(quads(file.out) * 4, quads(flag.out)) << file.out << flag.out;
    // One reference for both: the second run finds the first's in the cache.
    EXPECT_NE(flag.out.find("from the cache"), std::string::npos) << flag.out;
}

TEST_F(LevelOfDetailCli, RefusesBadBiasesNamingTheFlag) {
    const std::filesystem::path csv = dir_ / "refused.csv";
    const std::string run = "tradeoff " + world("bumps.json", "{}").string() + " --size 32x18 --csv " + csv.string();
    for (const char* bad : {"-1", "abc", "1,-2", "1,nan", "65"}) expectRefused(run + " --lod-biases=" + bad, "--lod-biases", csv);
    expectRefused(run + " --lod-biases 1 --lod-bias 2", "--lod-bias", csv);
    expectRefused(run + " --lod-bias -1", "--lod-bias", csv);
}

}  // namespace
}  // namespace grotto
