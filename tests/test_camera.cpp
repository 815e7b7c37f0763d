// Projection and depth linearisation at the numerical extremes we support: near 1e-4 to 10,
// infinite and finite (1e7) far planes, a camera 1e6 units from the origin.
#include "engine/camera.h"

#include <gtest/gtest.h>

#include <cmath>

namespace grotto {
namespace {

Camera cameraAt(glm::dvec3 position, double nearPlane, double farPlane) {
    voxel::CameraDesc d;
    d.position = position;
    d.target = position + glm::dvec3(0.3, -0.2, -1.0);
    d.nearPlane = nearPlane;
    d.farPlane = farPlane;
    d.fovDegrees = 70.0;
    return makeCamera(d, 333, 177);
}

TEST(Camera, DepthRoundTripsThroughA32BitDepthBuffer) {
    for (double n : {1e-4, 1e-2, 1.0, 10.0})
        for (double f : {0.0, 1e7}) {
            const Camera c = cameraAt({0, 0, 0}, n, f);
            const glm::dmat4 p = c.projection();
            const double farthest = f > 0 ? f * 0.999 : 1e6;
            for (double z = n * 1.001; z < farthest; z *= 1.7) {
                const glm::dvec4 clip = p * glm::dvec4(0.1 * z, -0.05 * z, -z, 1.0);
                const float stored = float(clip.z / clip.w);  // what a D32 target keeps
                ASSERT_GT(stored, 0.0f);
                ASSERT_LE(stored, 1.0f);
                EXPECT_NEAR(c.linearDepth(stored) / z, 1.0, 1e-5) << "near " << n << " far " << f << " z " << z;
            }
            EXPECT_NEAR(c.linearDepth(1.0), n, 1e-12 * n);  // the near plane maps to 1
        }
}

TEST(Camera, InfiniteFarMapsZeroDepthToInfinity) {
    const Camera c = cameraAt({0, 0, 0}, 0.05, 0.0);
    EXPECT_TRUE(std::isinf(c.linearDepth(0.0)));
    const Camera finite = cameraAt({0, 0, 0}, 0.05, 1e7);
    EXPECT_NEAR(finite.linearDepth(0.0), 1e7, 1.0);
}

TEST(Camera, RelativeMatricesMatchAbsoluteFarFromTheOrigin) {
    const glm::dvec3 eye(1e6, 2e3, -1e6);
    const Camera c = cameraAt(eye, 1e-4, 0.0);
    const glm::dmat4 absolute = c.projection() * c.viewFromWorld();
    const glm::mat4 relative = c.viewProjRelative();
    for (glm::dvec3 offset : {glm::dvec3(0.01, 0.0, -0.5), glm::dvec3(3, -2, -40), glm::dvec3(-100, 5, -900)}) {
        const glm::dvec4 a = absolute * glm::dvec4(eye + offset, 1.0);
        const glm::vec4 r = relative * glm::vec4(glm::vec3(offset), 1.0f);
        // Depth and screen position agree; the float path sees only small numbers.
        EXPECT_NEAR(r.z / r.w, a.z / a.w, 1e-6 * a.z / a.w);
        EXPECT_NEAR(r.x / r.w, a.x / a.w, 1e-5);
        EXPECT_NEAR(r.y / r.w, a.y / a.w, 1e-5);
    }
}

TEST(Camera, RayThroughPixelCentreProjectsBackToIt) {
    const Camera c = cameraAt({5, 6, 7}, 0.05, 0.0);
    const glm::dmat4 vp = c.projection() * c.viewFromWorld();
    for (auto [px, py] : {std::pair{0.5, 0.5}, {166.5, 88.5}, {332.5, 176.5}}) {
        const glm::dvec3 p = c.position + 10.0 * c.rayDirection(px, py);
        const glm::dvec4 clip = vp * glm::dvec4(p, 1.0);
        EXPECT_NEAR((clip.x / clip.w * 0.5 + 0.5) * c.width, px, 1e-6);
        EXPECT_NEAR((clip.y / clip.w * 0.5 + 0.5) * c.height, py, 1e-6);  // y flipped: row 0 on top
    }
}

TEST(Camera, LooksStraightDownWithoutNaN) {
    voxel::CameraDesc d;
    d.position = {0, 10, 0};
    d.target = {0, 0, 0};
    const Camera c = makeCamera(d, 2, 2);
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) EXPECT_TRUE(std::isfinite(c.basis[i][j]));
    EXPECT_NEAR(c.rayDirection(1, 1).y, -1.0, 1e-12);
}

}  // namespace
}  // namespace grotto
