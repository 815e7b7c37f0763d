// Occlusion culling and levels of detail in the G-buffer:
//  - culling is conservative: on every frame of every shipped path, the G-buffer
//    with culling equals the one without, bit for bit (depth and surface ids);
//  - coarse levels open no holes: where the exact voxels show a surface, the
//    coarse ones do too, and never behind it;
//  - the reference AO is traced from the exact voxels even where the default
//    bias draws coarse chunks;
//  - the level choice and the tile test on their own.
#include "engine/camera_path.h"
#include "engine/frame/chunk_culling.h"
#include "engine/lab/reference_view.h"
#include "engine/renderer.h"
#include "engine/lab/surface_points.h"
#include "tests/gpu_fixture.h"
#include "tests/scenes.h"
#include "tests/test_util.h"
#include "voxel/solid.h"

#include <cstring>

namespace grotto {
namespace {

using test::GpuTest;

AoOptions noAo() {
    AoOptions ao;
    ao.estimator = estimatorPreset("high", 1.0);
    ao.enabled = false;
    return ao;
}

voxel::Lighting noShadows(voxel::Lighting l) {
    l.sunShadows = false;  // the G-buffer is what is compared
    return l;
}

size_t differingPixels(const FrameImages& a, const FrameImages& b) {
    size_t n = 0;
    for (size_t i = 0; i < a.surfaceIds.size(); ++i)
        n += a.surfaceIds[i] != b.surfaceIds[i] || std::memcmp(&a.depthBuffer[i], &b.depthBuffer[i], 4) != 0;
    return n;
}

class Culling : public GpuTest, public ::testing::WithParamInterface<const char*> {};

TEST_P(Culling, NeverHidesWhatTheFrameShowsOnAnyFrameOfTheShippedPaths) {
    const voxel::World world = voxel::World::load(test::worldsDir() / (std::string(GetParam()) + ".json"));
    auto scene = uploadScene(ctx(), world);
    constexpr uint32_t w = 128, h = 72;
    const voxel::Lighting lighting = noShadows(world.desc().lighting);
    Renderer culled(ctx(), *scene, lighting, noAo(), w, h), all(ctx(), *scene, lighting, noAo(), w, h);
    culled.setCulling({.lodBias = 0.0, .occlusion = true});
    all.setCulling({.lodBias = 0.0, .occlusion = false});
    ASSERT_FALSE(world.desc().paths.empty());
    // The culled renderer draws every frame (its first phase is what the frame
    // before showed). Under the sanitizers the frames are at 12 fps, twice the step
    // between them (more is uncovered from one to the next), and the unculled
    // renderer draws, and the two are compared, on every 2nd only.
    const int fps = test::underSanitizers(24, 12), compareEvery = test::underSanitizers(1, 2);
    uint64_t hidden = 0, frames = 0;
    for (const auto& [name, desc] : world.desc().paths) {
        const CameraPath path(desc, world.camera("", double(w) / h));
        const int count = int(path.frameCount(fps));  // every frame, as flythrough renders them at 24 fps
        for (int i = 0; i < count; ++i) {
            const double t = i / double(fps);
            const Camera camera = path.camera(t, w, h);
            if (i > 0 && path.cutBetween((i - 1) / double(fps), t)) culled.resetHistory();
            const FrameStats stats = culled.render(camera, uint32_t(i));
            hidden += stats.culling.clustersHidden;
            ++frames;
            if (i % compareEvery != 0) continue;
            all.render(camera, uint32_t(i));
            ASSERT_EQ(differingPixels(culled.readback(camera, true), all.readback(camera, true)), 0u)
                << name << " frame " << i + 1;
        }
    }
    // The test means something only where culling hid clusters.
    if (std::string(GetParam()) == "caves") EXPECT_GT(hidden, 10 * frames) << "clusters hidden per frame";
}

INSTANTIATE_TEST_SUITE_P(ShippedWorlds, Culling, ::testing::Values("rooms", "caves", "thin", "yard"));

class LevelsOfDetail : public GpuTest {};

TEST_F(LevelsOfDetail, CoarseChunksOpenNoHolesAndNeverLieBehindTheVoxels) {
    const voxel::World world = voxel::World::load(test::worldsDir() / "caves.json");
    auto scene = uploadScene(ctx(), world);
    constexpr uint32_t w = 320, h = 180;
    const voxel::Lighting lighting = noShadows(world.desc().lighting);
    Renderer coarse(ctx(), *scene, lighting, noAo(), w, h), exact(ctx(), *scene, lighting, noAo(), w, h);
    // A bias large enough that chunks at every distance take every level, so
    // chunks of different levels meet along many borders.
    coarse.setCulling({.lodBias = 12.0, .occlusion = true});
    exact.setCulling({.lodBias = 0.0, .occlusion = false});
    std::array<uint32_t, 4> levels{};
    for (const char* name : {"overview", "walk"}) {
        const Camera camera = worldCamera(world, name, w, h);
        const FrameStats stats = coarse.render(camera, 0);
        exact.render(camera, 0);
        for (int level = 0; level <= 3; ++level) levels[level] += stats.culling.chunksAtLevel[level];
        const FrameImages c = coarse.readback(camera, true), e = exact.readback(camera, true);
        size_t holes = 0, behind = 0, surface = 0, changed = 0;
        for (size_t i = 0; i < e.depthBuffer.size(); ++i) {
            if (e.surfaceIds[i] == 0) continue;
            ++surface;
            holes += c.surfaceIds[i] == 0;
            // Reverse-Z: a coarse surface grows outward, so it is nearer (larger) or equal.
            behind += c.surfaceIds[i] != 0 && c.depthBuffer[i] < e.depthBuffer[i] * (1.0f - 1e-6f);
            changed += c.depthBuffer[i] != e.depthBuffer[i];
        }
        // A coarse silhouette edge may coincide with the exact one, drawn by other
        // triangles: a pixel centre on it may fall to either side by rounding (seen:
        // one far pixel of the overview). More than one in 10^4 would be a real hole.
        const size_t rounding = 1 + surface / 10000;
        EXPECT_LE(holes, rounding) << name << ": sky seen through coarse chunks";
        EXPECT_LE(behind, rounding) << name << ": coarse surfaces behind the exact ones";
        EXPECT_GT(changed, surface / 20) << name << ": the coarse levels must be drawn";
    }
    for (int level = 1; level <= 3; ++level) EXPECT_GT(levels[level], 0u) << "no chunk drawn at level " << level;
}

TEST_F(LevelsOfDetail, TheReferenceIsTracedFromTheExactVoxels) {
    // Columns one or two voxels tall in a checkerboard, seen from so far that the
    // default bias (1) draws them from coarse cells: the reference must still be
    // the one traced from the exact G-buffer's points, bit for bit.
    const voxel::World world =
        test::makeVoxelWorld({0, 0, 0}, {63, 1, 63}, [](int x, int y, int z) { return y <= (x + z) % 2; });
    const Camera camera = makeCamera(test::lookAt({160, 100, 160}, {32, 0, 32}, 40.0), 96, 54);
    auto scene = uploadScene(ctx(), world);
    const voxel::Lighting lighting = noShadows(world.desc().lighting);
    Renderer coarse(ctx(), *scene, lighting, noAo(), 96, 54), exact(ctx(), *scene, lighting, noAo(), 96, 54);
    coarse.setCulling({.lodBias = voxel::Detail{}.lodBias, .occlusion = true});
    exact.setCulling({.lodBias = 0.0, .occlusion = false});
    const FrameStats stats = coarse.render(camera);
    exact.render(camera);
    ASSERT_EQ(stats.culling.chunksAtLevel[0], 0u) << "the default bias must draw this view coarse";
    const FrameImages e = exact.readback(camera, true);
    ASSERT_GT(differingPixels(coarse.readback(camera, true), e), 0u);

    const SurfacePoints sp = surfacePoints(e, camera, world.voxelSize(), world.origin());
    const voxel::ReferenceAo traced = voxel::referenceAo(world, sp.points, sp.normals, {.radius = 4.0, .spp = 16});
    const ReferenceView ref = referenceView(world, camera, 4.0, 16, &ctx());  // built in memory: never cached
    size_t surface = 0, differing = 0;
    for (uint8_t s : ref.surface) surface += s;
    ASSERT_EQ(surface, sp.pixels.size());
    for (size_t k = 0; k < sp.pixels.size(); ++k)
        differing += !ref.surface[sp.pixels[k]] || ref.ao[sp.pixels[k]] != traced.visibility[k];
    EXPECT_EQ(differing, 0u) << "of " << sp.pixels.size() << " surface pixels";
}

TEST(LevelChoice, FollowsTheBiasWithHysteresis) {
    // A cell of 2^L voxels of 0.3 px each: level 1 is 0.6 px, level 2 1.2 px.
    EXPECT_EQ(chooseLevel(0.3, 0.0, -1, 4), 0);  // bias 0: exact everywhere
    EXPECT_EQ(chooseLevel(0.3, 1.0, -1, 4), 1);
    EXPECT_EQ(chooseLevel(0.3, 1.0, -1, 1), 0);  // a chunk without coarse levels
    EXPECT_EQ(chooseLevel(0.1, 1.0, -1, 4), 3);  // 0.8 px at level 3, and no level 4
    // Going coarser waits until the coarser cell is a quarter below the bias...
    EXPECT_EQ(chooseLevel(0.45, 1.0, 0, 4), 0);  // level 1 would be 0.9 px > 1 / 1.25
    EXPECT_EQ(chooseLevel(0.35, 1.0, 0, 4), 1);  // 0.7 px
    // ... going finer does not wait.
    EXPECT_EQ(chooseLevel(0.45, 1.0, 1, 4), 1);  // 0.9 px: stays
    EXPECT_EQ(chooseLevel(0.55, 1.0, 1, 4), 0);  // 1.1 px: finer at once
    EXPECT_EQ(chooseLevel(2.0, 1.0, 3, 4), 0);
}

TEST(DepthTileTest, HidesOnlyBoxesBehindEveryTileTheyCover) {
    Camera camera;
    camera.width = 64, camera.height = 64;
    camera.fovY = glm::radians(90.0);
    const glm::dmat4 viewProj = camera.viewProjRelativeDouble();
    // A wall at view depth 10 over the whole image: depth near / 10 (reverse-Z, infinite far).
    const float wall = float(camera.nearPlane / 10.0);
    std::vector<float> tiles(8 * 8, wall);
    DepthTiles t{64, 64, 8, 8, tiles};
    const glm::vec3 behindLo(-1, -1, -21), behindHi(1, 1, -19), frontLo(-1, -1, -6), frontHi(1, 1, -4);
    EXPECT_TRUE(hiddenBehind(t, viewProj, behindLo, behindHi));
    EXPECT_FALSE(hiddenBehind(t, viewProj, frontLo, frontHi));
    EXPECT_FALSE(hiddenBehind(t, viewProj, glm::vec3(-1, -1, -11), glm::vec3(1, 1, -9.9f)));  // straddles the wall
    EXPECT_FALSE(hiddenBehind(t, viewProj, glm::vec3(-1, -1, 1), glm::vec3(1, 1, 3)));        // behind the camera
    // One tile of sky (depth 0) under the box: not hidden.
    tiles[size_t(4) * 8 + 4] = 0.0f;
    EXPECT_FALSE(hiddenBehind(t, viewProj, behindLo, behindHi));
    // A box elsewhere on screen does not see that tile.
    EXPECT_TRUE(hiddenBehind(t, viewProj, glm::vec3(-15, -15, -21), glm::vec3(-13, -13, -19)));
}

}  // namespace
}  // namespace grotto
