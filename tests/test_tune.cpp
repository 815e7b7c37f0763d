// `grotto tune`: the coordinate search never reports a fit worse than where it
// started, and re-evaluating the fit it reports gives the error it claims.
#include "tests/test_util.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <string>

namespace grotto {
namespace {

// The run's last "mean rmse AFTER (before BEFORE)", checked: no worse than it started.
double fittedRmse(const std::string& out) {
    const size_t summary = out.rfind("mean rmse ");
    double after = 0.0, before = 0.0;
    EXPECT_NE(summary, std::string::npos) << out;
    if (summary == std::string::npos) return 0.0;
    EXPECT_EQ(std::sscanf(out.c_str() + summary, "mean rmse %lf (before %lf)", &after, &before), 2) << out;
    EXPECT_LE(after, before);
    EXPECT_GT(after, 0.0);
    return after;
}

TEST(Tune, ReportsAFitNoWorseThanTheDefaultsAndReproducesIt) {
    const test::ScratchDir cache;
    const test::RunResult r = test::runGrotto(
        "tune " + (test::worldsDir() / "rooms.json").string() + " --size 64x36 --spp 64 --rounds 1",
        "GROTTO_CACHE_DIR=" + cache.path.string());
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const double after = fittedRmse(r.out);
    // One world: its own RMSE under the fitted settings is the mean.
    const size_t world = r.out.rfind("rooms    rmse ");
    ASSERT_NE(world, std::string::npos) << r.out;
    double rooms = 0.0;
    ASSERT_EQ(std::sscanf(r.out.c_str() + world, "rooms    rmse %lf", &rooms), 1);
    EXPECT_NEAR(rooms, after, 1e-4);
}

// VBAO fits its own settings: the shared heuristics and, with a thickness that
// is a share of the view depth, that share; not GTAO's thin-occluder compensation.
TEST(Tune, FitsVbaosOwnSettings) {
    const test::ScratchDir cache;
    const test::RunResult r = test::runGrotto("tune " + (test::worldsDir() / "rooms.json").string() +
                                                  " --size 64x36 --spp 64 --rounds 1 --ao vbao --thickness distance",
                                              "GROTTO_CACHE_DIR=" + cache.path.string());
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const std::string before = r.out.substr(0, r.out.find('\n'));
    EXPECT_NE(before.find("falloff_range 0.300"), std::string::npos) << "VBAO's own falloff default: " << before;
    EXPECT_NE(before.find("thickness_value 0.100"), std::string::npos) << before;
    EXPECT_EQ(r.out.find("thin_occluder"), std::string::npos) << r.out;
    fittedRmse(r.out);
}

}  // namespace
}  // namespace grotto
