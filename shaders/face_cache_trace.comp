#version 460
#extension GL_GOOGLE_include_directive : require
// The face cache's texels traced on the GPU: one invocation per texel of the faces
// face_cache_plan.comp took this frame, each tracing the texel's whole sequence of
// rays (the CPU bake's, voxel/face_bake.cpp) afresh, so a texel traced again
// continues nothing and needs no sums kept. It writes the texel's packed bits
// (shared/face_cache.h), with the day's sun its bits for each position, and its
// face's level. With full light, a texel traced here holds the sky's light alone
// until the world is baked again. A face's first look, with the coarse rays, is
// one invocation for the whole face: the face traced as one texel (the CPU bake's
// at one texel a side), its value in each of its texels. A CPU device runs 8
// invocations in step, so a quarter of the invocations is a quarter of the time,
// where fewer rays a texel would have left each lane its seed and set-up.
#include "shared/face_trace.h"
#include "shared/quad.h"
#define GROTTO_FACE_CACHE_LAYOUT_ONLY  // its texel encodings alone
#include "shared/face_cache.h"

layout(local_size_x = GROTTO_FACE_TRACE_GROUP) in;
layout(push_constant) uniform Push { FaceTraceConstants c; };
layout(set = 0, binding = 0, std430) readonly buffer Queue { uvec4 queue[]; };
layout(set = 0, binding = 1, std430) buffer Header { uint header[]; };
layout(set = 0, binding = 2, std430) buffer Levels { uint levels[]; };
layout(set = 0, binding = 3, std430) buffer FaceTexels { uint faceTexels[]; };
layout(set = 0, binding = 4, std430) readonly buffer DaySun { vec4 dayPositions[]; };  // xyz: toward the sun
#define GROTTO_TRACE_BINDING 5
#include "trace.glsl"
#include "texel_rays.glsl"

uint unorm(float v, uint bits) { return uint(round(clamp(v, 0.0, 1.0) * float((1u << bits) - 1u))); }

// The texel's light word, and its AO and sun half beside its pair's other texel's.
void storeTexel(uint texel, uint aoSun, uint light) {
    uint pair = 3u * (texel >> 1u), shift = 16u * (texel & 1u);
    faceTexels[pair + (texel & 1u)] = light;
    atomicAnd(faceTexels[pair + 2u], ~(0xFFFFu << shift));
    atomicOr(faceTexels[pair + 2u], aoSun << shift);
}

// Does a ray from `start` along d leave the world without entering a solid voxel?
bool leaves(VoxelRayStart start, vec3 d) {
    return trace.boundsHi.w != 0 || voxelRay(start, d, kVoxelRayNever, trace.boundsLo.xyz, trace.boundsHi.xyz, true, 16384).t < 0.0;
}

// Texel (i, j)'s centre (of k a side) of the face of `cell` looking `dir`, a hair
// in front of the face, in the open voxel there.
VoxelRayStart texelStart(ivec3 cell, uint dir, uint i, uint j, uint k) {
    uint axis = faceAxis(dir);
    bool positive = facePositive(dir);
    VoxelRayStart start;
    start.voxel = cell;
    start.voxel[axis] += positive ? 1 : -1;
    start.fraction[axis] = positive ? c.epsilon : 1.0 - c.epsilon;
    start.fraction[faceUAxis(dir)] = (float(i) + 0.5) / float(k);
    start.fraction[faceVAxis(dir)] = (float(j) + 0.5) / float(k);
    return start;
}

// Texel (i, j) of k a side of the face of `cell` looking `dir`, traced with `rays`
// and `sunRays`: its AO and sun half, and its light word.
uvec2 traceTexel(ivec3 cell, uint dir, uint i, uint j, uint k, uint rays, uint sunRays) {
    uint ua = faceUAxis(dir), va = faceVAxis(dir);
    VoxelRayStart start = texelStart(cell, dir, i, j, k);
    vec3 n = faceAxisNormal(dir), t1, t2;
    texelTangents(n, t1, t2);

    uvec2 h = texelSeed(cell, dir, i, j);
    vec2 shift = vec2(unitInterval(h), unitInterval(splitmix64(h)));
    uint open = 0u;
    float horizon = 0.0, zenith = 0.0;
    for (uint r = 0u; r < rays; ++r) {
        vec3 l = cosineDirection(r2(r, shift));
        vec3 d = t1 * l.x + t2 * l.y + n * l.z;
        if (traceShortWorldRay(start, d, c.radiusVoxels) >= 0.0) continue;  // within R: neither AO nor sky
        ++open;
        if (!leaves(start, d)) continue;
        if (d.y < 0.0) horizon += 0.8;  // the darker horizon below it (voxel::skyWeights)
        else {
            float s = sqrt(min(d.y, 1.0));
            horizon += 1.0 - s;
            zenith += s;
        }
    }
    uint sunOpen = 0u;
    bool pointSun = c.sun.w >= 1.0;
    vec2 sunShift = vec2(unitInterval(splitmix64(h ^ uvec2(1u, 0u))), unitInterval(splitmix64(h ^ uvec2(2u, 0u))));
    vec2 spreadShift = vec2(unitInterval(splitmix64(h ^ uvec2(3u, 0u))), unitInterval(splitmix64(h ^ uvec2(4u, 0u))));
    vec3 s1, s2;
    texelTangents(c.sun.xyz, s1, s2);
    for (uint r = 0u; r < sunRays; ++r) {
        vec3 d = c.sun.xyz;
        if (!pointSun) {
            vec3 cone = coneDirection(r2(r, sunShift), c.sun.w);
            d = s1 * cone.x + s2 * cone.y + c.sun.xyz * cone.z;
        }
        // From all over the texel's square, so a thin edge of sunlight reads part lit.
        VoxelRayStart from = start;
        vec2 a = texelSpread(r, spreadShift);
        from.fraction[ua] = (float(i) + a.x) / float(k);
        from.fraction[va] = (float(j) + a.y) / float(k);
        if (dot(d, n) > 0.0 && leaves(from, d)) ++sunOpen;
    }
    float samples = float(max(rays, 1u));
    uint aoSun = unorm(float(open) / samples, 8u) | unorm(sunRays > 0u ? float(sunOpen) / float(sunRays) : 1.0, 8u) << 8u;
    uint light = c.skyZenith.w > 0.5
                     ? faceCacheEncodeLight((horizon * c.skyHorizon.rgb + zenith * c.skyZenith.rgb) / samples)
                     : packHalf2x16(vec2(horizon, zenith) / samples);
    return uvec2(aoSun, light);
}

// The day's positions, from texel (i, j)'s centre, at every level: a sun seen
// once is seen exact, and where these bits disagree the frame traces per pixel.
void traceDaySun(ivec3 cell, uint dir, uint i, uint j, uint k, uint texel) {
    VoxelRayStart start = texelStart(cell, dir, i, j, k);
    vec3 n = faceAxisNormal(dir);
    uint bits = 0u;
    for (uint m = 0u; m < c.dayPositions; ++m) {
        vec3 d = dayPositions[m].xyz;
        if (dot(d, n) > 0.0 && leaves(start, d)) bits |= 1u << m;
    }
    faceTexels[c.daySunFirst + texel] = bits;
}

void main() {
    uint k = c.texelsPerSide, texels = k * k;
    uint empty = header[GROTTO_FACE_TRACED_EMPTY], taken = header[GROTTO_FACE_TRACED_PARTIAL];
    bool coarse = header[GROTTO_FACE_EMPTY_FULL] == 0u;
    // The first list's faces at the coarse rays take an invocation each, the rest one a texel.
    uint item = gl_GlobalInvocationID.x, wholeFaces = coarse ? empty : 0u;
    uint slot = item < wholeFaces ? item : wholeFaces + (item - wholeFaces) / texels;
    uint t = item < wholeFaces ? 0u : (item - wholeFaces) % texels;
    if (slot >= empty + taken) return;
    bool first = slot < empty, full = !first || !coarse;
    uvec4 e = first ? queue[slot] : queue[header[GROTTO_FACE_CAPACITY] + slot - empty];
    ivec3 cell = ivec3(e.xyz);
    uint dir = e.w & 7u, face = e.w >> 3u;
    if (full) {
        uint i = t % k, j = t / k;
        uvec2 bits = traceTexel(cell, dir, i, j, k, c.rays, c.sunRays);
        storeTexel(face * texels + t, bits.x, bits.y);
        if (c.dayPositions > 0u) traceDaySun(cell, dir, i, j, k, face * texels + t);
    } else {
        uvec2 bits = traceTexel(cell, dir, 0u, 0u, 1u, c.coarseRays, c.coarseSunRays);
        for (uint u = 0u; u < texels; ++u) {
            storeTexel(face * texels + u, bits.x, bits.y);
            if (c.dayPositions > 0u) traceDaySun(cell, dir, u % k, u / k, k, face * texels + u);
        }
    }
    if (t == 0u) {
        uint shiftBits = (face & 15u) * 2u;
        uint was = (atomicAnd(levels[face >> 4u], ~(3u << shiftBits)) >> shiftBits) & 3u;
        atomicOr(levels[face >> 4u], (full ? GROTTO_FACE_LEVEL_CONVERGED : 1u) << shiftBits);
        if (full) atomicAdd(header[GROTTO_FACE_UNCONVERGED], uint(-1));  // it was not, or it would not be listed
        if (full && was < 2u) atomicAdd(header[GROTTO_FACE_ROUGH], uint(-1));
    }
}
