// How a flythrough writes its frames: names by pattern and start number (and a
// resume that never mixes them), PNG compression levels, EXR half floats and
// chosen AOV layers, and what it refuses of those flags.
#include "tests/cli_fixture.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <fstream>

namespace grotto {
namespace {

namespace fs = std::filesystem;
using test::CliErrors;
using test::runGrotto;

class FlythroughCapture : public CliErrors {
protected:
    void SetUp() override {
        CliErrors::SetUp();
        world_ = writeFlyWorld();  // 9 frames at --fps 8
    }
    std::string flythrough(const std::string& flags, const fs::path& out) const {
        return "flythrough " + world_.string() + " --path p --size 16x8 --fps 8 " + flags + " -o " + out.string();
    }
    fs::path seq() const { return dir_ / "seq"; }

    fs::path world_;
};

TEST_F(FlythroughCapture, NamesFollowThePatternAndStartNumberAndResumeWithThem) {
    const std::string flags = "--name shot_%03d_beauty --start-number 101 --frames 2-4";
    test::RunResult r = runGrotto(flythrough(flags, seq()));
    ASSERT_EQ(r.exitCode, 0) << r.err;
    for (int n : {102, 103, 104}) EXPECT_TRUE(fs::exists(seq() / ("shot_" + std::to_string(n) + "_beauty.png"))) << n;
    EXPECT_FALSE(fs::exists(seq() / "shot_101_beauty.png"));
    EXPECT_FALSE(fs::exists(seq() / "frame.0002.png"));
    std::ifstream in(seq() / "flythrough.json");
    const nlohmann::json manifest = nlohmann::json::parse(in);
    EXPECT_EQ(manifest["name"], "shot_%03d_beauty");
    EXPECT_EQ(manifest["start_number"], 101);

    // A resume skips the frames on disk under the same names.
    fs::remove(seq() / "shot_103_beauty.png");
    r = runGrotto(flythrough(flags + " --warmup 0", seq()));
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_NE(r.out.find("wrote 1 frames"), std::string::npos) << r.out;
    EXPECT_TRUE(fs::exists(seq() / "shot_103_beauty.png"));
    // Other names or numbers into the same directory would mix sequences.
    for (const std::string& other : {"--name shot_%04d_beauty --start-number 101", "--name shot_%03d_beauty", ""}) {
        r = runGrotto(flythrough(other + " --frames 2-4", seq()));
        EXPECT_EQ(r.exitCode, 2) << other;
        EXPECT_NE(r.err.find("other settings"), std::string::npos) << other << ": " << r.err;
    }
    // Default names keep the manifest of earlier versions: neither is recorded.
    ASSERT_EQ(runGrotto(flythrough("--frames 1", dir_ / "plain")).exitCode, 0);
    std::ifstream plain(dir_ / "plain" / "flythrough.json");
    const nlohmann::json defaults = nlohmann::json::parse(plain);
    EXPECT_FALSE(defaults.contains("name"));
    EXPECT_FALSE(defaults.contains("start_number"));
}

TEST_F(FlythroughCapture, PngLevelChangesTheFileNotThePixels) {
    ASSERT_EQ(runGrotto(flythrough("--frames 3 --png-level 0", dir_ / "l0")).exitCode, 0);
    ASSERT_EQ(runGrotto(flythrough("--frames 3 --png-level 9", dir_ / "l9")).exitCode, 0);
    for (const char* name : {"frame.0001.png", "frame.0003.png"}) {
        const std::vector<uint8_t> a = test::readPixels8(dir_ / "l0" / name), b = test::readPixels8(dir_ / "l9" / name);
        ASSERT_FALSE(a.empty()) << name;
        EXPECT_EQ(test::worstDifference(a, b), 0) << name;
        EXPECT_GT(fs::file_size(dir_ / "l0" / name), fs::file_size(dir_ / "l9" / name)) << name;
    }
}

TEST_F(FlythroughCapture, ExrHalfWithChosenAovs) {
    ASSERT_EQ(runGrotto(flythrough("--frames 2 --format exr", dir_ / "full")).exitCode, 0);
    test::RunResult r = runGrotto(flythrough("--frames 2 --format exr --exr-type half --aovs AO,Z,N", dir_ / "half"));
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const std::optional<ImageFile> full = readImage(dir_ / "full" / "frame.0002.exr");
    const std::optional<ImageFile> half = readImage(dir_ / "half" / "frame.0002.exr");
    ASSERT_TRUE(full && half);
    const ImageFile& f = *full;
    const ImageFile& h = *half;
    EXPECT_EQ(f.channels(), 18);  // RGBA and every AOV, as before the flags
    for (ChannelType t : f.channelTypes) EXPECT_EQ(t, ChannelType::Float);
    // (EXR keeps channels sorted by name: the order asked does not matter.)
    std::vector<std::string> names = h.channelNames;
    std::sort(names.begin(), names.end());
    EXPECT_EQ(names, (std::vector<std::string>{"A", "AO", "B", "G", "N.x", "N.y", "N.z", "R", "Z"}));
    for (int c = 0; c < h.channels(); ++c)
        EXPECT_EQ(h.channelTypes[size_t(c)], h.channelNames[size_t(c)] == "Z" ? ChannelType::Float : ChannelType::Half)
            << h.channelNames[size_t(c)];
    ASSERT_GE(h.zChannel, 0);
    EXPECT_EQ(h.channelNames[size_t(h.zChannel)], "Z");
    EXPECT_TRUE(h.worldToCamera.has_value());
    // The same values, to half's precision.
    for (const char* channel : {"R", "AO", "N.y", "Z"}) {
        const std::vector<float> a = f.channel(channel), b = h.channel(channel);
        ASSERT_EQ(a.size(), size_t(f.width) * f.height) << channel;
        ASSERT_EQ(b.size(), a.size()) << channel;
        for (size_t i = 0; i < a.size(); ++i) EXPECT_NEAR(a[i], b[i], 1e-3 * std::max(1.0f, std::abs(a[i]))) << channel;
    }
    r = runGrotto(flythrough("--frames 1 --format exr --aovs none", dir_ / "none"));
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const std::optional<ImageFile> colour = readImage(dir_ / "none" / "frame.0001.exr", ReadAs::Header);
    ASSERT_TRUE(colour);
    EXPECT_EQ(colour->channels(), 4);
    // Another choice of layers into the same directory would mix sequences.
    r = runGrotto(flythrough("--frames 2 --format exr --aovs AO", dir_ / "half"));
    EXPECT_EQ(r.exitCode, 2) << r.err;
}

TEST_F(FlythroughCapture, ChunksWithNothingToDoExitZero) {
    // 9 frames in 12 chunks: chunks 10 to 12 have none.
    const test::RunResult r = runGrotto(flythrough("--chunk 11/12", seq()));
    EXPECT_EQ(r.exitCode, 0) << r.err;
    EXPECT_NE(r.out.find("no frames"), std::string::npos) << r.out;
    EXPECT_FALSE(fs::exists(seq()));
    const test::RunResult nine = runGrotto(flythrough("--chunk 9/12", seq()));
    ASSERT_EQ(nine.exitCode, 0) << nine.err;
    EXPECT_TRUE(fs::exists(seq() / "frame.0009.png"));
    EXPECT_FALSE(fs::exists(seq() / "frame.0008.png"));
}

TEST_F(FlythroughCapture, RefusesBadCaptureFlags) {
    struct Bad {
        std::string flags, mention;
    };
    const std::vector<Bad> cases = {
        {"--chunk 0/3", "--chunk"},       {"--chunk 4/3", "--chunk"},
        {"--chunk 3", "--chunk"},         {"--chunk a/b", "--chunk"},
        {"--chunk 1/0", "--chunk"},       {"--chunk 1/3 --frames 1-2", "--chunk"},
        {"--name frame", "--name"},       {"--name %d_%d", "--name"},
        {"--name %s", "--name"},          {"--name a/%d", "--name"},
        {"--name .%04d", "--name"},       {"--start-number -1", "--start-number"},
        {"--start-number x", "--start-number"}, {"--png-level 10", "--png-level"},
        {"--png-level -1", "--png-level"}, {"--format exr --png-level 3", "--png-level"},
        {"--aovs AO", "--aovs"},          {"--format exr --aovs AO,bogus", "--aovs"},
        {"--format exr --aovs ''", "--aovs"}, {"--exr-type half", "--exr-type"},
        {"--format exr --exr-type double", "--exr-type"}, {"--video-quality 20", "--video-quality"},
    };
    for (const Bad& b : cases) expectRefused(flythrough(b.flags, seq()), b.mention, seq());
    // Neither a directory nor a video.
    expectRefused("flythrough " + world_.string() + " --path p --size 16x8", "--output", seq());
}

}  // namespace
}  // namespace grotto
