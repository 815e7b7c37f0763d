// How a flythrough names and splits its frames: --name patterns with one
// integer conversion and a start number (app/frame_names.h), and --chunk K/N
// ranges that cover the path exactly once (app/options.h, app/farm_chunk.h).
#include "app/frame_names.h"
#include "app/options.h"
#include "grotto/error.h"
#include "tests/input_error_checks.h"

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace grotto::app {
namespace {

TEST(FrameNames, PatternAndStartNumberMakeTheNames) {
    EXPECT_EQ(FrameNames(kDefaultFramePattern, 1, "png").name(1), "frame.0001.png");
    EXPECT_EQ(FrameNames(kDefaultFramePattern, 1, "png").name(12345), "frame.12345.png");
    EXPECT_EQ(FrameNames("shot_%04d", 1001, "exr").name(1), "shot_1001.exr");
    EXPECT_EQ(FrameNames("%d", 0, "png").name(3), "2.png");
    EXPECT_EQ(FrameNames("100%%_%3d_v2", 1, "png").name(7), "100%_  7_v2.png");
    EXPECT_TRUE(FrameNames(kDefaultFramePattern, 1, "png").isDefault());
    EXPECT_FALSE(FrameNames(kDefaultFramePattern, 0, "png").isDefault());
    EXPECT_FALSE(FrameNames("frame%04d", 1, "png").isDefault());
}

TEST(FrameNames, MatchesOnlyItsOwnNames) {
    const FrameNames names("shot_%04d_x", 1, "png");
    EXPECT_TRUE(names.matches("shot_0001_x.png"));
    EXPECT_TRUE(names.matches("shot_123456_x.png"));
    EXPECT_FALSE(names.matches("shot__x.png"));
    EXPECT_FALSE(names.matches("shot_00a1_x.png"));
    EXPECT_FALSE(names.matches("shot_0001_x.exr"));
    EXPECT_FALSE(names.matches("frame.0001.png"));
    EXPECT_FALSE(names.matches("stats.json"));
}

TEST(FrameNames, RefusesPatternsWithoutExactlyOneIntegerConversion) {
    for (const std::string& bad : std::vector<std::string>{"frame", "%d_%d", "%s", "%f", "%5.2d", "%x", "%ld", "%-4d", "a/%d", ".%04d", "%d%",
                            "%99d", "tab\t%d", std::string(190, 'x') + "%d"})
        test::inputErrorOf([&] { FrameNames(bad, 1, "png"); }, {"--name"});
}

TEST(Chunks, CoverThePathOnceInOrder) {
    for (int count : {1, 2, 7, 9, 100, 101})
        for (int n : {1, 2, 3, 4, 7, 12}) {
            int next = 1;
            for (int k = 1; k <= n; ++k) {
                const FrameRange r = chunkFrames({k, n}, count);
                EXPECT_EQ(r.first, next) << k << "/" << n << " of " << count;
                EXPECT_GE(r.count(), count / n);
                EXPECT_LE(r.count(), count / n + 1);
                if (k > 1 && r.count() > 0) EXPECT_LE(r.count(), chunkFrames({k - 1, n}, count).count());
                next = r.last + 1;
            }
            EXPECT_EQ(next, count + 1) << n << " chunks of " << count;
        }
    EXPECT_EQ(chunkFrames(parseKOfN("3/3"), 10).first, 8);  // 4, 3, 3
    EXPECT_EQ(chunkFrames(parseKOfN("5/8"), 3).count(), 0);  // more chunks than frames: nothing to do
}

TEST(Chunks, RefusesWhatIsNotKOfN) {
    for (const char* bad : {"0/3", "4/3", "3", "a/b", "1/0", "-1/3", "1/3x", " 1/3", "1/ 3", "1//3", "/3", "1/2000000"})
        test::inputErrorOf([&] { parseKOfN(bad); }, {"--chunk"});
}

}  // namespace
}  // namespace grotto::app
