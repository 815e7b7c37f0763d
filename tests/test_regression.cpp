// Temporal-stability regression tests on the shipped camera paths, through the
// same `grotto stability --baseline` users run on their own worlds. Each baseline
// in tests/baselines/ is the --json output of the run below; a run fails (exit 3)
// when a flicker or error figure (of the AO, or of the display colour) exceeds
// its baseline by more than the default tolerance (5 % + 0.0005), or the colour
// of the thumbnailed frames differs from the baseline's by more than 0.0005 RMS.
// Improvements pass (and are worth re-blessing).
//
// Re-bless on purpose, after a change that should move the figures:
//   GROTTO_BLESS=1 ctest --test-dir build -R Regression
// then review and commit the changed tests/baselines/*.json.
#include "tests/test_util.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <functional>

namespace grotto {
namespace {

namespace fs = std::filesystem;
using json = nlohmann::json;

// Returns this run's figures (null when blessing, or when it wrote none).
// `more`: further checks on the run's JSON.
json checkPath(const std::string& name, const std::string& world, const std::string& path,
               const std::function<void(const json&)>& more = {}) {
    const fs::path baseline = test::worldsDir().parent_path() / "tests" / "baselines" / (name + ".json");
    const test::ScratchDir dir;
    const fs::path out = dir / "out.json";
    const std::string args = "stability " + (test::worldsDir() / world).string() + " --path " + path +
                             " --size 320x180 --frames 32 --spp 128 --reference-every 8 --json " + out.string();
    if (const char* bless = std::getenv("GROTTO_BLESS"); bless && std::string(bless) == "1") {
        const test::RunResult r = test::runGrotto(args);
        if (r.exitCode != 0) {
            ADD_FAILURE() << args << "\n" << r.err;
            return json();
        }
        // Without what differs from machine to machine, so a re-bless diffs only in figures.
        std::ifstream in(out);
        json figures = json::parse(in);
        figures.erase("cost_ms");
        figures.erase("device");
        figures["world"] = world;
        std::ofstream(baseline) << figures.dump(2) << "\n";
        std::printf("blessed %s\n", baseline.c_str());
        return json();
    }
    const test::RunResult r = test::runGrotto(args + " --baseline " + baseline.string());
    EXPECT_EQ(r.exitCode, 0) << args << "\n" << r.out << r.err;
    if (!fs::exists(out)) {
        ADD_FAILURE() << r.err;
        return json();
    }
    std::ifstream in(out);
    const json now = json::parse(in);
    EXPECT_EQ(now["baseline"]["checks"].size(), now.contains("edit_recovery") ? 10u : 8u) << "every figure was checked";
    // The temporal pass must keep paying for itself on every path.
    EXPECT_LT(now["flicker"]["temporal"].get<double>(), now["flicker"]["spatial"].get<double>()) << name;
    if (more) more(now);
    return now;
}

// Ghosting behind moving objects, as for camera motion (docs/temporal.md): 8 frames
// after a disocclusion the temporal AO's error is within 0.05 of its steady state
// (pixels 16 or more frames old), and at every age from 8 on it is within 0.05 of
// the spatial AO's on the same pixels (which has no history to lag behind).
void checkGhosting(const json& run) {
    double steadySum = 0.0, steadyPixels = 0.0, at8 = -1.0;
    size_t checked = 0;
    for (const json& bin : run["ghosting"]["by_age"]) {
        const int age = bin["frames_since_disocclusion"].get<int>();
        const double pixels = bin["pixels"].get<double>(), temporal = bin["mae_temporal"].get<double>();
        if (age == 8) at8 = temporal;
        if (age >= 16) steadySum += temporal * pixels, steadyPixels += pixels;
        if (age >= 8 && pixels >= 100) {
            EXPECT_LT(temporal, bin["mae_spatial"].get<double>() + 0.05) << "frames since disocclusion " << age;
            ++checked;
        }
    }
    ASSERT_GT(steadyPixels, 0.0);
    ASSERT_GE(at8, 0.0) << "no pixels 8 frames after a disocclusion";
    EXPECT_LT(std::abs(at8 - steadySum / steadyPixels), 0.05);
    EXPECT_GT(checked, 8u);
}

// A path that edits the world: besides its baseline, no pixel near the edit may
// keep the pre-edit AO after the edit frame, and the edited region's error must be
// back within 1.2x its steady state within 8 frames (docs/metrics.md, "After an edit").
void checkEditPath(const std::string& name, const std::string& world, const std::string& path) {
    const json now = checkPath(name, world, path);
    if (now.is_null()) return;  // blessed, or already failed
    ASSERT_TRUE(now.contains("edit_recovery")) << name;
    ASSERT_EQ(now["edits"].size(), 1u) << "one edit within the 32 frames measured";
    EXPECT_GT(now["edits"][0]["frames"][1]["pixels"].get<int>(), 200) << "the edit is in view";
    EXPECT_EQ(now["edit_recovery"]["stale_after_edit_frame"].get<double>(), 0.0) << name;
    ASSERT_TRUE(now["edit_recovery"]["recovered_within_frames"].is_number()) << name;
    EXPECT_LE(now["edit_recovery"]["recovered_within_frames"].get<int>(), 8) << name;
}

TEST(Regression, RoomsOrbit) { checkPath("rooms-orbit", "rooms.json", "orbit"); }
TEST(Regression, CavesWalk) { checkPath("caves-walk", "caves.json", "walk"); }
TEST(Regression, ThinFence) { checkPath("thin-fence", "thin.json", "fence"); }
TEST(Regression, RoomsDigThroughAWall) { checkEditPath("rooms-dig", "rooms.json", "dig"); }
TEST(Regression, CavesCarveASphere) { checkEditPath("caves-carve", "caves.json", "carve"); }
// A swinging door, a sliding block and a spinning cube watched by a slow camera.
TEST(Regression, YardWatch) { checkPath("yard-watch", "yard.json", "watch", checkGhosting); }

}  // namespace
}  // namespace grotto
