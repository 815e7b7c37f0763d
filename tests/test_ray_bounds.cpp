// An AO radius of any accepted length finishes: a ray that has left the world's
// bounds can hit nothing more, so it ends there. Every command that traces the
// world's rays on the CPU (bake, render --ao cache baking at load, export-mesh,
// reference) runs with --radius 1e15 (the largest accepted) within a few CPU
// seconds, and gives what a radius just past the world's diagonal gives.
#include "tests/cli_fixture.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>
#include <string>
#include <vector>

namespace grotto {
namespace {

namespace fs = std::filesystem;
using test::CliErrors;
using test::runGrotto;

// Today's rays take well under a second here; without the clip, 1e15 ran for minutes.
const test::RunLimits kBounded{.cpuSeconds = 10, .hangSeconds = 120};
const std::string kDiagonal = "30";  // the world below is 16 x 6 x 16 voxels: its diagonal is 23.4

class RayBounds : public CliErrors {
protected:
    void SetUp() override {
        CliErrors::SetUp();
        // A floor, a wall along one side and a block on the floor: AO near each.
        writeSolid(world_, 16, 6, [](int x, int y, int z) {
            return y == 0 || (x == 0 && y < 6) || (x >= 6 && x <= 8 && z >= 6 && z <= 8 && y < 4);
        });
    }

    // Runs `command` with each radius; returns the outputs' paths in that order.
    std::vector<fs::path> runBoth(const std::string& command, const std::string& ext) {
        std::vector<fs::path> outputs;
        for (const std::string radius : {"1e15", kDiagonal.c_str()}) {
            outputs.push_back(dir_ / ("r" + radius + ext));
            const test::RunResult r =
                runGrotto(command + " --radius " + radius + " -o " + outputs.back().string(), "", kBounded);
            EXPECT_EQ(r.exitCode, 0) << command << " --radius " << radius << ": " << r.err;
        }
        return outputs;
    }

    static std::string bytesOf(const fs::path& p) {
        std::ifstream in(p, std::ios::binary);
        return {std::istreambuf_iterator<char>(in), {}};
    }

    // The reference's first channel, AO.
    static std::vector<float> aoOf(const fs::path& exr) {
        const std::optional<ImageFile> image = readImage(exr);
        if (!image || image->channelNames.empty()) return {};
        return image->channel(image->channelNames[0]);
    }

    fs::path world_ = dir_ / "walls.vdb";
};

TEST_F(RayBounds, ABakeWithTheLargestRadiusIsTheBakeWithTheDiagonal) {
    const auto gfc = runBoth("bake " + world_.string() + " --rays 16", ".gfc");
    const std::string a = bytesOf(gfc[0]), b = bytesOf(gfc[1]);
    ASSERT_EQ(a.size(), b.size());
    ASSERT_GT(a.size(), 1000u);
    size_t differing = 0;
    for (size_t k = 0; k < a.size(); ++k) differing += a[k] != b[k];
    EXPECT_LE(differing, 8u);  // the key's radius (a double), and nothing of the texels
}

TEST_F(RayBounds, RenderAndExportWithTheLargestRadiusFinishAlike) {
    const auto png = runBoth("render " + world_.string() + " --ao cache --size 32x16", ".png");
    const std::vector<uint8_t> a = test::readPixels8(png[0]);
    ASSERT_FALSE(a.empty());
    EXPECT_EQ(a, test::readPixels8(png[1]));
    const auto glb = runBoth("export-mesh " + world_.string() + " --rays 16", ".glb");
    EXPECT_EQ(bytesOf(glb[0]), bytesOf(glb[1]));
}

TEST_F(RayBounds, AReferenceWithTheLargestRadiusIsTheReferenceWithTheDiagonal) {
    const auto exr = runBoth("reference " + world_.string() + " --size 32x16 --spp 16", ".exr");
    const std::vector<float> a = aoOf(exr[0]);
    ASSERT_FALSE(a.empty());
    EXPECT_EQ(a, aoOf(exr[1]));
    float darkest = 1.0f;
    for (float v : a) darkest = std::min(darkest, v);
    EXPECT_LT(darkest, 0.9f);  // the walls do occlude: the radius reaches something
}

// The world file's own radius takes the same way.
TEST_F(RayBounds, AWorldsLargestRadiusFinishes) {
    const fs::path json = writeText("far.json", R"({"grid": {"file": "walls.vdb"}, "ao": {"radius": 1e15}})");
    const fs::path gfc = dir_ / "far.gfc";
    const test::RunResult r = runGrotto("bake " + json.string() + " --rays 16 -o " + gfc.string(), "", kBounded);
    EXPECT_EQ(r.exitCode, 0) << r.err;
    EXPECT_TRUE(fs::exists(gfc));
}

}  // namespace
}  // namespace grotto
