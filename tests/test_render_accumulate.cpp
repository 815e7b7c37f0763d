// render --accumulate: a still is rendered N times through the temporal pass, so
// its AO averages N frames of noise. The history shows N, the noise falls, the
// error against the ray-traced reference does too, objects hold their --time
// pose, and what cannot be accumulated is refused.
#include "tests/cli_fixture.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <limits>
#include <map>

namespace grotto {
namespace {

namespace fs = std::filesystem;
using test::CliErrors;
using test::runGrotto;

// An EXR's channels by name, each width x height floats; empty if it cannot be read.
std::map<std::string, std::vector<float>> readChannels(const fs::path& exr) {
    const std::optional<ImageFile> image = readImage(exr);
    if (!image) return {};
    std::map<std::string, std::vector<float>> channels;
    for (const std::string& name : image->channelNames) channels[name] = image->channel(name);
    return channels;
}

// Renders with --aov and returns the EXR's channels; fails the test when the run does.
std::map<std::string, std::vector<float>> renderAovs(const std::string& args, const fs::path& exr) {
    const test::RunResult r = runGrotto("render " + args + " --aov -o " + exr.string());
    EXPECT_EQ(r.exitCode, 0) << args << "\n" << r.err;
    return readChannels(exr);
}

// EXR readers expect a finite Z, so sky is written as the largest float.
bool surface(float z) { return z < std::numeric_limits<float>::max(); }

// AO_history at each AO pixel (full-res pixel (2x, 2y), which the half-res AOVs
// are stored from) that shows a surface, counted by value.
std::map<float, int> historyOnSurfaces(const std::map<std::string, std::vector<float>>& aovs, int width) {
    std::map<float, int> counts;
    const std::vector<float>& z = aovs.at("Z");
    const size_t w = size_t(width);
    for (size_t i = 0; i < z.size(); ++i)
        if ((i % w) % 2 == 0 && (i / w) % 2 == 0 && surface(z[i])) ++counts[aovs.at("AO_history")[i]];
    return counts;
}

// Root mean square of a - b over the surface pixels (Z below the sky's).
double rms(const std::vector<float>& a, const std::vector<float>& b, const std::vector<float>& z) {
    double sum = 0.0;
    size_t n = 0;
    for (size_t i = 0; i < a.size(); ++i)
        if (surface(z[i])) sum += double(a[i] - b[i]) * double(a[i] - b[i]), ++n;
    return n ? std::sqrt(sum / double(n)) : 0.0;
}

// Every surface pixel's history holds exactly the frames accumulated: the flag's
// N, the temporal history by default (16, or --temporal's), and N where N is
// longer than the history (raised for the render).
TEST_F(CliErrors, AccumulatedHistoryCountsEveryFrame) {
    const fs::path exr = dir_ / "still.exr";
    const std::string base = (test::worldsDir() / "rooms.json").string() + " --camera table --size 64x36";
    const std::pair<const char*, float> cases[] = {
        {" --accumulate 8", 8.0f}, {" --accumulate 1", 1.0f}, {"", 16.0f}, {" --temporal 5", 5.0f},
        {" --temporal 4 --accumulate 8", 8.0f}, {" --accumulate 64", 64.0f}};
    for (const auto& [flags, frames] : cases) {
        const std::map<float, int> history = historyOnSurfaces(renderAovs(base + flags, exr), 64);
        ASSERT_EQ(history.size(), 1u) << flags << ": every surface pixel has one history length";
        EXPECT_EQ(history.begin()->first, frames) << flags;
        EXPECT_GT(history.begin()->second, 32 * 18 / 2) << flags << ": the room fills most of the view";
    }
    // Without a temporal pass there is one frame, and that is the default then.
    const test::RunResult r = runGrotto("render " + base + " --temporal 0 --aov -o " + exr.string());
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_NE(r.out.find("1 frame,"), std::string::npos) << r.out;
    const std::map<float, int> off = historyOnSurfaces(readChannels(exr), 64);
    ASSERT_EQ(off.size(), 1u);
    EXPECT_EQ(off.begin()->first, 1.0f);
}

// The accumulated AO averages the frames' noise. Noise is measured against the
// most converged still (64 frames): the mean of the first k of 64 frames differs
// from the mean of all 64 by sqrt(1/k - 1/64) of one frame's noise, 0.33 of the
// single frame's difference for k = 8 were the frames' noise independent (GTAO's
// noise sequence does better: 0.23 measured). What the averaging removes must be
// error, not detail: the squared error against the ray-traced reference falls by
// about as much as the noise's variance (measured 0.78 of it here; 0.74-1.55 on
// rooms, thin and city). GTAO's remaining error is bias, which no number of
// frames removes, so the RMSE itself falls by little (0.2302 to 0.2282).
TEST_F(CliErrors, AccumulatedStillIsLessNoisyAndCloserToTheReference) {
    // A third of the pixels under the sanitizers: the reference's CPU rays are most of the time.
    const std::string args = (test::worldsDir() / "caves.json").string() + (test::kAddressSanitizer ? " --size 96x54" : " --size 160x90");
    std::map<int, std::vector<float>> ao;
    std::vector<float> z;
    for (int frames : {1, 8, 64}) {
        auto aovs = renderAovs(args + " --accumulate " + std::to_string(frames), dir_ / "still.exr");
        ASSERT_TRUE(aovs.count("AO")) << frames;
        ao[frames] = aovs.at("AO");
        z = aovs.at("Z");
    }
    const fs::path refExr = dir_ / "ref.exr";
    const test::RunResult ref = runGrotto("reference " + args + " --spp 1024 -o " + refExr.string(),
                                          "GROTTO_CACHE_DIR=" + (dir_ / "cache").string());
    ASSERT_EQ(ref.exitCode, 0) << ref.err;
    const std::vector<float> reference = readChannels(refExr).at("AO");

    const double noise1 = rms(ao[1], ao[64], z), noise8 = rms(ao[8], ao[64], z);
    const double error1 = rms(ao[1], reference, z), error8 = rms(ao[8], reference, z);
    const double error64 = rms(ao[64], reference, z);
    std::printf("noise against 64 frames: 1 frame %.4f, 8 frames %.4f (ratio %.2f)\n", noise1, noise8, noise8 / noise1);
    std::printf("RMSE against the reference: 1 frame %.4f, 8 frames %.4f, 64 frames %.4f\n", error1, error8, error64);
    EXPECT_GT(noise1, 0.01) << "a single frame is visibly noisy; a render that ignored --accumulate would read 0";
    EXPECT_LT(noise8, 0.5 * noise1);
    EXPECT_LT(error8, error1);
    EXPECT_LT(error64, error1);
    EXPECT_GT(error1 * error1 - error8 * error8, 0.5 * (noise1 * noise1 - noise8 * noise8))
        << "the averaging removed detail along with the noise";
}

// --time places the objects, and they hold that pose through every accumulated
// frame: had they moved between frames, the pixels they cover or uncover would
// restart their history and read less than N.
TEST_F(CliErrors, AccumulatedObjectsHoldTheirTimePose) {
    const std::string args = (test::worldsDir() / "yard.json").string() + " --size 96x64 --accumulate 8";
    const auto at0 = renderAovs(args + " --time 0", dir_ / "t0.exr");
    const auto at1 = renderAovs(args + " --time 1.2", dir_ / "t1.exr");
    ASSERT_TRUE(at0.count("R") && at1.count("R"));
    size_t changed = 0;
    for (size_t i = 0; i < at0.at("Z").size(); ++i) changed += std::abs(at0.at("Z")[i] - at1.at("Z")[i]) > 0.1f;
    EXPECT_GT(changed, 100u) << "the objects moved between 0 s and 1.2 s";
    for (const auto* aovs : {&at0, &at1}) {
        const std::map<float, int> history = historyOnSurfaces(*aovs, 96);
        ASSERT_EQ(history.size(), 1u) << "every surface pixel, objects' too, has the whole history";
        EXPECT_EQ(history.begin()->first, 8.0f);
    }
}

// Out of range, not a number, or more than one frame with nothing to average:
// exit 2, one line naming --accumulate, nothing written.
TEST_F(CliErrors, AccumulateRefusesWhatItCannotDo) {
    for (const char* bad : {"0", "65", "abc", "2.5", "-1"}) {
        const test::RunResult r = expectRefused(render(good_) + " --accumulate " + bad, "--accumulate", out());
        EXPECT_NE(r.err.find("1 to 64"), std::string::npos) << r.err;
    }
    expectRefused(render(good_) + " --ao off --accumulate 8", "--accumulate: 8 frames have nothing to average: AO is off",
                  out());
    expectRefused(render(good_) + " --temporal 0 --accumulate 2", "--temporal 0", out());
    const fs::path world = writeText("still.json", R"({"grid": {"file": "good.vdb"}, "ao": {"temporal_history": 0}})");
    expectRefused(render(world) + " --accumulate 4", "ao.temporal_history is 0", out());
    // One frame is always possible.
    for (const char* one : {" --ao off --accumulate 1", " --temporal 0 --accumulate 1", " --ao off"}) {
        const test::RunResult r = runGrotto(render(good_) + one);
        EXPECT_EQ(r.exitCode, 0) << one << "\n" << r.err;
        EXPECT_NE(r.out.find("1 frame,"), std::string::npos) << r.out;
        fs::remove(out());
    }
}

}  // namespace
}  // namespace grotto
