// Files from and for other tools through the command line: a glTF camera played by
// flythrough frame by frame, glTF meshes exported, MagicaVoxel models converted
// and rendered, and broken ones refused the way every bad input is.
#include "tests/cli_fixture.h"
#include "tests/gltf_camera_writer.h"
#include "tests/vox_writer.h"

#include <glm/gtc/matrix_transform.hpp>
#include <glm/mat4x4.hpp>

#include <cmath>

namespace grotto::test {
namespace {

class CliFormats : public CliErrors {};

// The camera at frame i as the samplers say: the parent (8, 0, 8) turned 90 degrees
// about Y, the camera sliding along its local X over 2 s and turning 40 degrees.
struct Expected {
    glm::dvec3 position;
    glm::dvec3 forward;
};
Expected expectedAt(double t) {
    const double u = std::clamp(t / 2.0, 0.0, 1.0);
    const glm::dquat parent = glm::angleAxis(glm::radians(90.0), glm::dvec3(0, 1, 0));
    const glm::dvec3 local = glm::mix(glm::dvec3(-6, 6, 14), glm::dvec3(6, 6, 14), u);
    const glm::dquat turn = glm::angleAxis(glm::radians(40.0 * u), glm::dvec3(0, 1, 0));
    return {glm::dvec3(8, 0, 8) + parent * local, parent * turn * glm::dvec3(0, 0, -1)};
}

GltfCameraScene slidingCamera() {
    GltfCameraScene s;
    s.parentTranslation = {8, 0, 8};
    s.parentRotation = glm::angleAxis(float(glm::radians(90.0)), glm::vec3(0, 1, 0));
    s.yfov = 0.9;
    const glm::quat turned = glm::angleAxis(float(glm::radians(40.0)), glm::vec3(0, 1, 0));
    s.samplers = {{"translation", "LINEAR", {0, 2}, {-6, 6, 14, 6, 6, 14}},
                  {"rotation", "LINEAR", {0, 2}, {0, 0, 0, 1, turned.x, turned.y, turned.z, turned.w}}};
    return s;
}

TEST_F(CliFormats, FlythroughPlaysAGltfCameraFrameByFrame) {
    const fs::path shot = dir_ / "shot.glb", out = dir_ / "frames";
    ASSERT_TRUE(writeGltfCamera(slidingCamera(), shot));
    const RunResult r = runGrotto("flythrough " + good_.string() + " --path-file " + shot.string() +
                                  " --fps 2 --size 24x16 --format exr --quiet -o " + out.string());
    ASSERT_EQ(r.exitCode, 0) << r.err;
    for (int i = 1; i <= 5; ++i) {  // 2 s at 2 fps: frames at 0, 0.5, ... 2 s
        char name[32];
        std::snprintf(name, sizeof name, "frame.%04d.exr", i);
        const std::optional<ImageFile> in = readImage(out / name, ReadAs::Header);
        ASSERT_TRUE(in) << name;
        ASSERT_TRUE(in->worldToCamera && in->worldToScreen) << name;
        glm::mat4 view, viewProjection;
        std::memcpy(&view[0][0], in->worldToCamera->data(), 64);
        std::memcpy(&viewProjection[0][0], in->worldToScreen->data(), 64);
        const glm::dmat4 worldFromCamera = glm::inverse(glm::dmat4(view));
        const Expected want = expectedAt((i - 1) / 2.0);
        EXPECT_LT(glm::length(glm::dvec3(worldFromCamera[3]) - want.position), 1e-3) << name;
        EXPECT_LT(glm::length(-glm::dvec3(worldFromCamera[2]) - want.forward), 1e-4) << name;
        // The projection's vertical scale is 1 / tan(yfov / 2).
        const glm::dmat4 projection = glm::dmat4(viewProjection) * worldFromCamera;
        EXPECT_NEAR(std::abs(projection[1][1]), 1.0 / std::tan(0.45), 1e-4) << name;
    }
}

TEST_F(CliFormats, ACameraFileWithoutAnAnimatedCameraIsRefusedNamingIt) {
    GltfCameraScene still = slidingCamera();
    still.samplers.clear();
    const fs::path shot = dir_ / "still.glb", out = dir_ / "frames";
    ASSERT_TRUE(writeGltfCamera(still, shot));
    expectRefused("flythrough " + good_.string() + " --path-file " + shot.string() + " -o " + out.string(),
                  "still.glb", out);
    expectRefused("path import " + shot.string() + " -o " + (dir_ / "p.json").string(), "is not animated", dir_ / "p.json");
    writeText("junk.glb", "glTF but not really");
    expectRefused("path import " + (dir_ / "junk.glb").string() + " -o " + (dir_ / "p.json").string(), "junk.glb",
                  dir_ / "p.json");
}

TEST_F(CliFormats, ExportMeshWritesGlbWithItsAoAndRefusesOtherNames) {
    const fs::path glb = dir_ / "floor.glb";
    const RunResult r = runGrotto("export-mesh " + good_.string() + " --rays 8 --texels 1 -o " + glb.string());
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_NE(r.out.find("576 faces"), std::string::npos) << r.out;  // 16 x 16 x 1: 256 + 256 + 64
    EXPECT_GT(fs::file_size(glb), 1000u);
    expectRefused("export-mesh " + good_.string() + " -o " + (dir_ / "floor.obj").string(), "floor.obj", dir_ / "floor.obj");
}

// A MagicaVoxel scene: a 6 x 6 x 1 floor and a 2 x 2 x 3 tower on it (colours 1 and 2).
fs::path writeVox(const fs::path& file) {
    std::array<voxel::VoxColor, 256> palette{};
    palette[0] = {180, 180, 170, 255};
    palette[1] = {40, 90, 200, 255};
    std::vector<std::array<uint8_t, 4>> floor, tower;
    for (uint8_t x = 0; x < 6; ++x)
        for (uint8_t y = 0; y < 6; ++y) floor.push_back({x, y, 0, 1});
    for (uint8_t x = 0; x < 2; ++x)
        for (uint8_t y = 0; y < 2; ++y)
            for (uint8_t z = 0; z < 3; ++z) tower.push_back({x, y, z, 2});
    const std::vector<uint8_t> bytes = voxel::test::VoxWriter()
        .model({6, 6, 1}, floor).model({2, 2, 3}, tower).palette(palette)
        .transform(0, 1).group(1, {2, 4}).transform(2, 3).shape(3, 0).transform(4, 5, {0, 0, 2}).shape(5, 1)
        .bytes();
    std::ofstream(file, std::ios::binary).write(reinterpret_cast<const char*>(bytes.data()), std::streamsize(bytes.size()));
    return file;
}

TEST_F(CliFormats, AVoxModelRendersDirectlyAndConvertedTheSame) {
    const fs::path vox = writeVox(dir_ / "tower.vox");
    const RunResult info = runGrotto("info " + vox.string());
    ASSERT_EQ(info.exitCode, 0) << info.err;
    EXPECT_NE(info.out.find("48"), std::string::npos) << info.out;  // 36 + 12 solid voxels
    const RunResult converted = runGrotto("convert " + vox.string() + " -o " + (dir_ / "tower.vdb").string());
    ASSERT_EQ(converted.exitCode, 0) << converted.err;
    EXPECT_TRUE(fs::exists(dir_ / "tower.json"));
    RunResult a = runGrotto("render " + vox.string() + " --size 32x24 --accumulate 1 -o " + (dir_ / "a.png").string());
    ASSERT_EQ(a.exitCode, 0) << a.err;
    RunResult b = runGrotto("render " + (dir_ / "tower.json").string() + " --size 32x24 --accumulate 1 -o " + (dir_ / "b.png").string());
    ASSERT_EQ(b.exitCode, 0) << b.err;
    const std::vector<uint8_t> pa = readPixels8(dir_ / "a.png"), pb = readPixels8(dir_ / "b.png");
    ASSERT_FALSE(pa.empty());
    EXPECT_EQ(worstDifference(pa, pb), 0);
    // The tower's blue shows: the palette became the materials.
    int blue = 0;
    for (size_t i = 0; i + 2 < pa.size(); i += 3) blue += pa[i + 2] > pa[i] + 40;
    EXPECT_GT(blue, 5);
    expectRefused("convert " + good_.string() + " -o " + (dir_ / "x.vdb").string(), "good.vdb", dir_ / "x.vdb");
}

TEST_F(CliFormats, AVoxModelExportsAsGlb) {
    const fs::path vox = writeVox(dir_ / "tower.vox");
    const RunResult r = runGrotto("export-mesh " + vox.string() + " --rays 16 -o " + (dir_ / "tower.glb").string());
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_NE(r.out.find("2 materials"), std::string::npos) << r.out;
}

}  // namespace
}  // namespace grotto::test
