// A path key marked "cut" restarts the temporal history in `grotto flythrough`:
// the frame at the cut has one frame of history everywhere, although its view
// overlaps the one before (so reprojection alone would have kept history).
#include "engine/image_input.h"
#include "tests/test_util.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>
#include <vector>

namespace grotto {
namespace {

namespace fs = std::filesystem;

// The largest AO_history in a flythrough EXR frame.
float mostHistory(const fs::path& exr) {
    const std::optional<ImageFile> image = readImage(exr);
    if (!image) return -1.0f;
    const std::vector<float> v = image->channel("AO_history");
    if (v.empty()) return -1.0f;
    return *std::max_element(v.begin(), v.end());
}

TEST(FlythroughCuts, ACutKeyRestartsTheHistory) {
    const test::ScratchDir dir;
    // Two shots of the same table from nearby viewpoints; the cut is at t = 1.5,
    // frame 4 at 2 frames a second.
    const fs::path path = dir / "cut.json";
    std::ofstream(path) << R"({"keys": [
        {"time": 0,   "position": [-4, 12, 26], "target": [4, 3, 11]},
        {"time": 1,   "position": [-3, 12, 26], "target": [4, 3, 11]},
        {"time": 1.5, "position": [-3, 11, 25], "target": [4, 3, 11], "cut": true},
        {"time": 2.5, "position": [-2, 11, 25], "target": [4, 3, 11]}]})";
    const fs::path out = dir / "frames";
    const test::RunResult r = test::runGrotto("flythrough " + (test::worldsDir() / "rooms.json").string() + " --path " +
                                        path.string() + " --size 64x36 --fps 2 --format exr -o " + out.string());
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_EQ(mostHistory(out / "frame.0003.exr"), 3.0f);  // three frames into the first shot
    EXPECT_EQ(mostHistory(out / "frame.0004.exr"), 1.0f);  // the cut: history restarted
    EXPECT_EQ(mostHistory(out / "frame.0005.exr"), 2.0f);
}

}  // namespace
}  // namespace grotto
