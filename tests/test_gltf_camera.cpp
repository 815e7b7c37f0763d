// A glTF camera animation as a Grotto path: the path plays the samplers (LINEAR
// exactly, CUBICSPLINE within the stated tolerance, STEP as cuts) through a
// parent's transform, and broken files are refused naming the file.
#include "engine/camera_path.h"
#include "grotto/error.h"
#include "tests/gltf_camera_writer.h"
#include "tests/test_util.h"
#include "voxel/gltf/gltf_camera.h"

#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <fstream>

namespace grotto {
namespace {

constexpr double kPi = 3.14159265358979323846;

glm::quat yaw(double degrees) { return glm::angleAxis(float(glm::radians(degrees)), glm::vec3(0, 1, 0)); }

// A parent turned 90 degrees about Y and moved; the camera moving in three LINEAR
// translation keys and two LINEAR rotation keys.
test::GltfCameraScene linearScene() {
    test::GltfCameraScene s;
    s.parentTranslation = {10, 0, -5};
    s.parentRotation = yaw(90);
    const glm::quat r1 = yaw(60);
    s.samplers = {{"translation", "LINEAR", {0, 1, 2}, {0, 5, 20, 4, 5, 20, 4, 8, 10}},
                  {"rotation", "LINEAR", {0, 2}, {0, 0, 0, 1, r1.x, r1.y, r1.z, r1.w}}};
    return s;
}

// What the samplers say, worked out here: parent * (T(t) R(t)).
voxel::GltfCameraAnimation::Pose expectedLinear(double t) {
    const glm::dvec3 keys[3] = {{0, 5, 20}, {4, 5, 20}, {4, 8, 10}};
    const double u = std::clamp(t, 0.0, 2.0);
    const glm::dvec3 local = u <= 1 ? glm::mix(keys[0], keys[1], u) : glm::mix(keys[1], keys[2], u - 1);
    const glm::dquat parent = glm::dquat(yaw(90));
    const glm::dquat rotation = glm::slerp(glm::dquat(1, 0, 0, 0), glm::dquat(yaw(60)), u / 2);
    return {glm::dvec3(10, 0, -5) + parent * local, parent * rotation};
}

// How far apart two frames are: the largest difference of their axes (about the angle, for small ones).
double angle(const glm::dmat3& a, const glm::dquat& b) {
    const glm::dmat3 m = glm::mat3_cast(b);
    double worst = 0.0;
    for (int c = 0; c < 3; ++c) worst = std::max(worst, glm::length(a[c] - m[c]));
    return worst;
}

TEST(GltfCamera, ALinearAnimationUnderAParentPlaysExactlyWithItsOwnKeys) {
    const test::ScratchDir dir;
    ASSERT_TRUE(test::writeGltfCamera(linearScene(), dir / "shot.glb"));
    const voxel::CameraPathDesc desc = voxel::importGltfCameraPath(dir / "shot.glb");
    EXPECT_EQ(desc.interpolation, voxel::PathInterpolation::Linear);
    EXPECT_EQ(desc.keys.size(), 3u);  // the key times 0, 1, 2: nothing else needed
    EXPECT_NEAR(*desc.fovDegrees, 0.8 * 180 / kPi, 1e-9);
    EXPECT_NEAR(*desc.nearPlane, 0.1, 1e-12);
    EXPECT_EQ(*desc.farPlane, 0.0);
    const CameraPath path(desc, voxel::CameraDesc{});
    EXPECT_DOUBLE_EQ(path.duration(), 2.0);
    for (double t = -0.5; t <= 2.5; t += 0.05) {
        const CameraPose pose = path.pose(t);
        const auto want = expectedLinear(t);
        EXPECT_LT(glm::length(pose.position - want.position), 1e-5) << "t " << t;
        EXPECT_LT(angle(pose.basis, want.rotation), 1e-5) << "t " << t;
        EXPECT_NEAR(pose.fovDegrees, 0.8 * 180 / kPi, 1e-9);
    }
    // The camera looks down its -Z: at t = 0 that is the parent's -Z turned 90 degrees, i.e. -X.
    const glm::dvec3 forward = -path.pose(0.0).basis[2];
    EXPECT_LT(glm::length(forward - glm::dvec3(-1, 0, 0)), 1e-6);
}

TEST(GltfCamera, ACubicSplineIsFollowedWithinTheToleranceAndAStepIsACut) {
    test::GltfCameraScene s;
    const glm::quat r1 = yaw(-45);
    // Per key: in-tangent, value, out-tangent.
    s.samplers = {{"translation", "CUBICSPLINE", {0, 1, 3},
                   {0, 0, 0, 0, 0, 0, 8, 0, 0,    -4, 6, 0, 5, 2, 1, -4, 6, 0,    0, 0, 3, 2, 4, 8, 0, 0, 0}},
                  {"rotation", "STEP", {0, 2}, {0, 0, 0, 1, r1.x, r1.y, r1.z, r1.w}}};
    const test::ScratchDir dir;
    ASSERT_TRUE(test::writeGltfCamera(s, dir / "shot.gltf"));
    const voxel::GltfCameraAnimation anim(dir / "shot.gltf");
    const voxel::CameraPathDesc desc = anim.path();
    EXPECT_GT(desc.keys.size(), 6u);  // the curve needed keys between the samplers'
    const CameraPath path(desc, voxel::CameraDesc{});
    auto hermite = [](glm::dvec3 p0, glm::dvec3 m0, glm::dvec3 p1, glm::dvec3 m1, double u, double span) {
        const double u2 = u * u, u3 = u2 * u;
        return (2 * u3 - 3 * u2 + 1) * p0 + (u3 - 2 * u2 + u) * span * m0 + (-2 * u3 + 3 * u2) * p1 + (u3 - u2) * span * m1;
    };
    double worst = 0.0;
    for (double t = 0.0; t <= 3.0; t += 0.01) {
        const glm::dvec3 want = t <= 1 ? hermite({0, 0, 0}, {8, 0, 0}, {5, 2, 1}, {-4, 6, 0}, t, 1.0)
                                       : hermite({5, 2, 1}, {-4, 6, 0}, {2, 4, 8}, {0, 0, 3}, (t - 1) / 2, 2.0);
        worst = std::max(worst, glm::length(path.pose(t).position - want));
    }
    std::printf("cubic: %zu keys, worst position error %.2e\n", desc.keys.size(), worst);
    // The stated tolerance is of the positions' extent (about 8.6 here), with slack for
    // the checks between keys being at quarter points only.
    EXPECT_LT(worst, 4 * voxel::kPathPositionTolerance * 8.6) << "worst " << worst;
    // The STEP rotation: identity up to 2 s, then a cut to the new one.
    EXPECT_EQ(path.shotAt(1.99), 0u);
    EXPECT_EQ(path.shotAt(2.0), 1u);
    EXPECT_LT(angle(path.pose(1.9).basis, glm::dquat(1, 0, 0, 0)), 1e-6);
    EXPECT_LT(angle(path.pose(2.0).basis, glm::dquat(r1)), 1e-6);
    EXPECT_LT(angle(path.pose(2.5).basis, glm::dquat(r1)), 1e-6);
}

// Files Blender's own exporter wrote (tests/data/blender/make_shot.py): the path
// plays the camera where Blender itself evaluates it at every frame f, at time
// f / fps as Blender exports it. Sampled (LINEAR, a key a frame): exactly.
// Unsampled (CUBICSPLINE from Bezier keys): as closely as the exporter's own
// conversion of the curves allows.
TEST(GltfCamera, BlenderExportsPlayWhereBlenderPutsTheCamera) {
    const std::filesystem::path data = test::worldsDir().parent_path() / "tests" / "data" / "blender";
    const nlohmann::json truth = nlohmann::json::parse(std::ifstream(data / "blender-shot.json"));
    const double fps = truth["fps"];
    for (const auto& [file, positionTolerance, axisTolerance] :
         {std::tuple{"blender-shot-sampled.glb", 1e-4, 1e-5}, std::tuple{"blender-shot-bezier.glb", 2e-3, 0.015}}) {
        SCOPED_TRACE(file);
        const voxel::CameraPathDesc desc = voxel::importGltfCameraPath(data / file);
        EXPECT_NEAR(*desc.fovDegrees, double(truth["fov_degrees"]), 1e-5);
        const CameraPath path(desc, voxel::CameraDesc{});
        double worstPosition = 0.0, worstAxis = 0.0;
        for (const auto& frame : truth["frames"]) {
            const CameraPose pose = path.pose(double(frame["frame"]) / fps);
            auto vec = [&](const char* key) { return glm::dvec3(frame[key][0], frame[key][1], frame[key][2]); };
            worstPosition = std::max(worstPosition, glm::length(pose.position - vec("position")));
            worstAxis = std::max({worstAxis, glm::length(-pose.basis[2] - vec("forward")), glm::length(pose.basis[1] - vec("up"))});
        }
        std::printf("%s: %zu keys, worst position %.2e, worst axis %.2e\n", file, desc.keys.size(), worstPosition, worstAxis);
        EXPECT_LT(worstPosition, positionTolerance);
        EXPECT_LT(worstAxis, axisTolerance);
    }
}

// A mirroring scale on the camera's node, and a morph-weights channel beside the
// camera's own: the camera still looks down its node's -Z, up its +Y, and moves
// as its translation says.
TEST(GltfCamera, AMirroredCameraNodeStillLooksDownItsMinusZ) {
    test::GltfCameraScene s = linearScene();
    s.samplers.push_back({"scale", "LINEAR", {0, 2}, {-1, 1, 1, -1, 1, 1}});
    const test::ScratchDir dir;
    ASSERT_TRUE(test::writeGltfCamera(s, dir / "mirror.glb"));
    const CameraPath path(voxel::importGltfCameraPath(dir / "mirror.glb"), voxel::CameraDesc{});
    for (double t = 0.0; t <= 2.0; t += 0.25) {
        const auto want = expectedLinear(t);
        const glm::dmat3 m = glm::mat3_cast(want.rotation);
        EXPECT_LT(glm::length(path.pose(t).position - want.position), 1e-5);
        EXPECT_LT(glm::length(path.pose(t).basis[2] - m[2]), 1e-5) << "t " << t;  // back (view is -back)
        EXPECT_LT(glm::length(path.pose(t).basis[1] - m[1]), 1e-5) << "t " << t;
    }
}

TEST(GltfCamera, ThePathFileWrittenFromItReadsBackTheSame) {
    const test::ScratchDir dir;
    ASSERT_TRUE(test::writeGltfCamera(linearScene(), dir / "shot.glb"));
    const test::RunResult r = test::runGrotto("path import " + (dir / "shot.glb").string() + " -o " + (dir / "shot.json").string());
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const voxel::CameraPathDesc read = voxel::loadCameraPath(dir / "shot.json");
    const CameraPath path(read, voxel::CameraDesc{});
    for (double t = 0.0; t <= 2.0; t += 0.25)
        EXPECT_LT(glm::length(path.pose(t).position - expectedLinear(t).position), 1e-5);
}

TEST(GltfCamera, BrokenFilesAreRefusedNamingTheFile) {
    const test::ScratchDir dir;
    auto refused = [&](const test::GltfCameraScene& s, const std::string& name, const std::string& says) {
        const std::filesystem::path file = dir / name;
        ASSERT_TRUE(test::writeGltfCamera(s, file));
        try {
            (void)voxel::importGltfCameraPath(file);
            ADD_FAILURE() << name << " was accepted";
        } catch (const Error& e) {
            EXPECT_NE(std::string(e.what()).find(file.string()), std::string::npos) << e.what();
            EXPECT_NE(std::string(e.what()).find(says), std::string::npos) << e.what();
        }
    };
    test::GltfCameraScene still = linearScene();
    still.samplers.clear();
    refused(still, "still.glb", "is not animated");
    test::GltfCameraScene backwards = linearScene();
    backwards.samplers[0].times = {0, 2, 1};
    refused(backwards, "backwards.glb", "does not come after");
    test::GltfCameraScene short_ = linearScene();
    short_.samplers[0].values.resize(6);
    refused(short_, "short.glb", "output values");
    test::GltfCameraScene wide = linearScene();
    wide.yfov = 3.1;
    refused(wide, "wide.glb", "yfov");
    test::GltfCameraScene oneKey = linearScene();
    oneKey.samplers = {{"translation", "LINEAR", {1}, {0, 0, 0}}};
    refused(oneKey, "one.glb", "one key time");
    test::GltfCameraScene cubic = linearScene();
    cubic.samplers[0].interpolation = "CUBICSPLINE";  // a third of the values it needs
    refused(cubic, "cubic.glb", "output values");
    test::GltfCameraScene twice = linearScene();
    twice.samplers.push_back(twice.samplers[0]);
    refused(twice, "twice.glb", "again");
    // JSON nested past 64 levels (tinygltf's parser would recurse once per level).
    std::ofstream(dir / "deep.gltf") << R"({"asset": {"version": "2.0", "extras": )" << std::string(100000, '[')
                                      << std::string(100000, ']') << "}}";
    try {
        (void)voxel::importGltfCameraPath(dir / "deep.gltf");
        ADD_FAILURE() << "deep.gltf was accepted";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("64 deep"), std::string::npos) << e.what();
    }
    // A .gltf whose buffer is a device: refused, not read forever.
    std::ofstream(dir / "device.gltf") << R"({"asset": {"version": "2.0"}, "buffers": [{"uri": "/dev/zero", "byteLength": 64}]})";
    EXPECT_THROW((void)voxel::importGltfCameraPath(dir / "device.gltf"), Error);
    // Not glTF at all, and a truncated .glb.
    std::ofstream(dir / "text.glb") << "hello";
    EXPECT_THROW((void)voxel::importGltfCameraPath(dir / "text.glb"), Error);
    ASSERT_TRUE(test::writeGltfCamera(linearScene(), dir / "whole.glb"));
    const auto size = std::filesystem::file_size(dir / "whole.glb");
    std::filesystem::copy_file(dir / "whole.glb", dir / "cut.glb");
    std::filesystem::resize_file(dir / "cut.glb", size / 2);
    EXPECT_THROW((void)voxel::importGltfCameraPath(dir / "cut.glb"), Error);
}

// Every cut of a camera file and every byte of it changed: read, or refused with
// grotto::Error naming the file; never anything else (the sanitizers watch).
TEST(GltfCamera, EveryTruncationAndChangedByteIsReadOrRefused) {
    const test::ScratchDir dir;
    test::GltfCameraScene s = linearScene();
    s.samplers.push_back({"scale", "CUBICSPLINE", {0, 1}, {0, 0, 0, 1, 1, 1, 0, 0, 0, 0, 0, 0, 2, 2, 2, 0, 0, 0}, 0});
    ASSERT_TRUE(test::writeGltfCamera(s, dir / "good.glb"));
    std::ifstream in(dir / "good.glb", std::ios::binary);
    const std::string real{std::istreambuf_iterator<char>(in), {}};
    const std::filesystem::path file = dir / "bad.glb";
    int read = 0, refused = 0;
    auto attempt = [&](const std::string& bytes) {
        std::ofstream(file, std::ios::binary | std::ios::trunc) << bytes;
        try {
            const voxel::CameraPathDesc p = voxel::importGltfCameraPath(file);
            for (const voxel::PathKey& k : p.keys) ASSERT_TRUE(std::isfinite(k.time) && std::isfinite(k.position.x));
            ++read;
        } catch (const Error& e) {
            ASSERT_NE(std::string(e.what()).find(file.string()), std::string::npos) << e.what();
            ++refused;
        }
    };
    for (size_t cut = 0; cut < real.size(); cut += 7) attempt(real.substr(0, cut));
    for (size_t i = 0; i < real.size(); ++i) {
        std::string bytes = real;
        bytes[i] = char(bytes[i] ^ (1 << (i % 8)));
        attempt(bytes);
    }
    EXPECT_GT(refused, 0);
    EXPECT_GT(read, 0);  // a changed float in a key is still a camera
    std::printf("%d read, %d refused\n", read, refused);
}

}  // namespace
}  // namespace grotto
