// Temporal-stability regression tests on the shipped camera paths. Each baseline
// in tests/baselines/ holds the `grotto stability` arguments it was made with,
// the metrics it produced and the tolerance: a run fails when a flicker or error
// figure exceeds its baseline by more than the tolerance. Improvements pass (and
// are worth re-blessing).
//
// Re-bless on purpose, after a change that should move the figures:
//   GROTTO_BLESS=1 ctest --test-dir build -R Regression
// then review and commit the changed tests/baselines/*.json.
#include "tests/test_util.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cstdlib>
#include <fstream>

namespace grotto {
namespace {

namespace fs = std::filesystem;
using json = nlohmann::json;

// The figures compared, as JSON pointers into the stability output.
const char* const kMetrics[] = {"/flicker/raw",          "/flicker/spatial",       "/flicker/temporal",
                                "/error_mean/spatial/rmse", "/error_mean/temporal/rmse", "/error_mean/temporal/mae"};

void checkPath(const std::string& name) {
    const fs::path file = test::worldsDir().parent_path() / "tests" / "baselines" / (name + ".json");
    std::ifstream in(file);
    ASSERT_TRUE(in) << file;
    json baseline = json::parse(in);
    in.close();
    test::ScratchDir dir;
    const std::string args = "stability " + (test::worldsDir() / baseline["world"].get<std::string>()).string() + " " +
                             baseline["args"].get<std::string>() + " --json " + (dir / "out.json").string();
    const test::RunResult r = test::runGrotto(args);
    ASSERT_EQ(r.exitCode, 0) << args << "\n" << r.err;
    std::ifstream outFile(dir / "out.json");
    const json now = json::parse(outFile);

    if (const char* bless = std::getenv("GROTTO_BLESS"); bless && std::string(bless) == "1") {
        for (const char* m : kMetrics) baseline["metrics"][m] = now.at(json::json_pointer(m));
        std::ofstream(file) << baseline.dump(2) << "\n";
        GTEST_SKIP() << "blessed " << file;
    }
    const double relative = baseline["tolerance"]["relative"], absolute = baseline["tolerance"]["absolute"];
    for (const char* m : kMetrics) {
        const double was = baseline["metrics"].at(m), is = now.at(json::json_pointer(m));
        EXPECT_LE(is, was * (1.0 + relative) + absolute) << name << " " << m << " rose from " << was << " to " << is;
    }
    // The temporal pass must keep paying for itself on every path.
    EXPECT_LT(now["flicker"]["temporal"].get<double>(), now["flicker"]["spatial"].get<double>()) << name;
}

TEST(Regression, RoomsOrbit) { checkPath("rooms-orbit"); }
TEST(Regression, CavesWalk) { checkPath("caves-walk"); }
TEST(Regression, ThinFence) { checkPath("thin-fence"); }

}  // namespace
}  // namespace grotto
