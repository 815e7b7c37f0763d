// `grotto compare`: one setting's error against the reference is the figure
// `grotto tradeoff` reports for the same setting, the reference is traced with
// the radius the method is given, and a setting with no AO is refused.
#include "tests/test_util.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <fstream>
#include <sstream>
#include <string>

namespace grotto {
namespace {

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
        "tradeoff " + world + " --size 96x54 --spp 128 --frames 2 --warmup 1 --csv " + (dir / "t.csv").string(), env);
    ASSERT_EQ(t.exitCode, 0) << t.err;
    std::ifstream csv(dir / "t.csv");
    std::string line;
    double tradeoffRmse = -1.0;
    while (std::getline(csv, line))
        if (line.rfind("rooms,gtao,high,", 0) == 0) {
            std::stringstream fields(line);
            std::string field;
            for (int i = 0; i < 7; ++i) std::getline(fields, field, ',');  // world,method,quality,ms_ao,ms_frame,mae,rmse
            tradeoffRmse = std::stod(field);
        }
    ASSERT_GT(tradeoffRmse, 0.0) << "no gtao high row";

    const test::RunResult c = test::runGrotto(
        "compare " + world + " --size 96x54 --spp 128 --frames 2 --warmup 1 --quality high --temporal 0", env);
    ASSERT_EQ(c.exitCode, 0) << c.err;
    EXPECT_NE(c.out.find("from the cache"), std::string::npos) << "tradeoff traced this reference already\n" << c.out;
    EXPECT_NEAR(compareRmse(c.out), tradeoffRmse, 1e-5) << c.out;
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

}  // namespace
}  // namespace grotto
