#version 460
#extension GL_GOOGLE_include_directive : require
// Sun shadows at full resolution: one exact ray per pixel from its surface point
// toward the sun through the world's voxels (trace.glsl: the exact traversal the
// CPU's World::raycast shares), until it leaves the world's bounds. Writes 1 where
// the sun reaches the point, 0 where a voxel blocks it or the face turns away from
// the sun; 1 for the sky.
//
// Built a second time as soft_shadow.comp (GROTTO_SOFT_SUN) for a sun of finite
// size: each pixel's ray takes a direction drawn uniformly from the sun's disc (its
// cone of angular radius acos(trace.sunCosRadius)), a new one every frame, and the
// result is averaged into a full-res history, so the penumbra converges over the
// frames as the AO does. The history is carried to each pixel from where its
// surface point was in the history's view, from the pixels there that saw the same
// face on the same plane; without one the pixel starts afresh. While objects move,
// their own pixels start afresh every frame, and so do those whose rays toward the
// sun's disc pass near an object, so a moving shadow leaves no trail.
//
// Objects' voxels block the rays as the world's do. With the face cache's sun
// (objectsOnlyOnWorld), a world surface's rays test the objects alone: the cache
// holds the world's own shadow, which the composite multiplies by this.
#include "shared/noise.h"
#include "shared/objects.h"
#include "shared/quad.h"
#include "shared/trace.h"

layout(constant_id = 0) const bool objectsOnlyOnWorld = false;
layout(local_size_x = GROTTO_TRACE_GROUP, local_size_y = GROTTO_TRACE_GROUP) in;
layout(set = 0, binding = 0) uniform sampler2D depthBuffer;   // full-res D32, reverse-Z
layout(set = 0, binding = 1) uniform usampler2D surfaceTex;   // full-res surface ids
layout(set = 0, binding = 2, std140) uniform Objects { ObjectUniforms objects; };  // object faces' normals
layout(set = 0, binding = 3, r32f) uniform writeonly image2D shadowOut;
#ifdef GROTTO_SOFT_SUN
// Visibility, frames of history, view depth, surface key (0 = sky).
layout(set = 0, binding = 4, rgba32f) uniform readonly image2D historyIn;
layout(set = 0, binding = 5, rgba32f) uniform writeonly image2D historyOut;
#define GROTTO_TRACE_BINDING 6
#else
#define GROTTO_TRACE_BINDING 4
#endif
#define GROTTO_TRACE_OBJECTS
#include "trace.glsl"
#include "surface_point.glsl"

void store(ivec2 q, float lit, float frames, float depth, uint key) {
    imageStore(shadowOut, q, vec4(lit));
#ifdef GROTTO_SOFT_SUN
    imageStore(historyOut, q, vec4(lit, frames, depth, float(key)));
#endif
}

#ifdef GROTTO_SOFT_SUN
// A direction drawn uniformly from the cone of half-angle acos(cosRadius) around
// `axis`, from the point `u` of the unit square.
vec3 coneDirection(vec3 axis, float cosRadius, vec2 u) {
    float cosT = 1.0 - u.x * (1.0 - cosRadius), sinT = sqrt(max(1.0 - cosT * cosT, 0.0));
    float phi = 6.28318530718 * u.y;
    vec3 t = normalize(cross(abs(axis.y) < 0.9 ? vec3(0.0, 1.0, 0.0) : vec3(1.0, 0.0, 0.0), axis));
    vec3 b = cross(axis, t);
    return normalize(axis * cosT + (t * cos(phi) + b * sin(phi)) * sinT);
}

ivec2 historySize() { return imageSize(historyIn); }
vec4 historyTap(ivec2 t, out float depth, out uint key) {
    vec4 h = imageLoad(historyIn, t);
    depth = h.z;
    key = uint(h.w);
    return h;
}
#include "surface_history.glsl"
#endif

void main() {
    ivec2 q = ivec2(gl_GlobalInvocationID.xy);
    ivec2 size = imageSize(shadowOut);
    if (any(greaterThanEqual(q, size))) return;
    uint surface = texelFetch(surfaceTex, q, 0).r;
    if (surface == 0u) {
        store(q, 1.0, 0.0, 0.0, 0u);
        return;
    }
    vec3 sun = trace.sunDirection.xyz;
    uint key = surfaceKey(surface);
    vec3 normal = surfaceWorldNormal(surface);
    bool world = surfaceObject(surface) == 0u;
    vec3 position = surfaceViewPosition(q);
#ifdef GROTTO_SOFT_SUN
    sun = coneDirection(sun, trace.sunCosRadius, gtaoNoise(uvec2(q), trace.frameIndex));
#endif
    float lit = 0.0;
    VoxelRayStart start = surfaceRayStart(position, surface, normal);
    if (dot(normal, sun) > 0.0) {
        bool blocked = world && objectsOnlyOnWorld ? traceObjects(start, sun, kVoxelRayNever) >= 0.0
                                                   : traceHit(start, sun, kVoxelRayNever, !world).t >= 0.0;
        lit = blocked ? 0.0 : 1.0;
    }
    float frames = 1.0;
#ifdef GROTTO_SOFT_SUN
    // Moving objects' pixels restart, and so do the pixels whose sun the objects may shade.
    bool restart = (trace.shadowReset & 1u) != 0u ||
                   ((trace.shadowReset & 2u) != 0u &&
                    (!world || traceNearObjects(start, trace.sunDirection.xyz,
                                                sqrt(1.0 / (trace.sunCosRadius * trace.sunCosRadius) - 1.0))));
    bool found = false;
    vec4 h = restart ? vec4(0.0) : surfaceHistory(q, position, normal, key, found);
    if (found && h.y > 0.0) {
        frames = min(h.y + 1.0, float(max(trace.shadowHistory, 1u)));
        lit = mix(h.x, lit, 1.0 / frames);
    }
#endif
    store(q, lit, frames, -position.z, key);
}
