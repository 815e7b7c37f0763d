// Projection and depth linearisation at the numerical extremes we support: near 1e-4 to 10,
// infinite and finite (1e7) far planes, a camera 1e6 units from the origin; and the
// default camera of a world without cameras, which frames its bounds tightly.
#include "engine/camera.h"
#include "voxel/world.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

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

// A bare grid's default camera fills the image with the grid's bounds, whatever
// their shape and the image's: every corner of the bounds projects inside the
// margin, and the projection spans kFramedFill of the width or the height, centred.
TEST(Camera, DefaultCameraFramesTheBoundsTightlyAtAnyAspect) {
    struct Shape {
        const char* name;
        glm::ivec3 size;
    };
    for (const Shape& shape : {Shape{"floor", {32, 1, 32}}, Shape{"tower", {4, 40, 4}}, Shape{"cube", {10, 10, 10}},
                               Shape{"wall", {60, 8, 2}}}) {
        const std::vector<uint8_t> solid(size_t(shape.size.x) * shape.size.y * shape.size.z, 1);
        const voxel::World world = voxel::World::fromDense(shape.size, solid.data(), 0.5, {1e5, -20.0, 3.0});
        const glm::dvec3 lo = world.origin(), hi = lo + glm::dvec3(shape.size) * world.voxelSize();
        for (auto [w, h] : {std::pair{320u, 180u}, {180u, 320u}, {100u, 100u}, {400u, 100u}, {90u, 300u}}) {
            SCOPED_TRACE(std::string(shape.name) + " " + std::to_string(w) + "x" + std::to_string(h));
            const Camera c = worldCamera(world, "", w, h);
            const double tx = std::tan(0.5 * c.fovY) * c.aspect(), ty = std::tan(0.5 * c.fovY);
            glm::dvec2 least(1e9), most(-1e9);  // the projected corners, in [-1, 1] across the image
            for (int k = 0; k < 8; ++k) {
                const glm::dvec3 corner((k & 1) ? hi.x : lo.x, (k & 2) ? hi.y : lo.y, (k & 4) ? hi.z : lo.z);
                const glm::dvec3 view = glm::transpose(c.basis) * (corner - c.position);
                ASSERT_LT(view.z, -c.nearPlane) << "corner " << k << " is behind the near plane";
                const glm::dvec2 ndc(view.x / -view.z / tx, view.y / -view.z / ty);
                least = glm::min(least, ndc), most = glm::max(most, ndc);
            }
            // Not cut: inside the margin on every side.
            EXPECT_GE(std::min(least.x, least.y), -voxel::kFramedFill - 1e-9);
            EXPECT_LE(std::max(most.x, most.y), voxel::kFramedFill + 1e-9);
            // Filling: the axis that binds spans the whole of kFramedFill; both are centred.
            const glm::dvec2 span = 0.5 * (most - least);
            EXPECT_NEAR(std::max(span.x, span.y), voxel::kFramedFill, 1e-9);
            EXPECT_NEAR(most.x + least.x, 0.0, 1e-9);
            EXPECT_NEAR(most.y + least.y, 0.0, 1e-9);
        }
    }
}

}  // namespace
}  // namespace grotto
