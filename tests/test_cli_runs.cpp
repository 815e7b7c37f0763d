// The commands that render paths and trace references (flythrough, reference,
// tradeoff, stability): what they write, how they resume, and what they refuse.
#include "tests/json_file.h"
#include "tests/cli_fixture.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>
#include "voxel/openvdb_grids.h"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <functional>
#include <map>
#include <random>
#include <sstream>

namespace grotto {
namespace {

namespace fs = std::filesystem;
using test::CliErrors;
using test::runGrotto;

// One second over the test floor: 9 frames at --fps 8.
constexpr const char* kFlyPath = R"({"keys": [{"time": 0, "position": [8, 10, 30], "target": [8, 0, 8]},
    {"time": 0.5, "position": [20, 8, 24], "target": [8, 0, 8]}, {"time": 1, "position": [26, 6, 12], "target": [8, 0, 6]}]})";

// VBAO is chosen by --ao vbao or by the world file's ao.method alike, and is not GTAO.
TEST_F(CliErrors, VbaoIsChosenByTheFlagOrTheWorldFile) {
    auto bytes = [](const fs::path& p) {
        std::ifstream in(p, std::ios::binary);
        return std::string(std::istreambuf_iterator<char>(in), {});
    };
    const fs::path rooms = test::worldsDir() / "rooms.json";
    nlohmann::json desc = nlohmann::json::parse(bytes(rooms));
    desc["grid"]["file"] = (test::worldsDir() / "rooms.vdb").string();
    desc["ao"]["method"] = "vbao";
    const fs::path world = writeText("vbao.json", desc.dump());
    const std::string size = " --size 48x27 --camera table --show ao -o ";
    test::RunResult flag = runGrotto("render " + rooms.string() + " --ao vbao" + size + (dir_ / "flag.png").string());
    ASSERT_EQ(flag.exitCode, 0) << flag.err;
    test::RunResult file = runGrotto("render " + world.string() + size + (dir_ / "file.png").string());
    ASSERT_EQ(file.exitCode, 0) << file.err;
    test::RunResult gtao = runGrotto("render " + rooms.string() + " --ao gtao" + size + (dir_ / "gtao.png").string());
    ASSERT_EQ(gtao.exitCode, 0) << gtao.err;
    EXPECT_EQ(bytes(dir_ / "flag.png"), bytes(dir_ / "file.png"));
    EXPECT_NE(bytes(dir_ / "flag.png"), bytes(dir_ / "gtao.png"));
    // And the thickness mode by its flag: one voxel everywhere differs from the voxels' own (the default).
    test::RunResult constant =
        runGrotto("render " + rooms.string() + " --ao vbao --thickness constant" + size + (dir_ / "constant.png").string());
    ASSERT_EQ(constant.exitCode, 0) << constant.err;
    EXPECT_NE(bytes(dir_ / "flag.png"), bytes(dir_ / "constant.png"));
}

TEST_F(CliErrors, FlythroughResumesButNeverMixesSequences) {
    const fs::path world = writeText("fly.json", std::string(R"({"grid": {"file": "good.vdb"}, "paths": {"p": )") + kFlyPath + "}}");
    const fs::path seq = dir_ / "seq";
    const std::string base = "flythrough " + world.string() + " --path p --size 16x8 -o " + seq.string();
    test::RunResult r = runGrotto(base + " --fps 2");
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_TRUE(fs::exists(seq / "frame.0003.png"));
    EXPECT_FALSE(fs::exists(seq / "frame.0004.png"));
    EXPECT_TRUE(fs::exists(seq / "stats.json"));
    // Not a terminal: one plain line per frame, no carriage returns.
    EXPECT_EQ(r.out.find('\r'), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("3/3 frame 0003 written"), std::string::npos) << r.out;
    fs::remove(seq / "frame.0002.png");  // an interrupted run
    const auto untouched = fs::last_write_time(seq / "frame.0003.png");
    r = runGrotto(base + " --fps 2 --warmup 0");
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_NE(r.out.find("wrote 1 frames"), std::string::npos) << r.out;
    EXPECT_EQ(r.out.find("frame 0001"), std::string::npos) << "frame 1 is complete and not needed: " << r.out;
    EXPECT_EQ(fs::last_write_time(seq / "frame.0003.png"), untouched);
    // With a warm-up, frame 1 is rendered again (history) but not rewritten.
    fs::remove(seq / "frame.0002.png");
    r = runGrotto(base + " --fps 2 --warmup 4");
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_NE(r.out.find("frame 0001 warm-up"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("wrote 1 frames"), std::string::npos) << r.out;
    r = runGrotto(base + " --fps 3");  // other timing must not reuse these frames
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_NE(r.err.find("other settings"), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(seq / "frame.0004.png"));
}

TEST_F(CliErrors, FlythroughSplitRunMatchesTheWholeRun) {
    // Caves (the path with the most disocclusion) at 160x90: frames 69-70 with the
    // default warm-up (64) start at frame 5, so the split run's history really is
    // cut short, and must still land within docs/paths.md's 2/255 of the whole run
    // (under the sanitizers at a third of the pixels).
    const std::string base = "flythrough " + (test::worldsDir() / "caves.json").string() + " --path walk --size " +
                             (test::kAddressSanitizer ? "96x54 " : "160x90 ");
    test::RunResult r = runGrotto(base + "--frames 1-70 -o " + (dir_ / "whole").string());
    ASSERT_EQ(r.exitCode, 0) << r.err;
    r = runGrotto(base + "--frames 69-70 -o " + (dir_ / "part").string());
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_NE(r.out.find("frame 0005 warm-up"), std::string::npos) << r.out;
    EXPECT_EQ(r.out.find("frame 0004"), std::string::npos) << r.out;
    EXPECT_FALSE(fs::exists(dir_ / "part" / "frame.0068.png"));
    for (int i = 69; i <= 70; ++i) {
        const std::string name = "frame.00" + std::to_string(i) + ".png";
        const std::vector<uint8_t> a = test::readPixels8(dir_ / "whole" / name), b = test::readPixels8(dir_ / "part" / name);
        ASSERT_FALSE(a.empty()) << name;
        // Measured 1/255 here (2/255 with --warmup 32, 12/255 with 8).
        EXPECT_LE(test::worstDifference(a, b), 2) << name;
    }
}

TEST_F(CliErrors, FlythroughRefusesBadPathsAndRanges) {
    const fs::path world = writeText("fly.json", std::string(R"({"grid": {"file": "good.vdb"}, "paths": {"p": )") + kFlyPath + "}}");
    const fs::path seq = dir_ / "seq";
    const std::string base = "flythrough " + world.string() + " --path p --size 16x8 --fps 8 -o " + seq.string();
    for (const char* bad : {"5-", "8-5", "0-3", "abc", "1-10", "3-4x"})
        expectRefused(base + " --frames " + bad, "--frames", seq);
    expectRefused("flythrough " + world.string() + " --path nope -o " + seq.string(), "paths: p", seq);
    const fs::path backwards = writeText("back.json", R"({"grid": {"file": "good.vdb"}, "paths": {"p": {"keys": [
        {"time": 1, "position": [8, 10, 30], "target": [8, 0, 8]}, {"time": 1, "position": [9, 10, 30], "target": [8, 0, 8]}]}}})");
    expectRefused("flythrough " + backwards.string() + " --path p -o " + seq.string(), "paths.p.keys[1].time", seq);
    const fs::path empty = writeText("empty.json", R"({"grid": {"file": "good.vdb"}, "paths": {"p": {"keys": []}}})");
    expectRefused("flythrough " + empty.string() + " --path p -o " + seq.string(), "paths.p.keys", seq);
}

TEST_F(CliErrors, ReferenceRefusesNonsense) {
    const fs::path exr = dir_ / "ref.exr";
    const std::string base = "reference " + good_.string() + " --size 16x8 -o " + exr.string();
    const std::string cache = "GROTTO_CACHE_DIR=" + (dir_ / "cache").string();
    expectRefused(base + " --spp 0", "--spp", exr, cache);
    expectRefused(base + " --spp -3", "--spp", exr, cache);
    expectRefused(base + " --spp 16 --radius -1", "--radius", exr, cache);
    expectRefused(base + " --spp 16 --radius 0", "--radius", exr, cache);
    expectRefused("reference " + good_.string() + " --size 16x8 --spp 16 -o " + out().string(), "out.png", out(), cache);
    EXPECT_FALSE(fs::exists(dir_ / "cache"));
}

TEST_F(CliErrors, ReferenceWritesAoAndStderrThenHitsTheCache) {
    const fs::path exr = dir_ / "ref.exr";
    const auto world = writeText("cam.json", R"({"grid": {"file": "good.vdb"},
        "cameras": {"c": {"position": [8, 10, 30], "target": [8, 0, 8]}}})");
    const std::string args = "reference " + world.string() + " --camera c --size 40x30 --spp 64 -o " + exr.string();
    const std::string env = "GROTTO_CACHE_DIR=" + (dir_ / "cache").string();
    const test::RunResult first = runGrotto(args, env);
    ASSERT_EQ(first.exitCode, 0) << first.err;
    EXPECT_EQ(first.out.find("cache hit"), std::string::npos) << first.out;
    EXPECT_NE(first.out.find("rays/s"), std::string::npos) << first.out;
    const std::optional<ImageFile> in = readImage(exr);
    ASSERT_TRUE(in);
    EXPECT_EQ(in->channelNames, (std::vector<std::string>{"AO", "AO_stderr"}));
    EXPECT_TRUE(in->worldToCamera);
    EXPECT_TRUE(in->worldToScreen);
    const std::vector<float>& px = in->floats;
    ASSERT_EQ(px.size(), size_t(in->width) * in->height * 2);
    // A 16x16 slab seen from above: its open top is exactly 1, sky is 1 with no error.
    for (size_t i = 0; i < px.size(); i += 2) {
        EXPECT_EQ(px[i], 1.0f);
        EXPECT_EQ(px[i + 1], 0.0f);
    }
    const auto written = fs::last_write_time(exr);
    const test::RunResult second = runGrotto(args, env);
    ASSERT_EQ(second.exitCode, 0) << second.err;
    EXPECT_NE(second.out.find("cache hit"), std::string::npos) << second.out;
    EXPECT_GE(fs::last_write_time(exr), written);
    // Another radius is another entry.
    const test::RunResult third = runGrotto(args + " --radius 2", env);
    ASSERT_EQ(third.exitCode, 0) << third.err;
    EXPECT_EQ(third.out.find("cache hit"), std::string::npos) << third.out;
}

TEST_F(CliErrors, UnknownAoMethodAndTradeoffNonsense) {
    expectRefused(render(good_) + " --ao nonsense", "--ao", out());
    const auto method = writeText("m.json", R"({"grid": {"file": "good.vdb"}, "ao": {"method": "rtao"}})");
    expectRefused(render(method), "ao.method", out());
    const fs::path csv = dir_ / "t.csv";
    expectRefused("tradeoff --size 16x8 --csv " + csv.string(), "world", csv);
    const fs::path unwritable = dir_ / "missing-dir" / "t.csv";
    expectRefused("tradeoff " + good_.string() + " --size 16x8 --csv " + unwritable.string(), "missing-dir", unwritable);
    expectRefused("tradeoff " + good_.string() + " --size 16x8 --methods gtao,sao --csv " + csv.string(), "'sao'", csv);
    expectRefused("tradeoff " + good_.string() + " --size 16x8 --csv " + csv.string() + " --plot " +
                      (dir_ / "p.svg").string(), "p.svg", csv);
}

TEST_F(CliErrors, TradeoffWritesEveryMethodAndPreset) {
    // A floor with a block and a pillar on it: corners where the methods differ.
    writeSolid(dir_ / "corners.vdb", 16, 5, [](int x, int y, int z) { return y == 0 || x < 4 || (x == 10 && z == 10); });
    const auto world = writeText("cam.json", R"({"grid": {"file": "corners.vdb"},
        "cameras": {"c": {"position": [30, 12, 30], "target": [8, 0, 8]}}})");
    const fs::path csv = dir_ / "t.csv", markdown = dir_ / "t.md", bakes = dir_ / "bakes";
    const std::string run = "tradeoff " + world.string() + " --size 32x24 --spp 256 --frames 1 --warmup 0 --csv " +
                            csv.string() + " --markdown " + markdown.string() + " --bakes " + bakes.string();
    const std::string env = "GROTTO_CACHE_DIR=" + (dir_ / "cache").string();
    const test::RunResult notFolder = runGrotto(run, env);
    EXPECT_EQ(notFolder.exitCode, 2);
    EXPECT_NE(notFolder.err.find(bakes.string() + ": is not a folder"), std::string::npos) << notFolder.err;
    fs::create_directories(bakes);
    // Another world's bake is refused before anything is measured.
    const auto floor = writeText("floor.json", R"({"grid": {"file": "good.vdb"}})");
    ASSERT_EQ(runGrotto("bake " + floor.string() + " -o " + (bakes / "cam.gfc").string()).exitCode, 0);
    const test::RunResult mismatch = runGrotto(run, env);
    EXPECT_EQ(mismatch.exitCode, 2);
    EXPECT_NE(mismatch.err.find((bakes / "cam.gfc").string()), std::string::npos) << mismatch.err;
    EXPECT_EQ(mismatch.out.find("ssao"), std::string::npos) << "measured before the bake was checked";
    ASSERT_EQ(runGrotto("bake " + world.string() + " -o " + (bakes / "cam.gfc").string()).exitCode, 0);
    const test::RunResult r = runGrotto(run, env);
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_EQ(r.err.find("baking the face cache"), std::string::npos) << "the bake in --bakes was not used: " << r.err;
    std::ifstream in(csv);
    std::string line;
    std::getline(in, line);
    EXPECT_EQ(line, "world,method,quality,ms_ao,ms_frame,mae,rmse,psnr,bias,ms_ao_noise");
    int rows = 0;
    std::map<std::string, double> rmse;  // by method and quality
    while (std::getline(in, line)) {
        ++rows;
        EXPECT_EQ(line.rfind("cam,", 0), 0u) << line;
        EXPECT_EQ(std::count(line.begin(), line.end(), ','), 9) << line;
        std::stringstream fields(line);
        std::vector<std::string> cell;  // world,method,quality,ms_ao,ms_frame,mae,rmse,...
        for (std::string field; std::getline(fields, field, ',');) cell.push_back(field);
        EXPECT_GE(std::stod(cell[3]), 0.0) << "a negative cost: " << line;
        rmse[cell[1] + " " + cell[2]] = std::stod(cell[6]);
    }
    // ssao x3, hbao x4, gtao x4, gtao+temporal, voxel x3, voxel+temporal, hybrid x3, hybrid+temporal,
    // vbao x4, vbao/constant, vbao/distance, vbao+temporal, cache
    EXPECT_EQ(rows, 28);
    // The converged cache estimates the reference's own quantity; GTAO approximates it.
    ASSERT_TRUE(rmse.count("cache baked") && rmse.count("gtao high"));
    std::printf("[ measured ] rmse: cache %.4f, gtao high %.4f\n", rmse["cache baked"], rmse["gtao high"]);
    EXPECT_LT(rmse["cache baked"], 0.5 * rmse["gtao high"]);
    // The same rows as a Markdown table (header, rule, 28 rows), SSAO by sample count.
    std::ifstream md(markdown);
    std::vector<std::string> table;
    while (std::getline(md, line)) table.push_back(line);
    ASSERT_EQ(table.size(), 30u);
    EXPECT_EQ(table[0].rfind("| world | method | quality |", 0), 0u);
    EXPECT_EQ(table[2].rfind("| cam | ssao | 8 |", 0), 0u) << table[2];
    EXPECT_EQ(table[13].rfind("| cam | gtao+temporal | high |", 0), 0u) << table[13];
    EXPECT_EQ(table[17].rfind("| cam | voxel+temporal | high |", 0), 0u) << table[17];
    EXPECT_EQ(table[21].rfind("| cam | hybrid+temporal | high |", 0), 0u) << table[21];
    EXPECT_EQ(table[26].rfind("| cam | vbao/constant | high |", 0), 0u) << table[26];
    EXPECT_EQ(table[28].rfind("| cam | vbao+temporal | high |", 0), 0u) << table[28];
    EXPECT_EQ(table[29].rfind("| cam | cache | baked |", 0), 0u) << table[29];
}

}  // namespace
}  // namespace grotto

namespace grotto {
namespace {

using nlohmann::json;

// `grotto stability` on a tiny run: every metric of docs/metrics.md is there, finite and in range.
TEST_F(CliErrors, StabilityReportsEveryMetric) {
    const fs::path out = dir_ / "stability.json";
    const test::RunResult r = runGrotto("stability " + (test::worldsDir() / "rooms.json").string() +
                                        " --path orbit --size 160x90 --frames 4 --spp 16 --reference-every 2 --json " +
                                        out.string());
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const json j = test::readJsonFile(out);
    for (const char* which : {"raw", "spatial", "temporal", "reference"}) {
        const double f = j["flicker"][which].get<double>();
        EXPECT_GT(f, 0.0) << which;  // noisy AO and a 16-spp reference both change between frames
        EXPECT_LT(f, 0.5) << which;
    }
    EXPECT_LT(j["flicker"]["temporal"].get<double>(), j["flicker"]["spatial"].get<double>());
    // --reference-every 2: a reference on every frame.
    ASSERT_EQ(j["error"].size(), 4u);
    for (int i = 0; i < 4; ++i) {
        const json& e = j["error"][i];
        EXPECT_EQ(e["frame"].get<int>(), i + 1);
        for (const char* which : {"spatial", "temporal"}) {
            const double mae = e[which]["mae"].get<double>(), rmse = e[which]["rmse"].get<double>();
            EXPECT_GT(mae, 0.0) << which;
            EXPECT_LE(mae, rmse) << which;
            EXPECT_LT(rmse, 0.5) << which;
            EXPECT_NEAR(e[which]["psnr"].get<double>(), -20.0 * std::log10(rmse), 1e-6) << which;
        }
    }
    // Ghosting: the cumulative curve adds up the per-age one; the first frame
    // counts as disoccluded everywhere, so k = 0 has pixels.
    const json& within = j["ghosting"]["within"];
    const json& byAge = j["ghosting"]["by_age"];
    ASSERT_FALSE(within.empty());
    EXPECT_EQ(within[0]["disoccluded_within_frames"].get<int>(), 0);
    EXPECT_GT(within[0]["pixels"].get<size_t>(), 1000u);
    size_t pixels = 0;
    double sumMae = 0.0;
    ASSERT_EQ(within.size(), byAge.size());  // four frames: every age is below the cap
    for (size_t k = 0; k < within.size(); ++k) {
        pixels += byAge[k]["pixels"].get<size_t>();
        sumMae += byAge[k]["pixels"].get<size_t>() * byAge[k]["mae_temporal"].get<double>();
        EXPECT_EQ(within[k]["disoccluded_within_frames"].get<int>(), byAge[k]["frames_since_disocclusion"].get<int>());
        EXPECT_EQ(within[k]["pixels"].get<size_t>(), pixels) << k;
        EXPECT_NEAR(within[k]["mae_temporal"].get<double>(), sumMae / double(pixels), 1e-9) << k;
        EXPECT_LT(within[k]["mae_spatial"].get<double>(), 0.5) << k;
    }
    EXPECT_GT(j["cost_ms"]["frame_wall"].get<double>(), 0.0);
    // Wall-time differences against the frames without AO and without the temporal
    // pass are present, with their noise; below it they read 0, never negative.
    for (const char* difference : {"ao_chain_wall", "temporal_wall"}) {
        ASSERT_TRUE(j["cost_ms"].contains(difference)) << difference;
        ASSERT_TRUE(j["cost_ms"].contains(std::string(difference) + "_noise")) << difference;
    }
    for (auto& [pass, ms] : j["cost_ms"].items())
        EXPECT_TRUE(ms.get<double>() >= 0.0 && std::isfinite(ms.get<double>())) << pass;
}

TEST_F(CliErrors, StabilityRefusesNonsense) {
    const fs::path out = dir_ / "stability.json";
    const std::string base = "stability " + (test::worldsDir() / "rooms.json").string() + " --size 16x8 --json " + out.string();
    expectRefused(base + " --path orbit --frames 0", "--frames", out);
    expectRefused(base + " --path orbit --fps 1 --frames 1000", "--frames", out);  // past the path's end
    expectRefused(base + " --path orbit --reference-every 1", "--reference-every", out);
    expectRefused(base + " --path nowhere", "paths: dig, orbit", out);
    expectRefused(base + " --path orbit --ao off", "--ao", out);
}

// `stability --baseline`: the same run passes, a figure above its baseline exits 3
// naming it (the run's own figures still written), and a baseline of another run or
// no JSON at all is refused before anything is measured.
TEST_F(CliErrors, StabilityBaselineCatchesARegressionAndRefusesAnotherRun) {
    const std::string run = "stability " + (test::worldsDir() / "rooms.json").string() +
                            " --path orbit --size 64x36 --frames 8 --spp 16 --json ";
    const fs::path baseline = dir_ / "baseline.json", again = dir_ / "again.json";
    ASSERT_EQ(runGrotto(run + baseline.string()).exitCode, 0);
    const test::RunResult same = runGrotto(run + again.string() + " --baseline " + baseline.string());
    EXPECT_EQ(same.exitCode, 0) << same.err;

    std::ifstream in(baseline);
    json doctored = json::parse(in);
    in.close();
    const double temporal = doctored["flicker"]["temporal"];
    // A quarter of it, less the default tolerance (5 % + 0.0005), must stay below it.
    ASSERT_GT(temporal, 0.0008) << "the run must flicker a little for the check to mean anything";
    doctored["flicker"]["temporal"] = temporal / 4.0;  // as if the last build had quartered it
    std::ofstream(dir_ / "better.json") << doctored.dump();
    fs::remove(again);
    const test::RunResult worse = runGrotto(run + again.string() + " --baseline " + (dir_ / "better.json").string());
    EXPECT_EQ(worse.exitCode, 3) << worse.err;
    EXPECT_NE(worse.err.find("flicker/temporal"), std::string::npos) << worse.err;
    EXPECT_EQ(std::count(worse.err.begin(), worse.err.end(), '\n'), 1) << worse.err;
    EXPECT_TRUE(fs::exists(again)) << "a regressed run keeps its figures";
    // A relative tolerance above 300 % lets the fourfold rise through.
    const test::RunResult tolerant = runGrotto(run + (dir_ / "tolerant.json").string() + " --baseline " +
                                               (dir_ / "better.json").string() + " --tolerance 3.1");
    EXPECT_EQ(tolerant.exitCode, 0) << tolerant.err;

    const std::string other = "stability " + (test::worldsDir() / "rooms.json").string() +
                              " --path orbit --size 64x32 --frames 8 --spp 16 --json ";
    expectRefused(other + (dir_ / "o.json").string() + " --baseline " + baseline.string(), "size", dir_ / "o.json");
    expectRefused(run + (dir_ / "r.json").string() + " --radius 2 --baseline " + baseline.string(), "ao.radius",
                  dir_ / "r.json");
    expectRefused(other + (dir_ / "t.json").string() + " --tolerance 0.1", "--baseline", dir_ / "t.json");
    expectRefused(run + baseline.string() + " --baseline " + baseline.string(), "--json", dir_ / "never.json");
    expectRefused(run + (dir_ / "d.json").string() + " --baseline " + dir_.path.string(), dir_.path.string(),
                  dir_ / "d.json");
    std::ofstream(dir_ / "garbage.json") << "{";
    expectRefused(run + (dir_ / "g.json").string() + " --baseline " + (dir_ / "garbage.json").string(), "garbage.json",
                  dir_ / "g.json");
    // Figures no run could have measured are refused (exit 2, naming the file and
    // the field), never compared: a negative flicker would fail any run.
    auto refusedWith = [&](const std::string& name, const std::function<void(json&)>& damage, const std::string& field) {
        json bad = json::parse(std::ifstream(baseline));
        damage(bad);
        const fs::path file = dir_ / (name + ".json");
        std::ofstream(file) << bad.dump();
        const test::RunResult r =
            expectRefused(run + (dir_ / "x.json").string() + " --baseline " + file.string(), file.string() + ": " + field, dir_ / "x.json");
        EXPECT_EQ(r.exitCode, 2) << name;
    };
    refusedWith("negative", [](json& j) { j["flicker"]["temporal"] = -0.01; }, "flicker/temporal");
    refusedWith("null", [](json& j) { j["error_mean"]["spatial"]["rmse"] = nullptr; }, "error_mean/spatial/rmse");
    refusedWith("text", [](json& j) { j["color"]["flicker"] = "0.1"; }, "color/flicker");
    refusedWith("old", [](json& j) { j.erase("color"); }, "color/flicker");
    refusedWith("cells", [](json& j) { j["color"]["thumbnails"]["cells"] = {16, 99}; }, "color.thumbnails.cells");
    refusedWith("hex", [](json& j) { j["color"]["thumbnails"]["frames"][0]["rgb"] = "00ff"; }, "color.thumbnails.frames[0].rgb");
}

// The final image regresses too: a change to shading, shadows or the tone map
// leaves every AO figure as it was but changes the display colour of the frames,
// which the baseline's thumbnails catch (exit 3, naming color/error_vs_baseline).
TEST_F(CliErrors, StabilityBaselineCatchesAChangedImage) {
    const fs::path path = writeText("orbit.json", R"({"keys": [{"time": 0, "position": [30, 12, 30], "target": [8, 0, 8]},
        {"time": 1, "position": [-10, 14, 28], "target": [8, 0, 8]}]})");
    // A floor with a wall on it: something to cast a shadow and shade.
    writeSolid(dir_ / "wall.vdb", 16, 6, [](int x, int y, int) { return y == 0 || (x >= 7 && x <= 8); });
    auto world = [&](const std::string& dir, const std::string& lighting) {
        fs::create_directories(dir_ / dir);
        std::ofstream(dir_ / dir / "w.json") << R"({"grid": {"file": ")" << (dir_ / "wall.vdb").string()
                                             << R"("}, "lighting": {)" << lighting << "}}";
        return (dir_ / dir / "w.json").string();
    };
    const std::string flags = " --path " + path.string() + " --fps 8 --size 64x36 --frames 8 --spp 8 --json ";
    const fs::path baseline = dir_ / "baseline.json";
    test::RunResult r = runGrotto("stability " + world("blessed", R"("exposure": 0.6)") + flags + baseline.string());
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const json blessed = json::parse(std::ifstream(baseline));
    EXPECT_GT(blessed["color"]["flicker"].get<double>(), 0.0) << "the camera moves: the image changes under it";
    EXPECT_LT(blessed["color"]["flicker"].get<double>(), 0.2);
    EXPECT_EQ(blessed["color"]["thumbnails"]["cells"], json({16, 9}));
    ASSERT_EQ(blessed["color"]["thumbnails"]["frames"].size(), 2u) << "frames 1 and 8";
    EXPECT_EQ(blessed["color"]["thumbnails"]["frames"][1]["frame"], 8);
    // The same world from elsewhere passes, with no colour error at all.
    r = runGrotto("stability " + world("same", R"("exposure": 0.6)") + flags + (dir_ / "same.json").string() +
                  " --baseline " + baseline.string());
    EXPECT_EQ(r.exitCode, 0) << r.err;
    const json same = json::parse(std::ifstream(dir_ / "same.json"));
    bool checked = false;
    for (const json& c : same["baseline"]["checks"])
        if (c["metric"] == "color/error_vs_baseline") {
            checked = true;
            EXPECT_EQ(c["is"].get<double>(), 0.0);
        }
    EXPECT_TRUE(checked) << same["baseline"].dump();
    for (const auto& [name, lighting] : std::vector<std::pair<std::string, std::string>>{
             {"shading", R"("exposure": 0.63)"}, {"shadows", R"("sun": {"shadows": false})"}, {"tonemap", R"("tone_map": "linear")"}}) {
        r = runGrotto("stability " + world(name, lighting) + flags + (dir_ / (name + ".json")).string() + " --baseline " +
                      baseline.string());
        EXPECT_EQ(r.exitCode, 3) << name << "\n" << r.out << r.err;
        EXPECT_NE(r.err.find("color/error_vs_baseline"), std::string::npos) << name << ": " << r.err;
        EXPECT_EQ(r.err.find("flicker/temporal"), std::string::npos) << name << ": the AO did not change: " << r.err;
    }
}

}  // namespace
}  // namespace grotto

namespace grotto {
namespace {

// A path file is found as given, else beside the world file (where the shipped
// ones live); otherwise the error names it and lists the world's paths.
TEST_F(CliErrors, PathFileIsFoundBesideTheWorld) {
    ASSERT_FALSE(fs::exists("caves-walk.json")) << "the test needs a working directory without it";
    const std::string base = "flythrough " + (test::worldsDir() / "caves.json").string() + " --size 16x8 --frames 1 ";
    const test::RunResult r = runGrotto(base + "--path caves-walk.json -o " + (dir_ / "seq").string());
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_TRUE(fs::exists(dir_ / "seq" / "frame.0001.png"));
    expectRefused(base + "--path no-such-walk.json -o " + (dir_ / "none").string(), "paths: carve, walk", dir_ / "none");
    const test::RunResult missing = runGrotto(base + "--path no-such-walk.json -o " + (dir_ / "none").string());
    EXPECT_NE(missing.err.find("no-such-walk.json"), std::string::npos) << missing.err;
}

}  // namespace
}  // namespace grotto

namespace grotto {
namespace {

// Resuming keeps the earlier runs' entries in DIR/stats.json (one per frame,
// merged by frame number), and refuses a damaged one before writing anything.
TEST_F(CliErrors, FlythroughResumeKeepsEarlierStats) {
    const fs::path world = writeText("fly.json", std::string(R"({"grid": {"file": "good.vdb"}, "paths": {"p": )") + kFlyPath + "}}");
    const fs::path seq = dir_ / "seq";
    const std::string base = "flythrough " + world.string() + " --path p --size 16x8 --fps 2 -o " + seq.string();
    auto framesOf = [&] {
        std::map<int, nlohmann::json> byFrame;
        const nlohmann::json stats = test::readJsonFile(seq / "stats.json");
        for (const nlohmann::json& f : stats["frames"]) byFrame[f["frame"].get<int>()] = f;
        return byFrame;
    };
    ASSERT_EQ(runGrotto(base).exitCode, 0);
    const auto first = framesOf();
    ASSERT_EQ(first.size(), 3u);

    fs::remove(seq / "frame.0002.png");
    test::RunResult r = runGrotto(base + " --warmup 0");
    ASSERT_EQ(r.exitCode, 0) << r.err;
    auto now = framesOf();
    ASSERT_EQ(now.size(), 3u);
    EXPECT_EQ(now[1], first.at(1));
    EXPECT_EQ(now[3], first.at(3));
    EXPECT_TRUE(now[2]["written"].get<bool>());
    const nlohmann::json second = now[2];

    // Frames 1 and 2 rendered again as warm-up keep the entries of the runs that wrote them.
    fs::remove(seq / "frame.0003.png");
    r = runGrotto(base + " --warmup 4");
    ASSERT_EQ(r.exitCode, 0) << r.err;
    now = framesOf();
    ASSERT_EQ(now.size(), 3u);
    EXPECT_EQ(now[1], first.at(1));
    EXPECT_EQ(now[2], second);
    EXPECT_TRUE(now[3]["written"].get<bool>());

    std::ofstream(seq / "stats.json") << R"({"frames": [{"frame": 1}]})";
    fs::remove(seq / "frame.0003.png");
    expectRefused(base, "stats.json", seq / "frame.0003.png");
}

}  // namespace
}  // namespace grotto
