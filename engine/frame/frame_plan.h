#pragma once
// What a frame does, worked out once: from the settings, the lighting, what the
// scene has and what the caller asked for. Which passes run and what each one's
// pipeline is made from (each pass's runs() and key(), pass_set.h), which render
// targets exist (frame_targets.h), the memory estimate (render_memory.h) and the
// commands' own checks all read these decisions; nothing decides them again.
#include "engine/ao_settings.h"
#include "voxel/daylight.h"
#include "voxel/world_desc.h"

#include <vulkan/vulkan.h>

#include <cstdint>
#include <optional>

namespace grotto {

// What the scene has, as far as a frame cares.
struct SceneFacts {
    bool occupancy = false;  // the world's voxels for rays (a scene uploaded from a mesh alone has none)
    // The light cached on the world's faces, by the sun it was baked with; none without a cache.
    struct CacheSun {
        glm::vec3 direction{0.0f, 1.0f, 0.0f};
        float angleDegrees = 0.0f;
        std::optional<voxel::SunPath> day;  // baked for the day's sun along this path instead
        bool fullLight = false;  // its light words hold full light, not the sky's weights
        bool dayLight = false;   // with full light over the day: each face's words for the sun's positions
    };
    std::optional<CacheSun> faceCache;
    bool faceAtlas = false;      // with it, its atlas is current (engine/scene/face_atlas.h)
    bool objects = false;        // the caller's objects (drawn, even an empty list that may grow)
    bool movingObjects = false;  // some of them move
};

// What the caller asked the frame for besides its colour.
struct FrameRequest {
    bool display = false;  // the tone-mapped display image (Renderer::setDisplayImage)
    bool normals = false;  // the world-space normals image (Renderer::setNormalsImage)
    bool aoAov = false;    // read-backs with AOVs: the full-resolution AO they upsample into
};

struct FramePlan {
    uint32_t width = 0, height = 0;
    AoOptions ao;
    SceneFacts scene;  // what the scene had: the renderer asks this, not the scene
    // What the caller asked for.
    bool display = false, normals = false, aoAov = false;
    // The AO.
    bool chain = false;        // a screen-space AO chain (estimator, denoise, maybe temporal) at AO resolution
    bool temporal = false;     // the chain's temporal pass, with its history
    bool faceCache = false;    // --ao cache: the composite reads the face cache instead of a chain
    bool cacheTracing = false; // the GPU traces the cache's texels in view not converged yet
    bool bentNormals = false;  // VBAO finds bent normals in every frame: the sky's ambient is lit around them
    // The sun.
    bool shadows = false;        // sun shadows: the lighting asks for them and the scene has occupancy
    bool shadowHistory = false;  // with them, a sun of finite size: the soft shadow's history target exists
    bool cachedSun = false;      // with them, the face cache's sun is the frame's: it gives the world's shadows
    bool tracedShadows = false;  // the shadow pass: sun shadows the cache does not give (objects', a moved sun)
    bool softShadows = false;    // traced with jittered rays accumulated in a history
    bool shadowEdges = false;    // exact sun rays on the cache's shadow edges
    bool daySun = false;         // with the cache's sun, the day's: its positions' disagreements sweep
                                 // areas as the sun rises and sets, so the edge list holds every pixel
    // How the composite reads the cache's light words. Each is a pipeline of its
    // own: a CPU device runs a branch any pixel of a group takes, and a branch on
    // a uniform too, so what a frame does not read would cost it all the same.
    bool cacheFullLight = false;  // full light (the world's ambient not a constant colour, the cache's words full light)
    bool cacheDayLight = false;   // with it, over the day: the sky's weights and the faces' bounce words
    // The composite reads the cache through its atlas (the G-buffer writes each
    // pixel's quad record): the atlas is current and holds what the frame reads
    // (not the day's sun bits nor the day's words).
    bool faceAtlas = false;
    // Objects.
    bool objects = false;
    bool movingObjects = false;
    bool motion = false;        // motion vectors: moving objects with the temporal pass
    bool objectLight = false;   // objects' AO and sky light over the face cache, with a history
    bool objectRays = false;    // some pass traces rays that see the objects: their grids are uploaded
    bool surfaceHistory = false;  // the full-resolution histories (soft shadows, objects' light) advance

    VkExtent2D frame() const { return {width, height}; }
    VkExtent2D aoExtent() const;  // the AO chain's resolution: the frame's, or half of it rounded up
};

// The ambient light a frame draws: the world's choice, but full light only where
// the face cache holds it; without the cache (another AO method, or none) the
// sky's light on each surface, times that method's AO.
voxel::AmbientSource ambientSource(const voxel::Lighting& lighting, const AoOptions& ao);

FramePlan planFrame(uint32_t width, uint32_t height, const AoOptions& ao, const voxel::Lighting& lighting,
                    const SceneFacts& scene, const FrameRequest& request = {});

// A world's frames at a size as the commands render them: from a scene uploaded
// from the world (so with occupancy), a face cache baked under its own sun, and
// its objects when `objects`.
FramePlan planWorldFrame(const voxel::WorldDesc& desc, uint32_t width, uint32_t height, const AoOptions& ao,
                         bool objects = true, const FrameRequest& request = {});

}  // namespace grotto
