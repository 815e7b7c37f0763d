// Objects: the G-buffer's motion vectors against the analytic motion of a
// translating and a spinning box (static and moving camera), and an object's AO
// cast on the floor and received from it: the same as the same voxels baked into
// the world, and, turned off the grid, as close to the reference as the world's.
#include "engine/lab/reference_view.h"
#include "engine/renderer.h"
#include "engine/scene/scene_objects.h"
#include "tests/gpu_fixture.h"
#include "tests/scenes.h"
#include "shaders/shared/objects.h"

#include <cmath>

namespace grotto {
namespace {

using Objects = test::GpuTest;

voxel::ObjectDesc movingDesc(glm::dvec3 pivot) {
    voxel::ObjectDesc d;
    d.pivot = pivot;
    d.keys = {{0.0, glm::dvec3(0.0), glm::dquat(1, 0, 0, 0)}, {1.0, glm::dvec3(1.0), glm::dquat(1, 0, 0, 0)}};
    return d;
}

AoOptions objectsAo() {
    AoOptions o;
    o.estimator = estimatorPreset("high", 3.0);
    o.chain.temporalHistory = 16;
    return o;
}

Camera camera(glm::dvec3 eye, glm::dvec3 target, uint32_t w, uint32_t h) {
    return makeCamera(test::lookAt(eye, target, 60.0), w, h);
}

// Pixel coordinates (pixel centres at +0.5) of a world point in a camera, and its view depth.
glm::dvec3 project(const Camera& c, glm::dvec3 p) {
    const glm::dvec3 view = glm::transpose(c.basis) * (p - c.position);
    const glm::dvec4 clip = c.projection() * glm::dvec4(view, 1.0);
    return {(clip.x / clip.w * 0.5 + 0.5) * c.width, (clip.y / clip.w * 0.5 + 0.5) * c.height, -view.z};
}

struct MotionCase {
    const char* name;
    voxel::ObjectPose before, now;
    Camera cameraBefore, cameraNow;
};

// Renders `before` then `now` and checks every pixel's motion against the analytic
// reprojection of its surface point: an object's point carried by its two poses,
// a world point by the cameras alone.
void checkMotion(vk::Context& ctx, const MotionCase& m) {
    const voxel::World world = test::floorWorld();
    std::vector<voxel::World> boxes;
    boxes.push_back(test::boxWorld({4, 3, 5}));
    voxel::WorldDesc desc = world.desc();
    desc.objects = {movingDesc(m.now.pivot)};
    auto scene = uploadScene(ctx, world.mesh(), world.desc());
    auto objects = uploadObjects(ctx, boxes, desc);
    ASSERT_TRUE(objects->moving);
    const uint32_t w = m.cameraNow.width, h = m.cameraNow.height;
    FrameImages f;
    {
        Renderer r(ctx, *scene, world.desc().lighting, objectsAo(), w, h, objects.get());
        r.setObjectPoses(std::vector<voxel::ObjectPose>{m.before});
        r.render(m.cameraBefore, 1);
        r.setObjectPoses(std::vector<voxel::ObjectPose>{m.now});
        r.render(m.cameraNow, 2);
        f = r.readback(m.cameraNow, true);
    }
    ASSERT_EQ(f.motion.size(), size_t(4) * w * h) << m.name;
    size_t objectPixels = 0, worldPixels = 0;
    double worst = 0.0, worstDepth = 0.0;
    for (uint32_t y = 0; y < h; ++y)
        for (uint32_t x = 0; x < w; ++x) {
            const size_t i = size_t(y) * w + x;
            const float* mv = &f.motion[4 * i];
            if (f.surfaceIds[i] == 0) {
                EXPECT_EQ(mv[0], 0.0f) << m.name << " sky";
                continue;
            }
            const glm::dvec3 p = m.cameraNow.pointAt(x + 0.5, y + 0.5, m.cameraNow.linearDepth(f.depthBuffer[i]));
            const uint32_t object = gpu::surfaceObject(f.surfaceIds[i]);
            const glm::dvec3 was = object ? m.before.toWorld(m.now.toLocal(p)) : p;
            const glm::dvec3 q = project(m.cameraBefore, was);
            const double error = glm::length(glm::dvec2(q.x - (x + 0.5), q.y - (y + 0.5)) - glm::dvec2(mv[0], mv[1]));
            worst = std::max(worst, error);
            worstDepth = std::max(worstDepth, std::abs(mv[2] - q.z) / q.z);
            (object ? objectPixels : worldPixels)++;
            if (object) {  // the normal AOV turns with the object
                const glm::dvec3 n(f.normal[3 * i], f.normal[3 * i + 1], f.normal[3 * i + 2]);
                EXPECT_NEAR(glm::length(n), 1.0, 1e-5);
                const glm::dvec3 local = glm::conjugate(m.now.rotation) * n;
                EXPECT_NEAR(std::max({std::abs(local.x), std::abs(local.y), std::abs(local.z)}), 1.0, 1e-5) << m.name;
            } else if (m.cameraBefore.position == m.cameraNow.position && m.cameraBefore.basis == m.cameraNow.basis) {
                EXPECT_EQ(mv[0], 0.0f) << m.name << " world pixel " << x << "," << y << " under a still camera";
                EXPECT_EQ(mv[1], 0.0f) << m.name;
            }
        }
    EXPECT_GT(objectPixels, 800u) << m.name;
    EXPECT_GT(worldPixels, 5000u) << m.name;
    EXPECT_LT(worst, 0.05) << m.name << ": largest motion error in pixels";
    EXPECT_LT(worstDepth, 1e-4) << m.name << ": largest relative error of the previous depth";
}

TEST_F(Objects, MotionVectorsMatchAnalyticMotion) {
    const uint32_t w = 192, h = 128;
    const Camera still = camera({7, 8, 11}, {0, 1, 0}, w, h);
    const Camera moved = camera({7.4, 8.1, 10.7}, {0.1, 1, 0}, w, h);
    const glm::dvec3 pivot(2.0, 1.5, 2.5);
    voxel::ObjectPose a{{0.0, 1.0, 0.0}, glm::dquat(1, 0, 0, 0), pivot};
    voxel::ObjectPose slid = a;
    slid.position += glm::dvec3(0.37, 0.0, -0.21);
    voxel::ObjectPose spun = a;
    spun.rotation = glm::angleAxis(glm::radians(9.0), glm::normalize(glm::dvec3(0.3, 1.0, 0.2)));
    voxel::ObjectPose tilted = spun;
    tilted.rotation = glm::angleAxis(glm::radians(31.0), glm::normalize(glm::dvec3(0.3, 1.0, 0.2)));
    for (const MotionCase& m : {MotionCase{"translating, still camera", a, slid, still, still},
                                MotionCase{"translating, moving camera", a, slid, still, moved},
                                MotionCase{"spinning, still camera", spun, tilted, still, still},
                                MotionCase{"spinning, moving camera", spun, tilted, still, moved},
                                MotionCase{"standing, moving camera", a, a, still, moved}})
        checkMotion(ctx(), m);
}

struct AoRun {
    FrameImages frame;
    ReferenceView reference;
};

// GTAO (8 frames of history on a still view) and the reference of a floor scene,
// with `box` as an object at `pose` (none: the world alone).
AoRun renderAo(vk::Context& ctx, const voxel::World& world, const voxel::World* box, const voxel::ObjectPose& pose,
               const Camera& cam) {
    std::vector<voxel::World> boxes;
    if (box) boxes.push_back(*box);
    voxel::WorldDesc desc = world.desc();
    if (box) desc.objects = {movingDesc(pose.pivot)};
    auto scene = uploadScene(ctx, world.mesh(), world.desc());
    auto objects = box ? uploadObjects(ctx, boxes, desc) : nullptr;
    AoRun r;
    {
        Renderer renderer(ctx, *scene, world.desc().lighting, objectsAo(), cam.width, cam.height, objects.get());
        if (box) renderer.setObjectPoses(std::vector<voxel::ObjectPose>{pose});
        for (uint32_t i = 1; i <= 8; ++i) renderer.render(cam, i);
        r.frame = renderer.readback(cam, true);
    }
    const std::vector<voxel::PosedWorld> posed = box ? std::vector<voxel::PosedWorld>{{box, pose}}
                                                     : std::vector<voxel::PosedWorld>{};
    r.reference = referenceView(world, cam, 3.0, 256, &ctx, posed);
    return r;
}

double meanAbs(const std::vector<float>& a, const std::vector<float>& b, const std::vector<uint8_t>& mask) {
    double sum = 0.0;
    size_t n = 0;
    for (size_t i = 0; i < a.size(); ++i)
        if (mask[i]) sum += std::abs(double(a[i]) - b[i]), ++n;
    return n ? sum / double(n) : 1.0;
}

TEST_F(Objects, TurnedObjectCastsAndReceivesAoLikeWorldVoxels) {
    const Camera cam = camera({9, 10, 12}, {1, 0, 0}, 160, 120);
    // A 4x2x6 box as an object turned 90 degrees about +Y is the 6x2x4 box baked
    // into the world at x 0..5, z -3..0: (x, y, z) -> (z, y, -x).
    const voxel::World floor = test::floorWorld();
    const voxel::World baked = test::floorWorld([](int x, int y, int z) { return x >= 0 && x <= 5 && y >= 0 && y <= 1 && z >= -3 && z <= 0; });
    const voxel::World box = test::boxWorld({4, 2, 6});
    const voxel::ObjectPose turned{glm::dvec3(0.0), glm::angleAxis(glm::radians(90.0), glm::dvec3(0, 1, 0)), glm::dvec3(0.0)};
    const AoRun world = renderAo(ctx(), baked, nullptr, {}, cam);
    const AoRun object = renderAo(ctx(), floor, &box, turned, cam);
    size_t same = 0, differ = 0, objectPixels = 0;
    std::vector<uint8_t> mask(world.frame.ao.size(), 0);
    for (size_t i = 0; i < mask.size(); ++i) {
        if (!world.reference.surface[i] || !object.reference.surface[i]) continue;
        mask[i] = 1;
        objectPixels += gpu::surfaceObject(object.frame.surfaceIds[i]) != 0;
        (std::abs(world.frame.ao[i] - object.frame.ao[i]) <= 0.02f ? same : differ)++;
    }
    EXPECT_GT(objectPixels, 500u);
    EXPECT_LT(double(differ), 0.005 * double(same + differ)) << "GTAO differs by more than 0.02 at " << differ << " pixels";
    EXPECT_LT(meanAbs(world.frame.ao, object.frame.ao, mask), 0.002);
    EXPECT_LT(meanAbs(world.reference.ao, object.reference.ao, mask), 0.01) << "the reference traces the object";

    // Off the grid (30 degrees): GTAO as close to the reference as on the world's voxels.
    const voxel::ObjectPose skew{glm::dvec3(0.0), glm::angleAxis(glm::radians(30.0), glm::dvec3(0, 1, 0)), glm::dvec3(0.0)};
    const AoRun skewed = renderAo(ctx(), floor, &box, skew, cam);
    const double bakedError = meanAbs(world.frame.ao, world.reference.ao, world.reference.surface);
    const double skewedError = meanAbs(skewed.frame.ao, skewed.reference.ao, skewed.reference.surface);
    EXPECT_LT(skewedError, bakedError + 0.01) << "baked " << bakedError;
    // It casts AO on the floor beside it and receives the floor's at its foot.
    double floorNear = 0.0, foot = 0.0, gtaoFoot = 0.0;
    size_t nFloor = 0, nFoot = 0;
    for (uint32_t y = 0; y < cam.height; ++y)
        for (uint32_t x = 0; x < cam.width; ++x) {
            const size_t i = size_t(y) * cam.width + x;
            if (!skewed.reference.surface[i]) continue;
            const glm::dvec3 p = cam.pointAt(x + 0.5, y + 0.5, skewed.frame.depth[i]);
            const glm::dvec3 local = skew.toLocal(p);
            const double outside = std::max({-0.5 - local.x, local.x - 3.5, -0.5 - local.z, local.z - 5.5, 0.0});
            if (gpu::surfaceObject(skewed.frame.surfaceIds[i]) == 0 && outside > 0.0 && outside < 0.5)
                floorNear += skewed.reference.ao[i], ++nFloor;
            if (gpu::surfaceObject(skewed.frame.surfaceIds[i]) != 0 && std::abs(skewed.frame.normal[3 * i + 1]) < 0.5 &&
                p.y < 0.0)
                foot += skewed.reference.ao[i], gtaoFoot += skewed.frame.ao[i], ++nFoot;
        }
    ASSERT_GT(nFloor, 20u);
    ASSERT_GT(nFoot, 20u);
    EXPECT_LT(floorNear / nFloor, 0.8) << "the object darkens the floor beside it";
    EXPECT_LT(foot / nFoot, 0.8) << "the floor darkens the object's foot";
    EXPECT_LT(gtaoFoot / nFoot, 0.85) << "in GTAO too";
}

}  // namespace
}  // namespace grotto
