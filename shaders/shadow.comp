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

// The history pixel's full-res position of a view-space point under a camera's
// ndcToViewMul_Add.
vec2 pixelOf(vec3 v, vec4 m) { return (v.xy / -v.z - m.zw) / m.xy - 0.5; }

// The pixel's accumulated visibility and its history length, or (0, 0) without a
// usable history. Bilinear between the four history pixels around where the
// surface point was, each only if it saw the same face on the same plane: the
// nearest pixel alone would, under sub-pixel motion, keep handing each pixel its
// own history and smear the penumbra along the motion.
vec2 history(ivec2 q, vec3 position, vec3 worldNormal, uint key, bool nearObject) {
    if ((trace.shadowReset & 1u) != 0u || (nearObject && (trace.shadowReset & 2u) != 0u)) return vec2(0.0);
    vec3 previous = (trace.currentToPrevious * vec4(position, 1.0)).xyz;
    float previousDepth = -previous.z;
    if (previousDepth <= 0.0) return vec2(0.0);
    // The motion as a difference of two identical computations: a still camera maps
    // every pixel exactly onto itself.
    vec4 m = trace.previousNdcToViewMul_Add;
    vec2 uv = vec2(q) + (pixelOf(previous, m) - pixelOf(position, trace.ndcToViewMul_Add));
    vec3 viewNormal = vec3(dot(trace.viewToWorld[0].xyz, worldNormal), dot(trace.viewToWorld[1].xyz, worldNormal),
                           dot(trace.viewToWorld[2].xyz, worldNormal));
    vec3 previousNormal = mat3(trace.currentToPrevious) * viewNormal;
    vec2 base = floor(uv), f = uv - base;
    uvec2 size = uvec2(imageSize(historyIn));
    vec3 sum = vec3(0.0);  // weighted visibility, length, weight
    for (int j = 0; j < 2; ++j)
        for (int i = 0; i < 2; ++i) {
            ivec2 t = ivec2(base) + ivec2(i, j);
            float w = (i == 0 ? 1.0 - f.x : f.x) * (j == 0 ? 1.0 - f.y : f.y);
            if (w <= 0.0 || any(greaterThanEqual(uvec2(t), size))) continue;
            vec4 h = imageLoad(historyIn, t);
            vec3 tap = vec3(((vec2(t) + 0.5) * m.xy + m.zw) * h.z, -h.z);
            if (uint(h.w) != key || abs(dot(tap - previous, previousNormal)) > 1e-3 * previousDepth) continue;
            sum += vec3(h.x, h.y, 1.0) * w;
        }
    return sum.z > 1e-3 ? sum.xy / sum.z : vec2(0.0);
}
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
    vec3 normal = objects.worldNormals[key - 1u].xyz;
    bool world = surfaceObject(surface) == 0u;
    if (world) {  // an axis: exact
        uint face = surfaceFace(surface);
        normal = vec3(0.0);
        normal[faceAxis(face)] = facePositive(face) ? 1.0 : -1.0;
    }
    float z = trace.depthAB.y / (texelFetch(depthBuffer, q, 0).r + trace.depthAB.x);
    vec2 m = (vec2(q) + 0.5) * trace.ndcToViewMul_Add.xy + trace.ndcToViewMul_Add.zw;
    vec3 position = vec3(m * z, -z);
#ifdef GROTTO_SOFT_SUN
    sun = coneDirection(sun, trace.sunCosRadius, gtaoNoise(uvec2(q), trace.frameIndex));
#endif
    float lit = 0.0;
    VoxelRayStart start = traceStart(position, world ? surfaceFace(surface) : 6u, normal);
    if (dot(normal, sun) > 0.0) {
        bool blocked = world && objectsOnlyOnWorld ? traceObjects(start, sun, kVoxelRayNever) >= 0.0
                                                   : traceHit(start, sun, kVoxelRayNever, !world).t >= 0.0;
        lit = blocked ? 0.0 : 1.0;
    }
    float frames = 1.0;
#ifdef GROTTO_SOFT_SUN
    // Moving objects' pixels restart, and so do the pixels whose sun the objects may shade.
    bool restart = !world || traceNearObjects(start, trace.sunDirection.xyz, sqrt(1.0 / (trace.sunCosRadius * trace.sunCosRadius) - 1.0));
    vec2 h = history(q, position, normal, key, restart);
    if (h.y > 0.0) {
        frames = min(h.y + 1.0, float(max(trace.shadowHistory, 1u)));
        lit = mix(h.x, lit, 1.0 / frames);
    }
#endif
    store(q, lit, frames, z, key);
}
