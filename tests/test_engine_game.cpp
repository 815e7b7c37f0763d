// What a game does with the engine beyond rendering (<grotto/grotto.h>): pick what a
// ray or a pixel meets, add and remove objects at run time, read depth beside
// colour, play a world's path. Headless, with the validation layer on.
#include "tests/test_util.h"

#include <grotto/grotto.h>

#include <glm/gtc/constants.hpp>
#include <gtest/gtest.h>

namespace grotto {
namespace {

// A 16 x 4 x 16 world whose lower two layers are stone (material 1): its floor is y = 2.
VoxelGrid floorGrid() {
    VoxelGrid g{.size = {16, 4, 16}, .materials = std::vector<uint8_t>(16 * 4 * 16, 0)};
    for (int z = 0; z < 16; ++z)
        for (int y = 0; y < 2; ++y)
            for (int x = 0; x < 16; ++x) g.materials[(size_t(z) * 4 + y) * 16 + x] = 1;
    return g;
}

// A 2 x 2 x 2 brick crate (material 4) standing with its base's centre at (8, 2, 8).
Object crate() {
    return {.name = "crate", .voxels = {.size = {2, 2, 2}, .materials = std::vector<uint8_t>(8, 4)},
            .pivot = {1.0, 0.0, 1.0}, .position = {8.0, 2.0, 8.0}};
}

float largestDifference(const std::vector<float>& a, const std::vector<float>& b) {
    EXPECT_EQ(a.size(), b.size());
    float worst = a.size() == b.size() ? 0.0f : INFINITY;
    for (size_t i = 0; i < a.size() && i < b.size(); ++i) worst = std::max(worst, std::abs(a[i] - b[i]));
    return worst;
}

TEST(EngineGame, RaycastFindsTheWorldsVoxelsAndTheObjectsAtTheirPoses) {
    Engine engine({.width = 32, .height = 32, .validation = true});
    engine.setWorld(floorGrid());
    EXPECT_EQ(engine.objectCount(), 0u);
    EXPECT_EQ(engine.addObject(crate()), 0u);

    // Straight down onto the crate's top (y = 4), and onto the floor beside it.
    std::optional<Hit> h = engine.raycast({8.0, 10.0, 8.5}, {0.0, -3.0, 0.0});
    ASSERT_TRUE(h);
    EXPECT_EQ(h->object, std::optional<size_t>(0));
    EXPECT_NEAR(h->distance, 6.0, 1e-9);
    EXPECT_NEAR(h->position.y, 4.0, 1e-9);
    EXPECT_EQ(h->voxel, glm::ivec3(1, 1, 1)) << "the crate's own voxel";
    EXPECT_EQ(h->material, 4);
    EXPECT_NEAR(glm::length(h->normal - glm::dvec3(0, 1, 0)), 0.0, 1e-9);
    h = engine.raycast({3.0, 10.0, 3.0}, {0.0, -1.0, 0.0});
    ASSERT_TRUE(h);
    EXPECT_FALSE(h->object);
    EXPECT_NEAR(h->distance, 8.0, 1e-9);
    EXPECT_EQ(h->voxel, glm::ivec3(3, 1, 3));
    EXPECT_EQ(h->material, 1);
    EXPECT_EQ(engine.material(h->voxel), 1);
    EXPECT_FALSE(engine.raycast({3.0, 10.0, 3.0}, {0.0, -1.0, 0.0}, 7.5)) << "the floor lies beyond 7.5";
    EXPECT_FALSE(engine.raycast({3.0, 10.0, 3.0}, {0.0, 1.0, 0.0})) << "nothing above";

    // Turned 45 degrees about y, the crate shows a corner to a ray along +x: at
    // z = 8.3 the ray meets the face from corner (8 - sqrt 2, 8) to (8, 8 + sqrt 2).
    engine.setObjectPose(0, {8.0, 2.0, 8.0}, glm::angleAxis(glm::quarter_pi<double>(), glm::dvec3(0, 1, 0)));
    h = engine.raycast({0.0, 3.0, 8.3}, {1.0, 0.0, 0.0});
    ASSERT_TRUE(h);
    EXPECT_EQ(h->object, std::optional<size_t>(0));
    EXPECT_NEAR(h->distance, 8.0 - std::sqrt(2.0) + 0.3, 1e-9);
    EXPECT_NEAR(glm::length(h->normal - glm::normalize(glm::dvec3(-1, 0, 1))), 0.0, 1e-9);

    // Removed, the crate no longer stops the ray: the floor does.
    engine.removeObject(0);
    EXPECT_EQ(engine.objectCount(), 0u);
    h = engine.raycast({8.0, 10.0, 8.5}, {0.0, -1.0, 0.0});
    ASSERT_TRUE(h);
    EXPECT_FALSE(h->object);
    EXPECT_NEAR(h->distance, 8.0, 1e-9);
    EXPECT_THROW(engine.setObjectPose(0, glm::dvec3(0.0)), Error);
    EXPECT_THROW(engine.removeObject(0), Error);
    EXPECT_THROW(engine.raycast(glm::dvec3(0.0), glm::dvec3(0.0)), Error);
    EXPECT_EQ(engine.validationMessages(), 0);
}

// A pixel's pick is the ray through its centre, and its distance is the depth the
// frame hands back there: at the image's centre the view axis, so equal.
TEST(EngineGame, PickAgreesWithTheFramesDepth) {
    Engine engine({.width = 33, .height = 21, .validation = true});
    engine.setWorld(floorGrid());
    engine.addObject(crate());
    engine.setCamera({.position = {12.0, 9.0, 13.0}, .target = {8.0, 3.5, 8.0}, .fovDegrees = 50.0});
    const RenderedFrame frame = engine.render();
    EXPECT_EQ(frame.depth.format, VK_FORMAT_D32_SFLOAT);
    EXPECT_EQ(frame.normals.format, VK_FORMAT_R16G16B16A16_SFLOAT);
    EXPECT_EQ(frame.normals.extent.width, 33u);
    const Pixels p = engine.readPixels();
    ASSERT_EQ(p.depth.size(), size_t(33) * 21);
    const std::optional<Hit> centre = engine.pick(16, 10);
    ASSERT_TRUE(centre);
    EXPECT_EQ(centre->object, std::optional<size_t>(0)) << "the camera looks at the crate";
    EXPECT_NEAR(p.depth[10 * 33 + 16], centre->distance, 1e-4 * centre->distance);
    EXPECT_NEAR(p.normals[3 * (10 * 33 + 16) + 1] + p.normals[3 * (10 * 33 + 16) + 2],
                centre->normal.y + centre->normal.z, 1e-6);
    EXPECT_FALSE(engine.pick(16, 0)) << "the sky at the top";
    EXPECT_THROW(engine.pick(33, 0), Error);
    EXPECT_EQ(engine.validationMessages(), 0);
}

// An object added at run time is drawn as a world file's object is: saved and
// loaded back, the world renders the same; removed, as if it had never been.
// Without AO: its noise follows the frame count, which differs between engines.
TEST(EngineGame, ObjectsAddedAndRemovedAtRunTime) {
    const test::ScratchDir dir;
    const CameraDesc view{.position = {14.0, 8.0, 15.0}, .target = {8.0, 3.0, 8.0}, .fovDegrees = 55.0};
    Engine live({.width = 40, .height = 30, .validation = true});
    live.setWorld(floorGrid());
    live.setAo({.method = "off"});
    live.setCamera(view);
    live.render();
    const Pixels empty = live.readPixels();
    Object turned = crate();
    turned.rotation = glm::angleAxis(0.4, glm::dvec3(0, 1, 0));
    live.addObject(turned);
    live.render();
    const Pixels added = live.readPixels();
    EXPECT_NE(added.rgba, empty.rgba) << "the crate is in view";
    live.saveWorld(dir / "crate.json");

    Engine loaded({.width = 40, .height = 30, .validation = true});
    loaded.loadWorld(dir / "crate.json");
    ASSERT_EQ(loaded.objectCount(), 1u);
    EXPECT_EQ(loaded.ao().method, "off") << "saved with the engine's settings";
    loaded.setCamera(view);
    loaded.render();
    // The saved pose's quaternion is written in decimal: a last-bit difference.
    EXPECT_LT(largestDifference(loaded.readPixels().rgba, added.rgba), 1e-6f);

    live.removeObject(0);
    live.render();
    loaded.removeObject(0);
    loaded.render();
    EXPECT_LT(largestDifference(live.readPixels().rgba, loaded.readPixels().rgba), 1e-6f);
    Engine bare({.width = 40, .height = 30, .validation = true});
    bare.setWorld(floorGrid());
    bare.setAo({.method = "off"});
    bare.setCamera(view);
    bare.render();
    EXPECT_EQ(bare.readPixels().rgba, empty.rgba) << "a world never given objects renders as one emptied";
    EXPECT_EQ(live.validationMessages() + loaded.validationMessages() + bare.validationMessages(), 0);
}

// A world's path plays through the engine with its timed edits: caves' "carve"
// digs at 0.15 s into what the camera looks at, so the pick at the centre reaches
// further after it.
TEST(EngineGame, APathPlaysWithItsEdits) {
    Engine engine({.width = 32, .height = 18, .validation = true});
    engine.loadWorld(test::worldsDir() / "caves.json");
    EXPECT_THROW(engine.renderPath(0.0), Error) << "no path is playing";
    EXPECT_THROW(engine.playPath("nowhere"), Error);
    engine.playPath("carve");
    EXPECT_DOUBLE_EQ(engine.pathDuration(), 2.0);
    engine.renderPath(0.1);
    engine.setCamera({.position = {36, 38, -30}, .target = {33.5, 36, -4.5}, .fovDegrees = 65});
    const std::optional<Hit> before = engine.pick(16, 9);
    engine.renderPath(0.2);
    const std::optional<Hit> after = engine.pick(16, 9);
    ASSERT_TRUE(before);
    EXPECT_TRUE(!after || after->distance > before->distance + 2.0) << "the sphere of radius 5 is dug";
    EXPECT_EQ(engine.validationMessages(), 0);
}

// Frames in flight are the frames render() waits for: three submitted without
// waiting, with an edit between them, read back as the same pixels.
TEST(EngineGame, SubmittedFramesAreRenderedFrames) {
    auto run = [](bool inFlight) {
        Engine engine({.width = 40, .height = 30, .validation = true});
        engine.setWorld(floorGrid());
        engine.addObject(crate());
        engine.setCamera({.position = {14.0, 8.0, 15.0}, .target = {8.0, 3.0, 8.0}, .fovDegrees = 55.0});
        uint64_t last = 0;
        for (int i = 0; i < 3; ++i) {
            if (i == 1) engine.edit(Edit::carveBox({{9, 1, 9}, {12, 1, 12}}));
            engine.setObjectPose(0, {8.0 + 0.5 * i, 2.0, 8.0});
            const RenderedFrame f = inFlight ? engine.submit() : engine.render();
            EXPECT_GT(f.timelineValue, last) << "each frame signals a later value";
            last = f.timelineValue;
        }
        EXPECT_EQ(engine.validationMessages(), 0);
        return engine.readPixels();
    };
    const Pixels waited = run(false), submitted = run(true);
    EXPECT_EQ(submitted.rgba, waited.rgba);
    EXPECT_EQ(submitted.ao, waited.ao);
}

}  // namespace
}  // namespace grotto
