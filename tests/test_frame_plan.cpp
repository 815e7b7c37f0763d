// The frame plan's decisions on their own (engine/frame/frame_plan.h): which
// passes run and what they are made from, from settings, lighting, the scene and
// the caller's request. No device: the plan is plain values.
#include "engine/frame/frame_passes.h"
#include "engine/frame/frame_plan.h"

#include <gtest/gtest.h>

namespace grotto {
namespace {

AoOptions method(const char* name) {
    voxel::AoDesc desc;
    desc.method = name;
    return aoOptionsFor(desc, 1.0, "test");
}

SceneFacts world() { return {.occupancy = true}; }

// A scene with a face cache baked under `lighting`'s sun.
SceneFacts cached(const voxel::Lighting& lighting, bool objects = false) {
    SceneFacts s = world();
    s.faceCache = SceneFacts::CacheSun{lighting.sunDirection, lighting.sunAngle};
    s.objects = objects;
    return s;
}

TEST(FramePlan, SunShadowsNeedTheScenesOccupancy) {
    const voxel::Lighting lighting;
    ASSERT_TRUE(lighting.sunShadows);
    const FramePlan mesh = planFrame(8, 8, method("gtao"), lighting, SceneFacts{});
    EXPECT_FALSE(mesh.shadows);
    EXPECT_FALSE(mesh.tracedShadows);
    EXPECT_FALSE(ShadowPass::runs(mesh));
    const FramePlan voxels = planFrame(8, 8, method("gtao"), lighting, world());
    EXPECT_TRUE(voxels.shadows && voxels.tracedShadows && ShadowPass::runs(voxels));
    EXPECT_FALSE(voxels.shadowHistory);  // a point sun: hard shadows, no history
}

TEST(FramePlan, TheCachesOwnSunGivesTheWorldsShadowsAndItsEdges) {
    voxel::Lighting lighting;
    const FramePlan plan = planFrame(8, 8, method("cache"), lighting, cached(lighting));
    EXPECT_TRUE(plan.cachedSun && plan.shadowEdges && ShadowEdgePass::runs(plan));
    EXPECT_FALSE(plan.tracedShadows);  // no objects: the cache has every shadow
    EXPECT_FALSE(plan.chain);
    EXPECT_TRUE(plan.cacheTracing && FaceCacheTracePass::runs(plan) && AskingCompositePass::runs(plan));
    // Objects' shadows on the world are traced, over the cache's sun.
    const FramePlan objects = planFrame(8, 8, method("cache"), lighting, cached(lighting, true));
    EXPECT_TRUE(objects.cachedSun && objects.tracedShadows && objects.objectLight);
    // A sun moved since the bake: traced everywhere, no edges.
    const SceneFacts bakedBefore = cached(lighting);
    lighting.sunDirection = glm::normalize(glm::vec3(1.0f, 1.0f, 0.0f));
    const FramePlan moved = planFrame(8, 8, method("cache"), lighting, bakedBefore);
    EXPECT_FALSE(moved.cachedSun || moved.shadowEdges);
    EXPECT_TRUE(moved.tracedShadows);
    EXPECT_NE(ShadowPass::key(objects), ShadowPass::key(moved));
    EXPECT_NE(CompositePass::key(plan), CompositePass::key(moved));
}

// How the composite reads the cache's light words is the plan's, and each way is
// a composite of its own: full light where the cache holds it and the ambient is
// not a constant colour, its day words only with the day's sun.
TEST(FramePlan, TheCachesLightWordsPickTheCompositesRead) {
    voxel::Lighting lighting;
    lighting.ambientFrom = voxel::AmbientSource::Full;
    SceneFacts skyCache = cached(lighting);
    const FramePlan sky = planFrame(8, 8, method("cache"), lighting, skyCache);
    EXPECT_FALSE(sky.cacheFullLight || sky.cacheDayLight);  // a sky-light bake keeps the sky's weights
    SceneFacts fullCache = skyCache;
    fullCache.faceCache->fullLight = true;
    fullCache.faceCache->dayLight = true;  // words for a day, but baked for one sun
    const FramePlan full = planFrame(8, 8, method("cache"), lighting, fullCache);
    EXPECT_TRUE(full.cacheFullLight);
    EXPECT_FALSE(full.cacheDayLight);
    EXPECT_NE(CompositePass::key(sky), CompositePass::key(full));
    SceneFacts dayCache = fullCache;
    dayCache.faceCache->day = voxel::sunPathOf(lighting);
    const FramePlan day = planFrame(8, 8, method("cache"), lighting, dayCache);
    EXPECT_TRUE(day.cacheFullLight && day.cacheDayLight);
    EXPECT_NE(CompositePass::key(full), CompositePass::key(day));
    // A constant ambient colour reads no light words; nor does a frame without the cache.
    voxel::Lighting colour = lighting;
    colour.ambientFrom = voxel::AmbientSource::Color;
    EXPECT_FALSE(planFrame(8, 8, method("cache"), colour, dayCache).cacheFullLight);
    EXPECT_FALSE(planFrame(8, 8, method("gtao"), lighting, dayCache).cacheFullLight);
}

TEST(FramePlan, ASoftSunKeepsAHistoryWhereItIsTraced) {
    voxel::Lighting lighting;
    lighting.sunAngle = 1.0f;
    const FramePlan traced = planFrame(8, 8, method("gtao"), lighting, world());
    EXPECT_TRUE(traced.shadowHistory && traced.softShadows && traced.surfaceHistory);
    const FramePlan byCache = planFrame(8, 8, method("cache"), lighting, cached(lighting));
    EXPECT_TRUE(byCache.shadowHistory);  // its target, as the memory estimate counts it
    EXPECT_FALSE(byCache.softShadows || byCache.surfaceHistory);
}

TEST(FramePlan, MotionVectorsOnlyForMovingObjectsWithTheTemporalPass) {
    SceneFacts moving = world();
    moving.objects = moving.movingObjects = true;
    AoOptions ao = method("gtao");
    const FramePlan temporal = planFrame(8, 8, ao, voxel::Lighting{}, moving);
    EXPECT_TRUE(temporal.temporal && temporal.motion);
    EXPECT_EQ(std::get<0>(GBufferPass::key(temporal)), GBufferMode::Motion);
    ao.chain.temporalHistory = 0;
    const FramePlan still = planFrame(8, 8, ao, voxel::Lighting{}, moving);
    EXPECT_FALSE(still.temporal || still.motion || TemporalPass::runs(still));
    EXPECT_EQ(std::get<0>(GBufferPass::key(still)), GBufferMode::Objects);
    EXPECT_EQ(std::get<0>(GBufferPass::key(planFrame(8, 8, ao, voxel::Lighting{}, world()))), GBufferMode::World);
}

TEST(FramePlan, BentNormalsForVbaoUnderTheSkyAndForReadBacksOtherwise) {
    voxel::Lighting sky;
    sky.ambientFrom = voxel::AmbientSource::Sky;
    const FramePlan lit = planFrame(8, 8, method("vbao"), sky, world());
    EXPECT_TRUE(lit.bentNormals);
    EXPECT_FALSE(BentNormalsPass::runs(planFrame(8, 8, method("vbao"), sky, world(), {.aoAov = true})));
    const FramePlan colour = planFrame(8, 8, method("vbao"), voxel::Lighting{}, world());
    EXPECT_FALSE(colour.bentNormals);
    EXPECT_NE(EstimatorPass::key(lit), EstimatorPass::key(colour));  // its specialisation
    EXPECT_FALSE(BentNormalsPass::runs(colour));  // only a read-back with AOVs wants them
    EXPECT_TRUE(BentNormalsPass::runs(planFrame(8, 8, method("vbao"), voxel::Lighting{}, world(), {.aoAov = true})));
    EXPECT_FALSE(planFrame(8, 8, method("gtao"), sky, world()).bentNormals);
}

TEST(FramePlan, TheEstimatorIsRemadeOnlyForWhatItIsCompiledFrom) {
    const AoOptions ssao = method("ssao");
    AoOptions wider = ssao;
    wider.estimator.radius *= 2.0;  // a uniform
    EXPECT_EQ(EstimatorPass::key(planFrame(8, 8, ssao, {}, world())), EstimatorPass::key(planFrame(8, 8, wider, {}, world())));
    AoOptions more = ssao;
    more.estimator.ssaoSamples += 4;  // its loop
    EXPECT_NE(EstimatorPass::key(planFrame(8, 8, ssao, {}, world())), EstimatorPass::key(planFrame(8, 8, more, {}, world())));
}

TEST(FramePlan, WhatTheCallerAskedForRunsItsPasses) {
    const FramePlan none = planFrame(8, 8, method("gtao"), {}, world());
    EXPECT_FALSE(DisplayPass::runs(none) || NormalsPass::runs(none) || FaceCacheAovPass::runs(none));
    const FramePlan asked = planFrame(8, 8, method("gtao"), {}, world(), {.display = true, .normals = true, .aoAov = true});
    EXPECT_TRUE(DisplayPass::runs(asked) && NormalsPass::runs(asked));
    EXPECT_FALSE(FaceCacheAovPass::runs(asked));  // the chain's AOVs need no pass of the cache's
}

TEST(FramePlan, NoAoRunsNoChain) {
    const FramePlan off = planFrame(8, 8, method("off"), {}, world());
    EXPECT_FALSE(off.chain || off.temporal || off.faceCache);
    EXPECT_FALSE(EstimatorPass::runs(off) || DepthPrefilterPass::runs(off) || DenoisePass::runs(off));
    EXPECT_TRUE(CompositePass::runs(off) && GBufferPass::runs(off));
}

TEST(FramePlan, AWorldsPlanIsTheRenderersForASceneFromThatWorld) {
    voxel::WorldDesc desc;
    desc.lighting.sunAngle = 1.0f;
    voxel::ObjectDesc box;
    box.keys = {{0.0, glm::dvec3(0.0), glm::dquat(1, 0, 0, 0)}, {1.0, glm::dvec3(1.0), glm::dquat(1, 0, 0, 0)}};
    desc.objects = {box};
    const AoOptions ao = method("cache");
    const FramePlan fromWorld = planWorldFrame(desc, 8, 8, ao);
    SceneFacts scene = cached(desc.lighting, true);
    scene.movingObjects = true;
    const FramePlan fromScene = planFrame(8, 8, ao, desc.lighting, scene);
    EXPECT_EQ(fromWorld.objectLight, fromScene.objectLight);
    EXPECT_EQ(fromWorld.cachedSun, fromScene.cachedSun);
    EXPECT_EQ(fromWorld.tracedShadows, fromScene.tracedShadows);
    EXPECT_EQ(fromWorld.movingObjects, fromScene.movingObjects);
    EXPECT_EQ(fromWorld.cacheTracing, fromScene.cacheTracing);
    EXPECT_TRUE(fromWorld.objectLight && fromWorld.tracedShadows);
    EXPECT_FALSE(planWorldFrame(desc, 8, 8, ao, false).objectLight);  // without its objects
}

}  // namespace
}  // namespace grotto
