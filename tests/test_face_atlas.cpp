// The face cache read through its atlas (engine/scene/face_atlas.h), with
// validation on:
//  - on every shipped world, the frame read through the atlas is the frame read
//    through the chain of look-ups, pixel for pixel, within 1/255 of the colour
//    (the taps are the same texels: seamless wherever the chain was, at quad
//    borders; coarser levels of detail, which have no regions, read by the chain);
//  - an atlas no storage buffer holds is not made: the frame reads the chain;
//  - after random carves and fills, the atlas laid out chunk by chunk (regions
//    kept, moved or freed) reads as one laid out afresh for the edited world, and
//    its regions never overlap.
#include "engine/renderer.h"
#include "engine/scene/face_atlas.h"
#include "engine/scene/face_cache_gpu.h"
#include "engine/scene/live_face_cache.h"
#include "engine/scene/live_scene.h"
#include "shaders/shared/face_trace.h"
#include "tests/gpu_fixture.h"
#include "tests/scenes.h"
#include "tests/test_util.h"

#include <cstdlib>
#include <filesystem>
#include <random>

namespace grotto {
namespace {

using FaceAtlas = test::GpuTest;

// A cheap bake: the read's equality does not depend on the rays, only on the texels.
voxel::FaceBakeSettings atlasTestSettings(const voxel::World& world) {
    voxel::FaceBakeSettings s = worldBakeSettings(world, 2.0 * world.voxelSize());
    s.rays = 1, s.sunRays = 1, s.day = std::nullopt;
    return s;
}

AoOptions atlasTestAo(const voxel::World& world) {
    AoOptions ao = aoOptionsFor(world.desc().ao, world.voxelSize(), "test");
    ao.method = AoMethod::Cache;
    return ao;
}

// The colour of a frame `renderer` draws, read through the atlas or, with `chain`,
// through the chain (the plan reads the switch each frame). `lodBias`: coarser
// levels of detail where a cell covers up to that many pixels, whose quads have no
// region (the chain's pass shades them after the atlas's).
std::vector<float> atlasTestColour(Renderer& renderer, const Camera& camera, bool chain, double lodBias = 1.0) {
    if (chain) setenv("GROTTO_CACHE_READ", "chain", 1);
    renderer.setCulling({.lodBias = lodBias, .occlusion = true});
    renderer.render(camera);
    unsetenv("GROTTO_CACHE_READ");
    EXPECT_EQ(renderer.plan().faceAtlas, !chain);
    return renderer.readback(camera, false).color;
}

// The largest difference between two colours, relative to the brighter (at least 1).
double atlasTestDifference(const std::vector<float>& a, const std::vector<float>& b) {
    double worst = 0.0;
    for (size_t i = 0; i < a.size(); ++i)
        worst = std::max(worst, std::abs(double(a[i]) - b[i]) / std::max({1.0, double(a[i]), double(b[i])}));
    return worst;
}

// Rolling ground with pillars, over two chunks' width and far from the origin.
voxel::World atlasTestWorld() {
    return test::makeVoxelWorld(
        {-20, 0, -20}, {44, 14, 44},
        [](int x, int y, int z) { return y <= 2 + (x * 7 + z * 3) % 4 / 3 || (x % 9 == 0 && z % 7 == 0 && y < 10); }, 1.0,
        glm::dvec3(512.0, 0.0, -2048.0));
}

TEST_F(FaceAtlas, EveryShippedWorldReadsThroughItAsThroughTheChain) {
    const uint32_t w = 96, h = 54;
    size_t worlds = 0;
    for (const auto& entry : std::filesystem::directory_iterator(test::worldsDir())) {
        // The worlds (not their camera paths, which name no grid).
        if (entry.path().extension() != ".json" || test::fileBytes(entry.path()).find("\"grid\"") == std::string::npos) continue;
        // Under the sanitizers two worlds: each costs a bake and the frames.
        const std::string stem = entry.path().stem().string();
        if (test::underSanitizers(0, 1) && stem != "rooms" && stem != "thin") continue;
        SCOPED_TRACE(entry.path().filename().string());
        const voxel::World world = voxel::World::load(entry.path());
        LiveScene scene(ctx(), voxel::World(world));
        const voxel::FaceBakeSettings settings = atlasTestSettings(world);
        // A world whose atlas one storage buffer cannot hold (city's on lavapipe)
        // is read through the chain (AnAtlasNoStorageBufferHoldsIsNotMade): its
        // bake is not spent here.
        scene.gpu().layFaceAtlas(settings.texelsPerSide);
        if (scene.gpu().faceAtlasLayout()->capacity() * sizeof(glm::uvec2) > ctx().properties.limits.maxStorageBufferRange)
            continue;
        scene.bakeFaceCache(settings);
        ASSERT_TRUE(scene.gpu().faceAtlasCurrent());
        const Camera camera = makeCamera(world.camera("", double(w) / h), w, h);
        Renderer renderer(ctx(), scene.gpu(), world.desc().lighting, atlasTestAo(world), w, h);
        for (double lodBias : {1.0, 4.0}) {
            const std::vector<float> atlas = atlasTestColour(renderer, camera, false, lodBias);
            const std::vector<float> chain = atlasTestColour(renderer, camera, true, lodBias);
            EXPECT_LE(atlasTestDifference(atlas, chain), 1.0 / 255.0) << "lod bias " << lodBias;
        }
        ++worlds;
    }
    EXPECT_GE(worlds, size_t(test::underSanitizers(6, 1)));
}

// Where one storage buffer cannot hold the atlas (a device's limit, which the test
// lowers under the atlas's size), it is not made and the frame reads through the
// chain, as it does when asked to.
TEST_F(FaceAtlas, AnAtlasNoStorageBufferHoldsIsNotMade) {
    const voxel::World world = atlasTestWorld();
    LiveScene scene(ctx(), voxel::World(world));
    const voxel::FaceBakeSettings settings = atlasTestSettings(world);
    scene.gpu().layFaceAtlas(settings.texelsPerSide);
    uint32_t& limit = ctx().properties.limits.maxStorageBufferRange;
    const uint32_t deviceLimit = limit;
    limit = uint32_t(scene.gpu().faceAtlasLayout()->capacity() * sizeof(glm::uvec2) - 1);
    scene.bakeFaceCache(settings);
    limit = deviceLimit;
    EXPECT_FALSE(scene.gpu().faceAtlasCurrent());
    EXPECT_EQ(scene.gpu().faceAtlasBytes(), 0u);
    const uint32_t w = 96, h = 54;
    const glm::dvec3 o = world.origin();
    const Camera camera = makeCamera(test::lookAt(o + glm::dvec3(-6.0, 16.0, -6.0), o + glm::dvec3(12.0, 2.0, 12.0), 70.0), w, h);
    Renderer renderer(ctx(), scene.gpu(), world.desc().lighting, atlasTestAo(world), w, h);
    renderer.setCulling({.lodBias = 1.0, .occlusion = true});
    renderer.render(camera);
    EXPECT_FALSE(renderer.plan().faceAtlas);
    const std::vector<float> unmade = renderer.readback(camera, false).color;
    EXPECT_EQ(unmade, atlasTestColour(renderer, camera, true));
}

TEST_F(FaceAtlas, AfterRandomEditsItReadsAsOneLaidOutAfresh) {
    voxel::World world = atlasTestWorld();
    LiveScene edited(ctx(), voxel::World(world));
    const voxel::FaceBakeSettings settings = atlasTestSettings(world);
    edited.bakeFaceCache(settings);
    std::mt19937 random(7);
    std::uniform_int_distribution<int> along(-18, 40), up(0, 12), size(0, 5);
    for (int e = 0; e < 24; ++e) {
        const glm::ivec3 a(along(random), up(random), along(random));
        const IndexBox box{a, a + glm::ivec3(size(random), size(random), size(random))};
        if (e % 3 == 2)
            edited.apply(voxel::Edit::fillBox(box, 1));
        else
            edited.apply(voxel::Edit::carveBox(box));
    }
    EXPECT_FALSE(edited.gpu().faceAtlasCurrent()) << "the edits' faces are the GPU tracer's until traced";
    edited.bakeFaceCache(settings);  // every face converged again: the atlas filled in its edited layout
    ASSERT_TRUE(edited.gpu().faceAtlasCurrent());

    // No two regions share a cell, and each lies within its chunk's range.
    const FaceAtlasLayout& layout = *edited.gpu().faceAtlasLayout();
    std::vector<std::pair<uint64_t, uint64_t>> ranges;
    for (const GpuChunk& c : edited.gpu().chunks) {
        const FaceAtlasLayout::Chunk* placed = layout.find(c.index);
        ASSERT_NE(placed, nullptr);
        ASSERT_EQ(placed->regions.size(), c.atlasBoxes.size());
        for (size_t q = 0; q < c.atlasBoxes.size(); ++q) {
            const uint64_t cells = atlasRegionCells(unpackAtlasBox(c.atlasBoxes[q]), layout.texelsPerSide());
            EXPECT_GE(placed->regions[q], placed->first);
            EXPECT_LE(placed->regions[q] + cells, placed->first + placed->cells);
            ranges.emplace_back(placed->regions[q], cells);
        }
    }
    std::sort(ranges.begin(), ranges.end());
    for (size_t i = 1; i < ranges.size(); ++i) EXPECT_LE(ranges[i - 1].first + ranges[i - 1].second, ranges[i].first);

    LiveScene fresh(ctx(), voxel::World(edited.world()));
    fresh.bakeFaceCache(settings);
    // Within a sixteenth and the chunks' spare room of a fresh layout: what edits leave free is reused.
    EXPECT_LE(layout.capacity(), 2 * fresh.gpu().faceAtlasLayout()->capacity());
    const uint32_t w = 128, h = 72;
    Renderer onEdited(ctx(), edited.gpu(), world.desc().lighting, atlasTestAo(world), w, h);
    Renderer onFresh(ctx(), fresh.gpu(), world.desc().lighting, atlasTestAo(world), w, h);
    const glm::dvec3 o = world.origin();
    for (const glm::dvec3& eye : {glm::dvec3(-6.0, 16.0, -6.0), glm::dvec3(30.0, 9.0, 40.0)}) {
        const Camera camera = makeCamera(test::lookAt(o + eye, o + glm::dvec3(12.0, 2.0, 12.0), 70.0), w, h);
        const std::vector<float> incremental = atlasTestColour(onEdited, camera, false);
        EXPECT_EQ(incremental, atlasTestColour(onFresh, camera, false));
        EXPECT_LE(atlasTestDifference(incremental, atlasTestColour(onEdited, camera, true)), 1.0 / 255.0);
    }
}

// A carve out of view: its faces are traced in the frames that find nothing in
// view to trace (the tracer's backlog), those never traced since first. Once none
// of those is left the atlas is filled again between frames and read, while the
// faces whose sky light alone moved converge; once they have, it is filled again
// and reads, where the carve is, as the chain reads.
TEST_F(FaceAtlas, AfterACarveOutOfViewTheTracerCatchesItUp) {
    const voxel::World world = atlasTestWorld();
    LiveScene scene(ctx(), voxel::World(world));
    scene.bakeFaceCache(atlasTestSettings(world));
    const glm::dvec3 o = world.origin();
    const uint32_t w = 96, h = 54;
    const Camera away = makeCamera(test::lookAt(o + glm::dvec3(30.0, 9.0, 40.0), o + glm::dvec3(44.0, 2.0, 44.0), 60.0), w, h);
    const Camera there = makeCamera(test::lookAt(o + glm::dvec3(2.0, 10.0, 4.0), o + glm::dvec3(-10.0, 2.0, -10.0), 70.0), w, h);
    AoOptions ao = atlasTestAo(world);
    // A backlog's window of about 500 faces a frame (a quarter of the budget, each
    // face 9 texels of 2 rays): the faces reached take a few dozen frames.
    ao.chain.cacheRays = GROTTO_FACE_BACKLOG_SHARE * 500 * 18;
    Renderer renderer(ctx(), scene.gpu(), world.desc().lighting, ao, w, h);
    renderer.render(away, 0);
    scene.apply(voxel::Edit::carveSphere(o + glm::dvec3(-10.0, 2.5, -10.0), 3.0));
    ASSERT_FALSE(scene.gpu().faceAtlasCurrent());
    LiveFaceCache& cache = *scene.faceCache();
    const size_t reached = cache.unconverged();
    ASSERT_GT(reached, 2000u);
    bool outOfView = false;          // a frame found nothing in view to trace, with faces left
    size_t fills = 0, readWhileSkyLeft = 0;  // the atlas's, and frames read through it with faces left
    uint32_t frame = 1;
    for (; frame < 96; ++frame) {
        if (scene.catchUpFaceAtlas()) {
            ++fills;
            if (cache.unconverged() == 0) break;
            // None left never traced since the carve: the frames read through the atlas.
            EXPECT_EQ(std::count_if(cache.levels().begin(), cache.levels().end(), [](uint8_t l) { return l < 2; }), 0);
        }
        renderer.render(away, frame);
        readWhileSkyLeft += renderer.plan().faceAtlas && cache.unconverged() > 0;
        const std::vector<uint32_t> header = scene.gpu().faceCache()->lastHeader();
        outOfView |= header[GROTTO_FACE_ASKED] == 0 && header[GROTTO_FACE_UNCONVERGED] > 0;
    }
    std::printf("%zu faces reached; filled %zu times, the last after %u frames; %zu frames read it with faces left\n",
                reached, fills, frame, readWhileSkyLeft);
    EXPECT_TRUE(outOfView);
    EXPECT_EQ(fills, 2u);
    EXPECT_GT(readWhileSkyLeft, 5u);
    ASSERT_TRUE(scene.gpu().faceAtlasCurrent());
    EXPECT_EQ(cache.unconverged(), 0u);
    EXPECT_FALSE(scene.catchUpFaceAtlas());  // nothing left to wait for
    const std::vector<float> atlas = atlasTestColour(renderer, there, false);
    EXPECT_LE(atlasTestDifference(atlas, atlasTestColour(renderer, there, true)), 1.0 / 255.0);
}

}  // namespace
}  // namespace grotto
