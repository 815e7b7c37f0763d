// The display image (what the window and a game show) is the scene-linear colour
// through the tone map the image writers apply on the CPU: the GLSL and the C++
// side of shaders/shared/tone_map.h agree, for both curves, on a scene bright
// enough to reach the shoulder and the clamp.
#include "engine/image_output.h"
#include "engine/renderer.h"
#include "engine/session.h"
#include "engine/vk/readback.h"
#include "tests/gpu_fixture.h"
#include "tests/scenes.h"

#include <glm/gtc/packing.hpp>

#include <glm/gtc/quaternion.hpp>

#include <cmath>
#include <cstring>

namespace grotto {
namespace {

class DisplayImage : public test::GpuTest {};

TEST_F(DisplayImage, IsTheColourThroughTheSharedToneMap) {
    // A floor with pillars: sunlit tops, shaded sides, sky.
    const voxel::World world = test::makeVoxelWorld({-16, -1, -16}, {15, 4, 15}, [](int x, int y, int z) {
        return y < 0 || (x % 6 == 0 && z % 5 == 0);
    });
    voxel::Lighting light = world.desc().lighting;
    light.sunIntensity = 4.0f;
    light.exposure = 1.0f;
    AoOptions ao;
    ao.enabled = false;
    ao.estimator = estimatorPreset("high", 1.0);  // unused, but checked
    auto scene = uploadScene(ctx(), world);
    const Camera camera = makeCamera(test::lookAt({0, 9, 20}, {0, 0, 0}), 61, 37);
    Renderer renderer(ctx(), *scene, light, ao, 61, 37);
    renderer.setDisplayImage(true);
    for (const voxel::ToneMap curve : {voxel::ToneMap::Filmic, voxel::ToneMap::Linear}) {
        light.toneMap = curve;
        renderer.setLighting(light);
        renderer.render(camera);
        const FrameImages f = renderer.readback(camera, false);
        EXPECT_EQ(f.toneMap, curve == voxel::ToneMap::Filmic ? GROTTO_TONE_MAP_FILMIC : GROTTO_TONE_MAP_CLAMP);
        const std::vector<float> cpu = displayColor(f);
        const std::vector<uint8_t> bytes = vk::readImage(ctx(), renderer.displayImage(), VK_IMAGE_LAYOUT_GENERAL, 8);
        ASSERT_EQ(bytes.size(), f.color.size() * 2);
        float worst = 0.0f, brightest = 0.0f;
        for (size_t k = 0; k < f.color.size(); ++k) {
            if (k % 4 == 3) continue;
            uint16_t half;
            std::memcpy(&half, &bytes[2 * k], 2);
            worst = std::max(worst, std::abs(glm::unpackHalf1x16(half) - cpu[k]));
            brightest = std::max(brightest, f.color[k]);
            ASSERT_EQ(cpu[k], gpu::toneMap(f.color[k], f.toneMap));
        }
        EXPECT_GT(brightest, 1.5f) << "the scene must reach the shoulder";
        EXPECT_LT(worst, 1e-3f) << "half floats round to 2^-11 of the value";
    }
}

// The normals image a game composites with holds each pixel's face normal in world
// space: the read-back's normals (made on the CPU from the surface ids and the
// poses), an object's faces turned by its rotation, w 1 on surfaces and 0 on the sky.
TEST_F(DisplayImage, NormalsAreEachPixelsFaceInWorldSpace) {
    voxel::World world = test::makeVoxelWorld({-8, -1, -8}, {7, 0, 7}, [](int, int y, int) { return y < 0; });
    AoOptions ao;
    ao.enabled = false;
    ao.estimator = estimatorPreset("high", 1.0);
    RenderSession session(ctx(), std::move(world), ao, voxel::Detail{}, 48, 36, true);
    session.addObject(test::makeVoxelWorld({0, 0, 0}, {2, 2, 2}, [](int, int, int) { return true; }),
                      {.name = "box", .pivot = {1.5, 0.0, 1.5},
                       .keys = {{.rotation = glm::angleAxis(0.5, glm::dvec3(0.0, 1.0, 0.0))}}});
    Renderer& renderer = session.renderer();
    renderer.setNormalsImage(true);
    const Camera camera = makeCamera(test::lookAt({5, 6, 8}, {0, 1, 0}), 48, 36);
    renderer.render(camera);
    const FrameImages f = renderer.readback(camera, true);
    const std::vector<uint8_t> bytes = vk::readImage(ctx(), renderer.normalsImage(), VK_IMAGE_LAYOUT_GENERAL, 8);
    ASSERT_EQ(bytes.size(), size_t(48) * 36 * 8);
    float worst = 0.0f;
    int turned = 0, sky = 0;
    for (size_t i = 0; i < size_t(48) * 36; ++i) {
        uint16_t half[4];
        std::memcpy(half, &bytes[8 * i], 8);
        const bool surface = std::isfinite(f.depth[i]);
        ASSERT_EQ(glm::unpackHalf1x16(half[3]), surface ? 1.0f : 0.0f) << "pixel " << i;
        sky += !surface;
        for (int c = 0; c < 3; ++c) worst = std::max(worst, std::abs(glm::unpackHalf1x16(half[c]) - f.normal[3 * i + c]));
        turned += surface && std::abs(f.normal[3 * i]) > 0.1f && std::abs(f.normal[3 * i]) < 0.9f;
    }
    EXPECT_LT(worst, 1e-3f) << "half floats round to 2^-11";
    EXPECT_GT(turned, 20) << "the turned box's faces are in view";
    EXPECT_GT(sky, 20) << "so is the sky";
}

}  // namespace
}  // namespace grotto
