// The viewer's fly camera: exact motion far from the origin, mouse look that
// round-trips and stops short of the poles, orbits that keep their distance and
// look at the pivot, and the wheel's speed steps.
#include "app/viewer/fly_camera.h"
#include "grotto/error.h"
#include "engine/camera.h"

#include <gtest/gtest.h>

#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

#include <cmath>

namespace grotto::viewer {
namespace {

voxel::CameraDesc looking(glm::dvec3 position, glm::dvec3 direction) {
    return {.position = position, .target = position + direction, .fovDegrees = 50.0, .nearPlane = 0.1, .farPlane = 900.0};
}

glm::dvec3 direction(const voxel::CameraDesc& d) { return glm::normalize(d.target - d.position); }

double degreesBetween(glm::dvec3 a, glm::dvec3 b) {
    return glm::degrees(std::atan2(glm::length(glm::cross(a, b)), glm::dot(a, b)));
}

bool finite(glm::dvec3 v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

TEST(FlyCamera, MovesExactlySpeedTimesDtFarFromTheOrigin) {
    const glm::dvec3 start(1e6, -1e6, 1e6);
    const double speed = 2.0, dt = 1.0 / 64.0, step = speed * dt;  // binary fractions: exact at 1e6
    struct Case {
        FlyInput in;
        glm::dvec3 axis;
    };
    const Case cases[] = {{{.forward = true}, {0, 0, -1}}, {{.back = true}, {0, 0, 1}}, {{.left = true}, {-1, 0, 0}},
                          {{.right = true}, {1, 0, 0}},    {{.up = true}, {0, 1, 0}},   {{.down = true}, {0, -1, 0}}};
    for (const Case& c : cases) {
        FlyCamera cam(looking(start, {0, 0, -1}), speed);
        for (int frame = 1; frame <= 1000; ++frame) {
            cam.update(c.in, dt);
            const glm::dvec3 expected = start + c.axis * (step * frame);
            ASSERT_EQ(cam.position().x, expected.x) << "frame " << frame;
            ASSERT_EQ(cam.position().y, expected.y) << "frame " << frame;
            ASSERT_EQ(cam.position().z, expected.z) << "frame " << frame;
        }
    }
    // Shift: four times as far.
    FlyCamera cam(looking(start, {0, 0, -1}), speed);
    cam.update({.forward = true, .fast = true}, dt);
    EXPECT_EQ(cam.position().z, start.z - 4.0 * step);
}

TEST(FlyCamera, MovesFarFromTheOriginAsItDoesAtTheOrigin) {
    const glm::dvec3 dir = glm::normalize(glm::dvec3(0.3, 0.4, -0.8)), far(1e6, 2e6, -3e6);
    FlyCamera nearCam(looking({0, 0, 0}, dir), 7.0), farCam(looking(far, dir), 7.0);
    const FlyInput in{.forward = true, .right = true, .up = true};
    for (int i = 0; i < 100; ++i) {
        nearCam.update(in, 0.01);
        farCam.update(in, 0.01);
    }
    const glm::dvec3 moved = farCam.position() - far;
    // 100 rounding steps of half an ulp at 3e6 (4.7e-10 each) at most.
    EXPECT_LT(glm::length(moved - nearCam.position()), 100 * 4.7e-10);
    // Several keys at once share the speed: 100 frames of 0.07 units.
    EXPECT_NEAR(glm::length(nearCam.position()), 7.0, 1e-12);
}

TEST(FlyCamera, DescRoundTripsDirectionAndLens) {
    const glm::dvec3 dirs[] = {{0, 0, -1}, {1, 0, 0}, {0, 0, 1}, {-1, 0, 0}, {0.3, -0.5, 0.2}, {-2, 3, -1}, {1, -30, 0.5}};
    for (const glm::dvec3& d : dirs) {
        const voxel::CameraDesc in = looking({12.5, -3, 1e5}, d * 40.0);
        const voxel::CameraDesc out = FlyCamera(in, 1.0).desc();
        EXPECT_EQ(out.position, in.position);
        EXPECT_LT(glm::length(direction(out) - glm::normalize(d)), 1e-9) << d.x << " " << d.y << " " << d.z;
        EXPECT_NEAR(glm::length(out.target - out.position), 1.0, 1e-9);  // unit forward
        EXPECT_EQ(out.fovDegrees, 50.0);
        EXPECT_EQ(out.nearPlane, 0.1);
        EXPECT_EQ(out.farPlane, 900.0);
        // The same view as the renderer builds from the original desc.
        const glm::dmat3 a = lookAtBasis(in.position, in.target), b = lookAtBasis(out.position, out.target);
        for (int c = 0; c < 3; ++c) EXPECT_LT(glm::length(a[c] - b[c]), 1e-9);
    }
}

TEST(FlyCamera, MouseLookTurnsRightAndDownAndComesBack) {
    FlyCamera cam(looking({0, 0, 0}, {0, 0, -1}), 1.0);
    cam.update({.look = {100, 0}}, 0.0);  // 100 px right: 15 degrees to the right (toward +X)
    EXPECT_NEAR(degreesBetween(cam.forward(), {0, 0, -1}), 15.0, 1e-9);
    EXPECT_GT(cam.forward().x, 0.0);
    EXPECT_NEAR(cam.forward().y, 0.0, 1e-15);
    cam.update({.look = {0, 60}}, 0.0);  // 60 px down: 9 degrees below the horizon
    EXPECT_NEAR(cam.forward().y, -std::sin(glm::radians(9.0)), 1e-12);
    cam.update({.look = {-100, -60}}, 0.0);
    EXPECT_LT(glm::length(cam.forward() - glm::dvec3(0, 0, -1)), 1e-12);
    // A full turn of yaw (2400 px) in many small moves ends where it began.
    for (int i = 0; i < 2400; ++i) cam.update({.look = {1, 0}}, 0.0);
    EXPECT_LT(glm::length(cam.forward() - glm::dvec3(0, 0, -1)), 1e-9);
    EXPECT_EQ(cam.position(), glm::dvec3(0.0));  // looking alone does not move
}

TEST(FlyCamera, PitchStopsAt89Degrees) {
    FlyCamera cam(looking({5, 5, 5}, {1, 0, 0}), 1.0);
    const double limit = std::sin(glm::radians(kMaxPitchDegrees));
    cam.update({.look = {0, -1e5}}, 0.0);
    EXPECT_NEAR(cam.forward().y, limit, 1e-12);
    EXPECT_GT(cam.forward().x, 0.0) << "the heading survives the clamp";
    cam.update({.look = {0, 3e5}}, 0.0);
    EXPECT_NEAR(cam.forward().y, -limit, 1e-12);
    // A desc beyond the limit is clamped too, keeping its heading.
    const voxel::CameraDesc steep = FlyCamera(looking({0, 0, 0}, {1, 500, 0}), 1.0).desc();  // 89.9 degrees up
    EXPECT_NEAR(direction(steep).y, limit, 1e-12);
    EXPECT_GT(direction(steep).x, 0.0);
}

TEST(FlyCamera, StraightUpOrDownGivesNoNaN) {
    for (const double y : {1.0, -1.0, 1e-300, 0.0}) {
        const voxel::CameraDesc start = looking({1e6, 0, 1e6}, {0, y, 0});
        FlyCamera cam(start, 3.0);
        cam.update({.forward = true, .right = true, .look = {3, 4}}, 0.1);
        cam.orbit({1e6, 10, 1e6}, {5, 5});
        const voxel::CameraDesc d = cam.desc();
        EXPECT_TRUE(finite(d.position) && finite(d.target)) << "y " << y;
    }
    // Straight up: pitch 89 degrees with the heading makeCamera gives the same desc.
    const voxel::CameraDesc up = looking({0, 0, 0}, {0, 1, 0});
    const FlyCamera cam(up, 1.0);
    EXPECT_NEAR(cam.forward().y, std::sin(glm::radians(kMaxPitchDegrees)), 1e-12);
    EXPECT_LT(glm::length(cam.right() - lookAtBasis(up.position, up.target)[0]), 1e-12);
    const voxel::CameraDesc down = looking({0, 0, 0}, {0, -1, 0});
    EXPECT_LT(glm::length(FlyCamera(down, 1.0).right() - lookAtBasis(down.position, down.target)[0]), 1e-12);
}

TEST(FlyCamera, OrbitKeepsDistanceAndLooksAtThePivot) {
    const glm::dvec3 pivot(1e6, 50, -1e6);
    // Starts looking away from the pivot: the first orbit turns toward it.
    FlyCamera cam(looking(pivot + glm::dvec3(30, 10, 40), {1, 0, 0}), 1.0);
    const double distance = glm::length(cam.position() - pivot);
    const glm::dvec2 looks[] = {{0, 0}, {100, 0}, {-37, 12}, {250, -80}, {0, 900}, {-3, -2000}, {1e4, 1}};
    for (const glm::dvec2& look : looks) {
        const glm::dvec3 before = glm::normalize(cam.position() - pivot);
        cam.orbit(pivot, look);
        const glm::dvec3 offset = cam.position() - pivot;
        EXPECT_NEAR(glm::length(offset), distance, 1e-9) << look.x << " " << look.y;
        EXPECT_LT(glm::length(cam.forward() - (-offset / glm::length(offset))), 1e-9);
        EXPECT_LT(glm::length(direction(cam.desc()) - cam.forward()), 1e-9);
        if (look == glm::dvec2(100, 0)) {  // level with the pivot's height band: 15 degrees of azimuth
            const glm::dvec2 a(before.x, before.z), b(offset.x, offset.z);
            const double turned = glm::degrees(std::acos(glm::dot(a, b) / (glm::length(a) * glm::length(b))));
            EXPECT_NEAR(turned, 15.0, 1e-6);
        }
    }
}

TEST(FlyCamera, WheelStepsTheSpeedBy125Percent) {
    FlyCamera cam(looking({0, 0, 0}, {0, 0, -1}), 2.0);
    cam.update({.wheel = 1}, 0.0);
    EXPECT_NEAR(cam.speed(), 2.5, 1e-12);
    cam.update({.wheel = -2}, 0.0);
    EXPECT_NEAR(cam.speed(), 2.0 / 1.25, 1e-12);
    cam.update({.wheel = 3}, 0.0);
    EXPECT_NEAR(cam.speed(), 2.0 * 1.25 * 1.25, 1e-12);
    cam.update({.wheel = -2}, 0.0);
    EXPECT_NEAR(cam.speed(), 2.0, 1e-12);
    // The new speed moves the camera in the same frame.
    cam.update({.forward = true, .wheel = 1}, 0.5);
    EXPECT_NEAR(cam.position().z, -1.25, 1e-12);
    // A spun wheel stops at the limits; jumpTo keeps the speed.
    cam.update({.wheel = 1e4}, 0.0);
    EXPECT_EQ(cam.speed(), kMaxFlySpeed);
    cam.update({.wheel = -1e5}, 0.0);
    EXPECT_EQ(cam.speed(), kMinFlySpeed);
    cam.jumpTo(looking({9, 9, 9}, {1, 0, 0}));
    EXPECT_EQ(cam.speed(), kMinFlySpeed);
    EXPECT_EQ(cam.position(), glm::dvec3(9.0));
    EXPECT_THROW(FlyCamera(looking({0, 0, 0}, {0, 0, -1}), 0.0), Error);
    EXPECT_THROW(FlyCamera(looking({0, 0, 0}, {0, 0, -1}), std::nan("")), Error);
}

TEST(FlyCamera, OppositeKeysCancel) {
    FlyCamera cam(looking({1, 2, 3}, {0, 0, -1}), 5.0);
    cam.update({.forward = true, .back = true, .left = true, .right = true, .up = true, .down = true}, 1.0);
    EXPECT_EQ(cam.position(), glm::dvec3(1, 2, 3));
}

}  // namespace
}  // namespace grotto::viewer
