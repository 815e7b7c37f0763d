#include "engine/frame/frame_plan.h"

#include "grotto/error.h"
#include "voxel/daylight.h"

#include <algorithm>

namespace grotto {
namespace {

// The cache's sun is the lighting's (as given, not yet in effect): the day's
// along the same path, or the same direction and size.
bool sameSun(const SceneFacts::CacheSun& baked, const voxel::Lighting& given) {
    if (baked.day)
        return given.sunFrom == voxel::SunSource::Day && *baked.day == voxel::sunPathOf(given) && baked.angleDegrees == given.sunAngle;
    const voxel::Lighting lighting = voxel::lightingInEffect(given);
    return glm::length(glm::normalize(baked.direction) - glm::normalize(lighting.sunDirection)) < 1e-6f &&
           baked.angleDegrees == lighting.sunAngle;
}

}  // namespace

VkExtent2D FramePlan::aoExtent() const {
    return ao.chain.fullResolution ? frame() : VkExtent2D{(width + 1) / 2, (height + 1) / 2};
}

voxel::AmbientSource ambientSource(const voxel::Lighting& lighting, const AoOptions& ao) {
    const bool full = lighting.ambientFrom == voxel::AmbientSource::Full;
    return full && !faceCached(ao) ? voxel::AmbientSource::Sky : lighting.ambientFrom;
}

FramePlan planFrame(uint32_t width, uint32_t height, const AoOptions& ao, const voxel::Lighting& lighting,
                    const SceneFacts& scene, const FrameRequest& request) {
    FramePlan p{.width = width, .height = height, .ao = ao, .scene = scene,
                .display = request.display, .normals = request.normals, .aoAov = request.aoAov};
    p.chain = aoChain(ao);
    p.temporal = p.chain && ao.chain.temporalHistory > 0;
    p.faceCache = faceCached(ao);
    p.cacheTracing = p.faceCache && scene.occupancy && scene.faceCache;
    p.bentNormals = ao.enabled && ao.method == AoMethod::Vbao && ambientSource(lighting, ao) == voxel::AmbientSource::Sky;

    p.objects = scene.objects;
    p.movingObjects = scene.objects && scene.movingObjects;
    p.motion = p.movingObjects && p.temporal;
    p.objectLight = p.faceCache && p.objects;

    p.shadows = lighting.sunShadows && scene.occupancy;
    p.shadowHistory = p.shadows && lighting.sunAngle > 0.0f;
    p.cachedSun = p.shadows && p.faceCache && scene.faceCache && sameSun(*scene.faceCache, lighting);
    p.tracedShadows = p.shadows && (!p.cachedSun || p.objects);
    p.softShadows = p.tracedShadows && lighting.sunAngle > 0.0f;
    p.shadowEdges = p.cachedSun;
    p.daySun = p.cachedSun && scene.faceCache->day;
    p.cacheFullLight = p.faceCache && scene.faceCache && scene.faceCache->fullLight &&
                       ambientSource(lighting, ao) != voxel::AmbientSource::Color;
    p.cacheDayLight = p.cacheFullLight && scene.faceCache->dayLight && scene.faceCache->day;
    p.faceAtlas = p.faceCache && scene.faceCache && scene.faceAtlas && !p.daySun && !p.cacheDayLight;

    p.objectRays = p.tracedShadows || p.objectLight || (p.chain && tracesVoxels(ao.method));
    p.surfaceHistory = p.softShadows || p.objectLight;
    return p;
}

FramePlan planWorldFrame(const voxel::WorldDesc& desc, uint32_t width, uint32_t height, const AoOptions& ao,
                         bool objects, const FrameRequest& request) {
    SceneFacts scene{.occupancy = true};
    const voxel::Lighting light = voxel::lightingInEffect(desc.lighting);
    if (faceCached(ao)) {
        // The bake the world's lighting asks for: full light where its ambient is.
        const bool day = desc.lighting.sunFrom == voxel::SunSource::Day;
        const bool full = desc.lighting.ambientFrom == voxel::AmbientSource::Full;
        scene.faceCache = SceneFacts::CacheSun{light.sunDirection, light.sunAngle,
                                               day ? std::optional(voxel::sunPathOf(desc.lighting)) : std::nullopt, full,
                                               full && day};
    }
    scene.objects = objects && !desc.objects.empty();
    scene.movingObjects = scene.objects && std::any_of(desc.objects.begin(), desc.objects.end(), [](const auto& o) { return o.moves(); });
    return planFrame(width, height, ao, desc.lighting, scene, request);
}

}  // namespace grotto
