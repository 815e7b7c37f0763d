// The game-facing engine (<grotto/grotto.h>), headless with the validation layer on.
#include "engine/ao_settings.h"
#include "engine/camera.h"
#include "engine/lab/reference_view.h"
#include "tests/display_checks.h"
#include "tests/test_util.h"
#include "voxel/brick_table.h"
#include "voxel/face_bake.h"
#include "voxel/face_cache_file.h"

#include <grotto/grotto.h>

#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>

namespace grotto {
namespace {

const voxel::Edit kDig = voxel::Edit::carveBox({{12, 0, 0}, {15, 4, 2}});  // through the wall rooms/dig faces
const voxel::CameraDesc kView{.position = {18, 6, 15}, .target = {15, 3.5, 2.5}, .fovDegrees = 60};

Pixels renderOnce(Engine& engine) {
    engine.render();
    return engine.readPixels();
}

// An edit between two frames shows in the next one exactly as if the world had
// been loaded edited: only the touched chunks were re-meshed and re-uploaded.
TEST(EngineApi, AnEditShowsInTheNextFrameAsAWorldLoadedEdited) {
    const voxel::AoDesc noAo{.method = "off"};  // colour without temporal history: comparable bit for bit
    Engine live({.width = 160, .height = 90, .validation = true});
    live.loadWorld(test::worldsDir() / "rooms.json");
    live.setAo(noAo);
    live.setCamera(kView);
    const Pixels before = renderOnce(live);
    const voxel::EditResult dug = live.edit(kDig);
    EXPECT_EQ(dug.changed, 4u * 5u * 3u);
    const Pixels after = renderOnce(live);

    const test::ScratchDir dir;
    voxel::World edited = voxel::World::load(test::worldsDir() / "rooms.json");
    edited.apply(kDig);
    edited.save(dir / "dug.json");
    Engine fresh({.width = 160, .height = 90, .validation = true});
    fresh.loadWorld(dir / "dug.json");
    fresh.setAo(noAo);
    fresh.setCamera(kView);
    EXPECT_EQ(after.rgba, renderOnce(fresh).rgba);
    EXPECT_NE(after.rgba, before.rgba) << "the hole is in view";

    live.undo();
    EXPECT_EQ(renderOnce(live).rgba, before.rgba) << "undone, the wall is whole again";
    EXPECT_EQ(live.validationMessages(), 0);
    EXPECT_EQ(fresh.validationMessages(), 0);
}

// A saved world reloads as the same world: a fresh engine loading the saved file
// renders what the engine that saved it renders (edits, objects, lighting and AO
// settings as set, the world's cameras).
TEST(EngineApi, ASavedWorldRendersAsTheEngineThatSavedIt) {
    const test::ScratchDir dir;
    Engine live({.width = 48, .height = 27, .validation = true});
    live.loadWorld(test::worldsDir() / "yard.json");
    live.edit(kDig);
    voxel::Lighting evening = live.lighting();
    evening.sunDirection = glm::normalize(glm::vec3(-0.8f, 0.3f, 0.2f));
    evening.sunColor = {1.0f, 0.6f, 0.3f};
    evening.exposure = 0.9f;
    live.setLighting(evening);
    live.setAo({.method = "gtao", .quality = "medium", .radius = 2.0});
    live.setTime(0.7);
    live.saveWorld(dir / "yard-dug.json");

    Engine fresh({.width = 48, .height = 27, .validation = true});
    fresh.loadWorld(dir / "yard-dug.json");
    ASSERT_EQ(fresh.objectCount(), live.objectCount());
    fresh.setTime(0.7);
    const Pixels saved = renderOnce(fresh), shown = renderOnce(live);
    EXPECT_EQ(saved.rgba, shown.rgba);
    EXPECT_EQ(saved.ao, shown.ao);
    EXPECT_EQ(live.validationMessages(), 0);
    EXPECT_EQ(fresh.validationMessages(), 0);
}

// Size, lighting and AO change between frames without a new engine or a reload.
TEST(EngineApi, SettingsChangeInPlace) {
    Engine engine({.width = 64, .height = 48, .validation = true});
    engine.loadWorld(test::worldsDir() / "rooms.json");
    engine.setCamera(kView);
    Pixels p = renderOnce(engine);
    EXPECT_EQ(p.width, 64u);
    engine.resize(33, 17);
    p = renderOnce(engine);
    EXPECT_EQ(p.width, 33u);
    EXPECT_EQ(p.rgba.size(), 33u * 17u * 4u);
    voxel::Lighting dark = engine.lighting();
    dark.sunIntensity = 0.0f;
    dark.ambientIntensity = 0.0f;
    const Pixels lit = p;
    engine.setLighting(dark);
    p = renderOnce(engine);
    double litSum = 0.0, darkSum = 0.0;
    for (size_t i = 0; i < p.rgba.size(); ++i) litSum += lit.rgba[i], darkSum += p.rgba[i];
    EXPECT_LT(darkSum, 0.8 * litSum) << "without sun and ambient only the sky is left";
    // The time of day: midnight's sun lights nothing and its sky is dark. The
    // engine keeps the lighting as set (the day and its hour), not as in effect.
    voxel::Lighting midnight = dark;
    midnight.sunIntensity = 1.0f, midnight.ambientIntensity = 0.7f;
    midnight.sunFrom = voxel::SunSource::Day, midnight.timeOfDay = 0.0f;
    engine.setLighting(midnight);
    EXPECT_EQ(engine.lighting().sunFrom, voxel::SunSource::Day);
    EXPECT_EQ(engine.lighting().timeOfDay, 0.0f);
    p = renderOnce(engine);
    double litRgb = 0.0, nightRgb = 0.0;
    for (size_t i = 0; i < p.rgba.size(); ++i)
        if (i % 4 != 3) litRgb += lit.rgba[i], nightRgb += p.rgba[i];
    EXPECT_LT(nightRgb, 0.05 * litRgb);
    engine.setAo({.method = "gtao", .quality = "low"});
    const RenderedFrame frame = engine.render();
    EXPECT_EQ(frame.ao.extent.width, 17u) << "AO at half resolution, rounded up";
    EXPECT_EQ(frame.color.extent.width, 33u);
    EXPECT_EQ(engine.validationMessages(), 0);
}

// The colour a game gets is scene-linear (above 1 under a bright sun), its
// display image the same frame through the tone map, and saveFrame writes the
// first as an EXR and the second as a PNG.
TEST(EngineApi, ColourIsSceneLinearAndDisplayItsToneMap) {
    const test::ScratchDir dir;
    Engine engine({.width = 40, .height = 24, .validation = true});
    engine.loadWorld(test::worldsDir() / "rooms.json");
    engine.setCamera(kView);
    voxel::Lighting bright = engine.lighting();
    bright.sunIntensity = 4.0f;
    bright.exposure = 1.0f;
    engine.setLighting(bright);
    const RenderedFrame frame = engine.render();
    EXPECT_EQ(frame.color.format, VK_FORMAT_R32G32B32A32_SFLOAT);
    EXPECT_EQ(frame.display.format, VK_FORMAT_R16G16B16A16_SFLOAT);
    EXPECT_EQ(frame.display.extent.width, 40u);
    EXPECT_EQ(frame.display.extent.height, 24u);
    const Pixels p = engine.readPixels();
    engine.saveFrame(dir / "f.exr");
    engine.saveFrame(dir / "f.png");
    const test::ExrAgainstPng r = test::compareExrWithPng(dir / "f.exr", dir / "f.png");
    test::expectSceneLinear(r, "saveFrame");
    EXPECT_EQ(r.brightest, *std::max_element(p.rgba.begin(), p.rgba.end())) << "readPixels holds the EXR's colour";
    EXPECT_EQ(engine.validationMessages(), 0);
}

// The reference's cache keys on the edits: an edited world is traced afresh, its own
// result cached apart from the file's.
TEST(EngineApi, ReferenceCacheTellsAnEditedWorldFromItsFile) {
    const test::ScratchDir cache;
    setenv("GROTTO_CACHE_DIR", cache.path.c_str(), 1);
    voxel::World world = voxel::World::load(test::worldsDir() / "rooms.json");
    const Camera camera = makeCamera(kView, 48, 27);
    const ReferenceView file = referenceView(world, camera, 4.0, 16);
    EXPECT_TRUE(referenceView(world, camera, 4.0, 16).cacheHit);
    world.apply(kDig);
    const ReferenceView dug = referenceView(world, camera, 4.0, 16);
    EXPECT_FALSE(dug.cacheHit);
    EXPECT_NE(dug.ao, file.ao) << "the hole is in view";
    EXPECT_TRUE(referenceView(world, camera, 4.0, 16).cacheHit);
    unsetenv("GROTTO_CACHE_DIR");
}

// ao.method "cache" reads a bake loaded with loadBake: AO per pixel, on after an
// edit, validation silent; a bake of other voxels is refused naming the file.
TEST(EngineApi, LoadsAWorldsBakeAndRefusesAnotherWorlds) {
    const test::ScratchDir dir;
    const voxel::World world = voxel::World::load(test::worldsDir() / "rooms.json");
    const double radius = aoOptionsFor(world.desc().ao, world.voxelSize(), "test").estimator.radius;
    auto writeBake = [&](const voxel::World& w, const std::filesystem::path& file) {
        const voxel::BrickTable table(w);
        const std::vector<voxel::ExposedFace> faces = voxel::exposedFaces(table, w);
        voxel::FaceCacheFile cache{.header = {.key = voxel::faceCacheKey(w, radius, 2), .rays = 8, .sunRays = 1,
                                              .totalFaces = faces.size(), .faceCount = faces.size()}};
        cache.texels.resize(cache.header.texelCount());
        voxel::bakeFaces(table, w, faces,
                         {.radius = radius, .texelsPerSide = 2, .rays = 8, .sunRays = 1,
                          .sunDirection = glm::dvec3(w.desc().lighting.sunDirection)},
                         cache.texels);
        voxel::saveFaceCache(cache, file);
    };
    writeBake(world, dir.path / "rooms.gfc");
    voxel::World dug = voxel::World::load(test::worldsDir() / "rooms.json");
    dug.apply(kDig);
    writeBake(dug, dir.path / "dug.gfc");

    Engine engine({.width = 48, .height = 32, .validation = true});
    engine.loadWorld(test::worldsDir() / "rooms.json");
    engine.setCamera(kView);
    try {
        engine.loadBake(dir.path / "dug.gfc");
        ADD_FAILURE() << "another world's bake was loaded";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("dug.gfc"), std::string::npos) << e.what();
    }
    engine.loadBake(dir.path / "rooms.gfc");
    engine.setAo({.method = "cache"});
    const RenderedFrame frame = engine.render();
    EXPECT_EQ(frame.ao.extent.width, 1u) << "the AO lives on the faces";
    Pixels p = engine.readPixels();
    size_t occluded = 0;
    for (float a : p.ao) occluded += a < 0.7f;
    EXPECT_GT(occluded, p.ao.size() / 50);
    engine.edit(kDig);  // the cache follows the edit
    p = renderOnce(engine);
    EXPECT_EQ(p.ao.size(), 48u * 32u);
    EXPECT_EQ(engine.validationMessages(), 0);
}

// A game's engine never waits for a bake: with full light the world's light is
// baked on a thread of the engine's, and the frames after it has finished have it.
TEST(EngineApi, FullLightWithoutABakeLightsASealedRoomOnceItsThreadHasBakedIt) {
    const glm::ivec3 size(10, 6, 8), lamp(3, 2, 4);
    VoxelGrid grid{.size = size, .materials = std::vector<uint8_t>(size_t(size.x) * size.y * size.z, 0)};
    for (int z = 0; z < size.z; ++z)
        for (int y = 0; y < size.y; ++y)
            for (int x = 0; x < size.x; ++x) {
                const bool wall = x == 0 || y == 0 || z == 0 || x == size.x - 1 || y == size.y - 1 || z == size.z - 1;
                grid.materials[(size_t(z) * size.y + y) * size.x + x] = glm::ivec3(x, y, z) == lamp ? 2 : wall ? 1 : 0;
            }
    Material stone, glow;
    stone.albedo = glm::vec3(0.5f);
    glow.emissionColor = glm::vec3(1.0f, 0.8f, 0.6f), glow.emissionIntensity = 4.0f;
    Engine engine({.width = 48, .height = 32, .validation = true});
    engine.setWorld(grid, {stone, glow});
    Lighting lighting = engine.lighting();
    lighting.ambientFrom = AmbientSource::Full;
    engine.setLighting(lighting);
    engine.setAo({.method = "cache"});
    engine.setCamera({.position = {8.5, 4.5, 1.5}, .target = {3.0, 1.0, 5.0}, .fovDegrees = 80});
    engine.render();
    engine.waitForLight();
    EXPECT_EQ(engine.lightBaked(), 1.0);
    const Pixels p = renderOnce(engine);
    size_t surfaces = 0, dark = 0;
    for (size_t i = 0; i < p.depth.size(); ++i) {
        if (!std::isfinite(p.depth[i])) continue;
        ++surfaces;
        dark += p.rgba[4 * i] + p.rgba[4 * i + 1] + p.rgba[4 * i + 2] < 1e-3f;
    }
    EXPECT_EQ(surfaces, p.depth.size()) << "the camera is inside";
    EXPECT_EQ(dark, 0u) << "every wall has the lamp's light, straight or bounced";
    EXPECT_EQ(engine.validationMessages(), 0);
}

TEST(EngineApi, MisuseIsRefusedWithAClearError) {
    Engine engine({.width = 32, .height = 32, .validation = true});
    EXPECT_THROW(engine.render(), Error);
    EXPECT_THROW(engine.edit(kDig), Error);
    EXPECT_THROW(engine.readPixels(), Error);
    EXPECT_THROW(engine.resize(0, 10), Error);
    engine.loadWorld(test::worldsDir() / "rooms.json");
    EXPECT_THROW(engine.setObjectPose(0, glm::dvec3(0.0)), Error) << "rooms has no objects";
    EXPECT_THROW(engine.edit(voxel::Edit::fillBox({{0, 0, 0}, {1, 1, 1}}, 99)), Error) << "no material 99";
    EXPECT_THROW(engine.setAo({.quality = "extreme"}), Error);
    EXPECT_NO_THROW(engine.render());
}

}  // namespace
}  // namespace grotto
