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
//
// With the cache's full light (trace.faceCache.w) it writes light instead (rgb,
// irradiance over pi, as the cache's texels hold it), the same rays telling:
//  - On a world surface: what objects change of its light. A ray that meets an
//    object before any world face takes away what came along it (the sky's
//    light, or the light the world face beyond sends: its material's albedo
//    times its texels' light and sun, and its glow); the composite adds the
//    result, negative there, to the cache's light.
//  - On an object's face: its light outright: the sky's where a ray leaves, the
//    light a world face sends where one meets it (the cache's, as above); light
//    other objects reflect is left out (they are small).
//  - On both: the light of objects' glowing faces (trace.glow), sampled, not
//    waited for: each face's light in closed form (Lambert's polygon formula),
//    and one shadow ray a frame drawn among them by it, through the world and the
//    objects, so an unblocked lantern is exact and only its shadows are noisy
//    (and averaged over the frames). Rays that meet a glowing object take
//    nothing from its glow, so that light is not counted twice.
#include "shared/frame.h"
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
layout(set = 0, binding = 6, std140) uniform Palette { vec4 palette[GROTTO_PALETTE_VEC4S]; };
#define GROTTO_TRACE_BINDING 7
#define GROTTO_TRACE_OBJECTS
#include "trace.glsl"
#include "surface_point.glsl"
uint faceCacheTable() { return trace.faceCache.x; }
uint faceCacheK() { return trace.faceCache.y; }
#define GROTTO_FACE_CACHE_BINDING 12
#include "face_cache.glsl"

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

vec3 skyRadiance(vec3 d) {
    vec2 w = skyWeights(d);
    return w.x * trace.skyHorizon.rgb + w.y * trace.skyZenith.rgb;
}

float luminance(vec3 c) { return dot(c, vec3(0.2126, 0.7152, 0.0722)); }

// The light a world face sends at point p (voxels from the camera's voxel) where a
// ray met it: its material's albedo times the light and sun of the cache's texel
// there, and its glow. The one texel the point lies on, not the composite's four
// blended: a ray's light needs no smoothness, and each lookup costs a chain of loads.
vec3 worldFaceLight(vec3 p, VoxelRayHit hit) {
    if (hit.face < 0 || trace.faceCache.z == 0u) return vec3(0.0);
    uint dir = uint(hit.face);
    int face = faceCacheFace(hit.voxel, dir);
    if (face < 0) return vec3(0.0);
    uint material = (faceTexels[trace.faceCache.z + uint(face) / 4u] >> (8u * (uint(face) & 3u))) & 0xFFu;
    if (material == 0u) return vec3(0.0);
    uint k = trace.faceCache.y;
    vec3 local = clamp(p - vec3(hit.voxel - trace.cameraCell.xyz), 0.0, 0.999999);
    uint i = min(uint(local[faceUAxis(dir)] * float(k)), k - 1u), j = min(uint(local[faceVAxis(dir)] * float(k)), k - 1u);
    uvec2 bits = faceCacheTexel(uint(face) * k * k + j * k + i);
    // The day's sun: the texel's bits at the positions either side of the hour.
    uint texel = uint(face) * k * k + j * k + i;
    float sun = trace.daySun.x != 0u
                    ? 0.5 * float(bitCount(faceTexels[trace.daySun.x + texel] & ((1u << trace.daySun.y) | (1u << trace.daySun.z))))
                    : faceCacheUnpack(bits).y;
    float cosSun = max(dot(faceAxisNormal(dir), trace.sunDirection.xyz), 0.0);
    vec3 albedo = palette[2u * (material - 1u)].rgb, emission = palette[2u * (material - 1u) + 1u].rgb;
    vec3 light = faceCacheDecodeLight(bits.y);
    if (trace.dayLight.x != 0u)
        light += faceCacheDayLight(texel, k, trace.dayLight, trace.skyZenith.rgb, trace.skyHorizon.rgb,
                                   trace.sunRadiance.rgb);
    return albedo * (light + trace.sunRadiance.rgb * (cosSun * sun)) + emission;
}

// The share of the hemisphere about n at p a glowing face covers, cosine-weighted
// (its form factor): Lambert's formula over the face clipped to the horizon.
float glowFormFactor(vec3 p, vec3 n, GlowFace g) {
    vec3 c[4] = vec3[4](g.corner.xyz, g.corner.xyz + g.edgeU.xyz, g.corner.xyz + g.edgeU.xyz + g.edgeV.xyz,
                        g.corner.xyz + g.edgeV.xyz);
    if (dot(p - c[0], cross(g.edgeU.xyz, g.edgeV.xyz)) <= 0.0) return 0.0;  // behind it
    vec3 v[5];
    int count = 0;
    for (int i = 0; i < 4; ++i) {
        vec3 a = c[i] - p, b = c[(i + 1) & 3] - p;
        float da = dot(a, n), db = dot(b, n);
        if (da >= 0.0) v[count++] = a;
        if ((da >= 0.0) != (db >= 0.0)) v[count++] = a + (b - a) * (da / (da - db));
    }
    if (count < 3) return 0.0;
    float sum = 0.0;
    for (int i = 0; i < count; ++i) {
        vec3 a = v[i], b = v[(i + 1) % count], x = cross(a, b);
        float lx = length(x);
        if (lx > 0.0) sum += atan(lx, dot(a, b)) * dot(n, x) / lx;
    }
    return clamp(abs(sum) / 6.28318530717958648, 0.0, 1.0);
}

// The glowing faces' light at p (normal n): in closed form, with one shadow ray
// toward a point (u) of a face drawn (pick) by its share of that light.
vec3 glowLight(VoxelRayStart start, vec3 p, vec3 n, bool openStart, vec2 u, float pick) {
    uint count = min(uint(trace.objectCount.y), GROTTO_MAX_GLOW_FACES);
    float total = 0.0;
    for (uint i = 0u; i < count; ++i) total += glowFormFactor(p, n, trace.glow[i]) * luminance(trace.glow[i].radiance.rgb);
    if (total <= 0.0) return vec3(0.0);
    // The shares again rather than kept: an array of 128 per invocation would cost
    // more than a few faces' formula twice.
    float target = pick * total, below = 0.0;
    uint at = 0u;
    for (; at + 1u < count; ++at) {
        float share = glowFormFactor(p, n, trace.glow[at]) * luminance(trace.glow[at].radiance.rgb);
        if (below + share > target && share > 0.0) break;
        below += share;
    }
    GlowFace g = trace.glow[at];
    vec3 toLight = g.corner.xyz + u.x * g.edgeU.xyz + u.y * g.edgeV.xyz - p;
    float distance = length(toLight);
    vec3 d = toLight / distance;
    // Short of the face itself: its own voxel is behind it.
    if (traceHit(start, d, max(distance - 1e-3, 0.0), openStart).t >= 0.0) return vec3(0.0);
    return g.radiance.rgb * (total / luminance(g.radiance.rgb));
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
    bool full = trace.faceCache.w != 0u;
    bool seen = !world || (full && trace.objectCount.y > 0), moved = false;
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
    // With full light, half the rays on world surfaces: each that meets an object
    // costs a cache lookup beyond it (houses-night's closed room, 640x360: the pass
    // 291 ms with 8, 208 ms with 4; the history averages the rest).
    uint rays = full && world ? specRays / 2u : specRays;
    for (uint i = 0u; i < rays; ++i) {
        vec3 d = traceCosineRay(normal, noise, i);
        if (full && world) {  // the light objects take from the world's surface
            float object = traceObjects(start, d, kVoxelRayNever);
            if (object < 0.0) continue;
            VoxelRayHit wall = traceWorldHit(start, d, kVoxelRayNever, false);
            if (wall.t >= 0.0 && wall.t < object) continue;  // a world face first: the object changes nothing along d
            light -= wall.t < 0.0 ? skyRadiance(d) : worldFaceLight(p + d * wall.t, wall);
        } else if (full) {  // an object's own light
            VoxelRayHit hit = traceHit(start, d, kVoxelRayNever, true);
            light += hit.t < 0.0 ? skyRadiance(d) : worldFaceLight(p + d * hit.t, hit);
        } else if (world) {
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
    light /= float(rays);
    if (full && trace.objectCount.y > 0) {
        // Numbers of their own for the face drawn and the point on it.
        vec2 u = gtaoNoise(uvec2(q), trace.frameIndex * 3u + 1u);
        float pick = gtaoNoise(uvec2(q) + uvec2(17u, 29u), trace.frameIndex * 3u + 2u).x;
        light += glowLight(start, p, normal, !world, u, pick);
    }
    float frames = 1.0;
    bool found = false;
    vec4 h = (trace.shadowReset & 1u) != 0u || moved ? vec4(0.0) : surfaceHistory(q, position, normal, key, found);
    if (found && h.w > 0.0) {
        frames = min(h.w + 1.0, float(max(trace.shadowHistory, 1u)));
        light = mix(h.xyz, light, 1.0 / frames);
    }
    store(q, light, frames, -position.z, key);
}
