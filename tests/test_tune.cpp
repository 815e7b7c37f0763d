// `grotto tune`: the coordinate search never reports a fit worse than where it
// started, and re-evaluating the fit it reports gives the error it claims.
#include "tests/test_util.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <string>

namespace grotto {
namespace {

TEST(Tune, ReportsAFitNoWorseThanTheDefaultsAndReproducesIt) {
    const test::ScratchDir cache;
    const test::RunResult r = test::runGrotto(
        "tune " + (test::worldsDir() / "rooms.json").string() + " --size 64x36 --spp 64 --rounds 1",
        "GROTTO_CACHE_DIR=" + cache.path.string());
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const size_t summary = r.out.rfind("mean rmse ");
    ASSERT_NE(summary, std::string::npos) << r.out;
    double after = 0.0, before = 0.0;
    ASSERT_EQ(std::sscanf(r.out.c_str() + summary, "mean rmse %lf (before %lf)", &after, &before), 2) << r.out;
    EXPECT_LE(after, before);
    EXPECT_GT(after, 0.0);
    // One world: its own RMSE under the fitted settings is the mean.
    const size_t world = r.out.rfind("rooms    rmse ");
    ASSERT_NE(world, std::string::npos) << r.out;
    double rooms = 0.0;
    ASSERT_EQ(std::sscanf(r.out.c_str() + world, "rooms    rmse %lf", &rooms), 1);
    EXPECT_NEAR(rooms, after, 1e-4);
}

}  // namespace
}  // namespace grotto
