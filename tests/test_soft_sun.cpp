// A soft sun (lighting.sun.angle > 0): each frame's shadow ray takes a direction
// from the sun's disc and the history averages them, so the shadow converges to
// the fraction of the disc each surface point sees. Checked against that fraction
// measured by exact CPU rays through the same disc, with the camera still and with
// the camera moving (the history must follow each surface point, not the pixel).
#include "engine/renderer.h"
#include "engine/lab/surface_points.h"
#include "tests/gpu_fixture.h"
#include "tests/scenes.h"
#include "tests/sun_rays.h"
#include "tests/test_util.h"

#include <glm/gtc/constants.hpp>

#include <cmath>
#include <cstdio>

namespace grotto {
namespace {

using test::GpuTest;

constexpr int kCpuRays = 256;           // per point, spread evenly over the sun's disc

// Unit directions spread evenly (a Fibonacci spiral) over the cone of half-angle
// acos(cosRadius) around `axis`, uniform in solid angle as the GPU draws them.
std::vector<glm::dvec3> coneDirections(glm::dvec3 axis, double cosRadius, int n) {
    const glm::dvec3 t = glm::normalize(glm::cross(std::abs(axis.y) < 0.9 ? glm::dvec3(0, 1, 0) : glm::dvec3(1, 0, 0), axis));
    const glm::dvec3 b = glm::cross(axis, t);
    const double golden = glm::pi<double>() * (3.0 - std::sqrt(5.0));
    std::vector<glm::dvec3> d;
    for (int i = 0; i < n; ++i) {
        const double cosT = 1.0 - (i + 0.5) / n * (1.0 - cosRadius), sinT = std::sqrt(1.0 - cosT * cosT);
        const double phi = golden * i;
        d.push_back(glm::normalize(axis * cosT + (t * std::cos(phi) + b * std::sin(phi)) * sinT));
    }
    return d;
}

struct SoftSunError {
    size_t points = 0;     // surface pixels
    size_t compared = 0;   // of them, those compared with the CPU
    size_t penumbra = 0;   // of those, seeing between 5% and 95% of the disc on the CPU
    double meanAbs = 0.0;  // mean |GPU - CPU| visible fraction
    size_t outliers = 0;   // |GPU - CPU| > kOutlier
};
constexpr double kOutlier = 0.25;

// The last of `frames` frames of rooms/table at 160x90 with a sun `angle` degrees
// wide, the camera stepping `step` world units to its right each frame (ending at
// the table camera), against the CPU's visible fraction of the disc. The CPU's rays
// take most of the time; under the sanitizers every 7th surface pixel is compared
// (7 is prime to the width: a diagonal pattern, not whole columns).
SoftSunError softSunError(vk::Context& ctx, float angle, uint32_t frames, double step) {
    const voxel::World world = voxel::World::load(test::worldsDir() / "rooms.json");
    auto scene = uploadScene(ctx, world);
    voxel::Lighting lighting = world.desc().lighting;
    lighting.sunShadows = true;
    lighting.sunAngle = angle;
    // The temporal AO's history caps the shadow's: long enough for a plain mean of every frame.
    AoOptions ao;
    ao.estimator = estimatorPreset("low", 2.0);
    ao.chain.temporalHistory = frames;
    Renderer renderer(ctx, *scene, lighting, ao, 160, 90);
    const voxel::CameraDesc end = world.camera("table", 16.0 / 9.0);
    const glm::dvec3 right = glm::normalize(glm::cross(end.target - end.position, glm::dvec3(0, 1, 0)));
    Camera camera;
    for (uint32_t k = 0; k < frames; ++k) {
        voxel::CameraDesc c = end;
        const glm::dvec3 shift = right * (step * double(frames - 1 - k));
        c.position -= shift;
        c.target -= shift;
        camera = makeCamera(c, 160, 90);
        renderer.render(camera, k);
    }
    const FrameImages f = renderer.readback(camera, true);
    const double vs = world.voxelSize();
    const glm::dvec3 sun(glm::normalize(lighting.sunDirection));
    const std::vector<glm::dvec3> disc = coneDirections(sun, std::cos(glm::radians(0.5 * double(angle))), kCpuRays);
    const SurfacePoints pts = surfacePoints(f, camera, vs, world.origin());
    test::SunRays rays(world);
    SoftSunError e;
    e.points = pts.points.size();
    for (size_t k = 0; k < pts.points.size(); k += size_t(test::underSanitizers(1, 7))) {
        const glm::dvec3 &p = pts.points[k], &n = pts.normals[k];
        int open = 0;
        for (const glm::dvec3& d : disc) open += glm::dot(n, d) > 0.0 && !rays.blocked(p, n, d);
        const double cpu = double(open) / double(disc.size()), diff = std::abs(f.shadow[pts.pixels[k]] - cpu);
        ++e.compared;
        e.penumbra += cpu > 0.05 && cpu < 0.95;
        e.meanAbs += diff;
        e.outliers += diff > kOutlier;
    }
    e.meanAbs /= double(std::max<size_t>(e.compared, 1));
    std::printf("[ measured ] soft sun %.1f deg, %u frames, step %.3f: %zu points, %zu compared (%zu in the penumbra), "
                "mean |GPU - CPU| %.4f, %zu beyond %.2f\n",
                angle, frames, step, e.points, e.compared, e.penumbra, e.meanAbs, e.outliers, kOutlier);
    return e;
}

using SoftSun = GpuTest;

TEST_F(SoftSun, StillCameraConvergesToTheVisibleFractionOfTheDisc) {
    const SoftSunError e = softSunError(ctx(), 8.0f, 64, 0.0);
    EXPECT_GT(e.points, size_t(160 * 90) / 2);
    EXPECT_GT(double(e.penumbra), 0.03 * double(e.compared));  // a real penumbra to get right
    EXPECT_LT(e.meanAbs, 0.01);  // measured 0.004 (every 7th pixel: 0.004)
    EXPECT_LE(double(e.outliers), 0.001 * double(e.compared));
}

TEST_F(SoftSun, HistoryFollowsTheSurfaceAsTheCameraMoves) {
    // A fraction of a pixel a frame: a history taken from the nearest pixel keeps
    // each pixel's own and smears the penumbra along the motion (mean error 0.047,
    // 6% of points beyond kOutlier, when tried).
    const SoftSunError e = softSunError(ctx(), 8.0f, 64, 0.02);
    EXPECT_GT(double(e.penumbra), 0.03 * double(e.compared));
    EXPECT_LT(e.meanAbs, 0.012);  // measured 0.0057, 10 of 14400 beyond (every 7th pixel: 0.0056, 1 of 2058)
    EXPECT_LE(double(e.outliers), 0.002 * double(e.compared));
}

TEST_F(SoftSun, FirstFramesAfterACutAnEditOrANewSunAreOneRayFromTheDisc) {
    // Before any history, each pixel holds one ray's answer: 0 or 1, nothing between.
    // An edit anywhere, or a sun that moved, may change the shadows anywhere: the
    // whole history restarts.
    const voxel::World world = voxel::World::load(test::worldsDir() / "rooms.json");
    auto scene = uploadScene(ctx(), world);
    voxel::Lighting lighting = world.desc().lighting;
    lighting.sunAngle = 8.0f;
    AoOptions noAo;
    noAo.estimator = estimatorPreset("low", 2.0);
    noAo.enabled = false;
    Renderer renderer(ctx(), *scene, lighting, noAo, 160, 90);
    const Camera camera = worldCamera(world, "table", 160, 90);
    uint32_t frame = 0;
    auto between = [&] {  // pixels strictly between 0 and 1 in the next frame
        renderer.render(camera, frame++);
        size_t n = 0;
        for (float s : renderer.readback(camera, true).shadow) n += s != 0.0f && s != 1.0f;
        return n;
    };
    EXPECT_EQ(between(), 0u) << "the first frame";
    for (int k = 0; k < 6; ++k) between();
    EXPECT_GT(between(), 100u) << "accumulated: a penumbra";
    renderer.invalidateHistory({{0.0, 0.0, 0.0}, {0.1, 0.1, 0.1}});
    EXPECT_EQ(between(), 0u) << "after an edit";
    EXPECT_GT(between(), 0u);
    lighting.sunDirection = glm::normalize(lighting.sunDirection + glm::vec3(0.05f, 0.0f, 0.0f));
    renderer.setLighting(lighting);
    EXPECT_EQ(between(), 0u) << "after the sun moved";
    EXPECT_GT(between(), 0u);
    ++frame;
    EXPECT_EQ(between(), 0u) << "after a frame index that does not follow";
}

}  // namespace
}  // namespace grotto
