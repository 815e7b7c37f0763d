#version 460
#extension GL_GOOGLE_include_directive : require
// Objects' part in the light the face cache holds (--ao cache with objects). The
// cache knows the static world alone; each frame, at full resolution and only where
// an object is in view of a surface, cosine-weighted rays find what objects change.
//  - On a world surface: the AO the objects take (rays that meet an object within
//    R where the world has no voxel within R) and the sky light they take (rays
//    that meet an object where the world would have let them out), the latter as
//    the sky's horizon and zenith weights. The composite subtracts them from the
//    cache's, so a shut door darkens its room and an object darkens the floor
//    around it.
//  - On an object's face: its AO and sky light outright, through the world's voxels
//    and every object's.
// The same estimator and definitions as the cache's bake (voxel/face_bake.cpp), so
// the difference keeps the cache's meaning. The rays are averaged over the frames
// in a full-res history reprojected as the soft sun's (surface_history.glsl). A
// pixel in view of an object that moved since the last frame (at either pose)
// starts afresh; one in view of none, or only of objects too far and small to
// change its light by 1/512, costs a test per object and writes 0.
// Writes RGBA16F: AO (taken, or the object's own), horizon and zenith weights.
#include "shared/noise.h"
#include "shared/objects.h"
#include "shared/quad.h"
#include "shared/trace.h"

layout(constant_id = 0) const uint specRays = 8u;  // rays per pixel per frame
layout(local_size_x = GROTTO_TRACE_GROUP, local_size_y = GROTTO_TRACE_GROUP) in;
layout(set = 0, binding = 0) uniform sampler2D depthBuffer;   // full-res D32, reverse-Z
layout(set = 0, binding = 1) uniform usampler2D surfaceTex;   // full-res surface ids
layout(set = 0, binding = 2, std140) uniform Objects { ObjectUniforms objects; };  // object faces' normals
layout(set = 0, binding = 3, rgba16f) uniform writeonly image2D lightOut;
// Light (halves: AO and horizon, zenith and frames), view depth (float bits), surface key.
layout(set = 0, binding = 4, rgba32ui) uniform readonly uimage2D historyIn;
layout(set = 0, binding = 5, rgba32ui) uniform writeonly uimage2D historyOut;
#define GROTTO_TRACE_BINDING 6
#define GROTTO_TRACE_OBJECTS
#include "trace.glsl"
#include "surface_point.glsl"

ivec2 historySize() { return imageSize(historyIn); }
vec4 historyTap(ivec2 t, out float depth, out uint key) {
    uvec4 h = imageLoad(historyIn, t);
    depth = uintBitsToFloat(h.z);
    key = h.w;
    return vec4(unpackHalf2x16(h.x), unpackHalf2x16(h.y));
}
#include "surface_history.glsl"

void store(ivec2 q, vec3 light, float frames, float depth, uint key) {
    imageStore(lightOut, q, vec4(light, 0.0));
    imageStore(historyOut, q, uvec4(packHalf2x16(light.xy), packHalf2x16(vec2(light.z, frames)), floatBitsToUint(depth), key));
}

// The sky's radiance in direction d as its horizon and zenith colours' weights
// (shared/sky.h's skyRadiance; voxel::skyWeights).
vec2 skyWeights(vec3 d) {
    if (d.y < 0.0) return vec2(0.8, 0.0);
    float s = sqrt(min(d.y, 1.0));
    return vec2(1.0 - s, s);
}

bool rowsDiffer(vec4 a[3], vec4 b[3]) { return a[0] != b[0] || a[1] != b[1] || a[2] != b[2]; }

// Is part of the sphere s in front of the plane through p with normal n?
bool inView(vec4 s, vec3 p, vec3 n) { return dot(s.xyz - p, n) > -s.w; }

// Can the sphere change the light at p by a visible amount? Within R of it the AO
// may change by any amount; beyond, the sky light it takes is at most the
// cosine-weighted share of the hemisphere it covers, below (r / d)^2, and under
// 1/512 (a fifth of the cache's finest step) it is left out.
bool matters(vec4 s, vec3 p) {
    float d = length(s.xyz - p);
    return d < trace.radiusVoxels + s.w || s.w * s.w * 512.0 > d * d;
}

void main() {
    ivec2 q = ivec2(gl_GlobalInvocationID.xy);
    if (any(greaterThanEqual(q, imageSize(lightOut)))) return;
    uint surface = texelFetch(surfaceTex, q, 0).r;
    if (surface == 0u) {
        store(q, vec3(0.0), 0.0, 0.0, 0u);
        return;
    }
    uint key = surfaceKey(surface);
    vec3 normal = surfaceWorldNormal(surface);
    bool world = surfaceObject(surface) == 0u;
    vec3 position = surfaceViewPosition(q);
    VoxelRayStart start = surfaceRayStart(position, surface, normal);
    vec3 p = vec3(start.voxel - trace.cameraCell.xyz) + start.fraction;
    bool seen = !world, moved = false;
    for (int k = 0; k < trace.objectCount.x; ++k) {
        vec3 size = vec3(trace.objects[k].size.xyz);
        vec4 now = objectGridSphere(trace.objects[k].fromWorld[0], trace.objects[k].fromWorld[1],
                                    trace.objects[k].fromWorld[2], size);
        bool here = inView(now, p, normal) && matters(now, p);
        seen = seen || here;
        if (rowsDiffer(trace.objects[k].fromWorld, trace.objects[k].previousFromWorld)) {
            vec4 before = objectGridSphere(trace.objects[k].previousFromWorld[0], trace.objects[k].previousFromWorld[1],
                                           trace.objects[k].previousFromWorld[2], size);
            moved = moved || here || (inView(before, p, normal) && matters(before, p));
        }
    }
    if (!seen) {  // no object changes this pixel's light: exactly none taken
        store(q, vec3(0.0), 0.0, -position.z, key);
        return;
    }
    vec2 noise = gtaoNoise(uvec2(q), trace.frameIndex);
    vec3 light = vec3(0.0);  // AO, horizon and zenith weights: taken on the world, outright on objects
    for (uint i = 0u; i < specRays; ++i) {
        vec3 d = traceCosineRay(normal, noise, i);
        if (world) {
            float object = traceObjects(start, d, kVoxelRayNever);
            if (object < 0.0) continue;
            float wall = traceWorldHit(start, d, kVoxelRayNever, false).t;
            if (object <= trace.radiusVoxels && (wall < 0.0 || wall > trace.radiusVoxels)) light.x += 1.0;
            if (wall < 0.0) light.yz += skyWeights(d);
        } else {
            float t = traceHit(start, d, kVoxelRayNever, true).t;
            if (t < 0.0 || t > trace.radiusVoxels) light.x += 1.0;
            if (t < 0.0) light.yz += skyWeights(d);
        }
    }
    light /= float(specRays);
    float frames = 1.0;
    bool found = false;
    vec4 h = (trace.shadowReset & 1u) != 0u || moved ? vec4(0.0) : surfaceHistory(q, position, normal, key, found);
    if (found && h.w > 0.0) {
        frames = min(h.w + 1.0, float(max(trace.shadowHistory, 1u)));
        light = mix(h.xyz, light, 1.0 / frames);
    }
    store(q, light, frames, -position.z, key);
}
