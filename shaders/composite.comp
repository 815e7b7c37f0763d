#version 460
#extension GL_GOOGLE_include_directive : require
// Sun Lambert x shadow + ambient x AO on surfaces, plus a glowing face's emission,
// a gradient sky where nothing was drawn, all times the exposure: scene-linear
// colour, no tone map.
// With AO, one invocation per AO pixel shades its block of full-res pixels and
// upsamples the AO for them on the way (upsample.glsl): a separate upsample pass
// would store full-res AO only to load it again here.
// Built a second time as composite_cache.comp (GROTTO_FACE_CACHE) for --ao cache:
// one invocation per pixel, and a world surface's AO, sky light and sun come from
// the face cache at its exact point (face_cache_surface.glsl). The sky light there
// is the sky seen through the world, occlusion at every distance included; the AO
// adds only the light bounced between nearby surfaces (the multi-bounce fit over
// the AO), so a closed room gets no sky and open ground today's light.
#include "shared/frame.h"
#include "shared/gtao.h"
#include "shared/objects.h"
#include "shared/quad.h"

layout(constant_id = 0) const bool withAo = true;  // false: one invocation per pixel, no AO bound
layout(constant_id = 3) const bool withShadow = true;  // false: the sun reaches everything, no shadow bound
layout(constant_id = 4) const bool withBentNormals = false;  // VBAO's bent normals light the sky's ambient
layout(constant_id = 5) const bool cachedSun = false;  // cache: world surfaces take the cache's sun visibility
layout(constant_id = 6) const bool objectLight = false;  // cache: objects' AO and sky light (object_light.comp)
layout(constant_id = 7) const bool shadowEdges = false;  // the cache's sun: list its edges' pixels (shadow_edge.comp)
// Cache, while faces have not converged: ask for the faces of the texels read, for
// the next frame's tracer, and read none at level 0. A separate pipeline: a CPU
// device runs a branch's code whether or not any pixel takes it, so a bake's
// frames leave it out.
layout(constant_id = 8) const bool askFaces = false;
// Cache: how its light words are read (the frame plan's cacheFullLight,
// cacheDayLight, daySun). Constants, not the frame's uniforms: a CPU device runs
// a branch on a uniform's value whether or not any pixel takes it.
layout(constant_id = 9) const bool fullLight = false;
layout(constant_id = 10) const bool dayLight = false;
layout(constant_id = 11) const bool daySun = false;
// Cache: the texels read through the atlas (engine/scene/face_atlas.h) where the
// pixel's quad has a region: four independent loads instead of the chain of
// look-ups (FramePlan::faceAtlas: never while asking, nor with the day's words).
layout(constant_id = 12) const bool atlasRead = false;
// Cache, after the atlas's pass: the chain's read for the world pixels that pass
// listed, those whose quad has no region (a coarser level of detail), one
// invocation each (groups of 64 x 1). A pass of its own over a list, not a branch
// nor a pass over every pixel that returns early: a CPU device ran the chain's
// code for every group either way (147 and 204 ms against 74 and 91, rooms and
// caves at 1280x720).
layout(constant_id = 13) const bool withoutRegion = false;
#define GROTTO_CACHE_READS_DAY_LIGHT dayLight
#define GROTTO_CACHE_READS_DAY_SUN daySun
// The group's side, set by CompositePass: lavapipe runs 16x16 groups of single
// pixels faster, 8x8 groups of 2x2 blocks (docs/benchmarks.md).
layout(local_size_x_id = 1, local_size_y_id = 2) in;
layout(set = 0, binding = 0, std140) uniform Frame { FrameUniforms frame; };
layout(set = 0, binding = 1, std140) uniform Palette { vec4 palette[GROTTO_PALETTE_VEC4S]; };
vec4 materialOf(uint surface) { return palette[2u * (surfaceMaterial(surface) - 1u)]; }  // rgb albedo, a: material AO
vec3 emissionOf(uint surface) { return palette[2u * (surfaceMaterial(surface) - 1u) + 1u].rgb; }
layout(set = 0, binding = 2) uniform usampler2D surfaceTex;
layout(set = 0, binding = 3, rgba32f) uniform writeonly image2D outColor;
layout(set = 0, binding = 4, std140) uniform Constants { GtaoConstants gtao; };
layout(set = 0, binding = 5, rgba32f) uniform readonly image2D aoHalf;  // the AO chain's half-res output
layout(set = 0, binding = 6) uniform sampler2D depthBuffer;             // full-res D32, reverse-Z
layout(set = 0, binding = 7, std140) uniform Objects { ObjectUniforms objects; };  // object faces' normals
layout(set = 0, binding = 8, r32f) uniform readonly image2D shadowImage;  // full res: 1 = sunlit (shadow.comp)
layout(set = 0, binding = 9, rgba16f) uniform readonly image2D bentNormals;  // AO res, world space (vbao)
#ifdef GROTTO_FACE_CACHE
uint faceCacheTable() { return frame.faceCache.x; }
uint faceCacheK() { return frame.faceCache.y; }
// AO and the sky's horizon and zenith weights: those objects take from a world
// surface, an object's own on its faces.
layout(set = 0, binding = 10, rgba16f) uniform readonly image2D objectLightImage;
// The atlas: each pixel's quad record (offset, row length; 0: no region) and the
// cells (x: the AO and sun half | 1 << 16 where a face lies, y: the light word).
layout(set = 0, binding = 19) uniform usampler2D atlasRecordTex;
layout(set = 0, binding = 20, std430) readonly buffer AtlasCells { uvec2 atlasCells[]; };
// The pixels the chain's pass shades: their count, then its groups (x, y, z), then
// each pixel, x | y << 16.
layout(set = 0, binding = 21, std430) buffer ChainList { uint chainHeader[4]; uint chainPixels[]; };
#define GROTTO_FACE_CACHE_BINDING 11
#include "face_cache.glsl"
#include "shared/face_trace.h"
#include "face_cache_surface.glsl"
layout(set = 0, binding = 14, std430) buffer Edges { uint edgeHeader[GROTTO_EDGE_HEADER_WORDS]; uvec4 edges[]; };
#define GROTTO_FACE_REQUEST_BINDING 15
#include "face_cache_requests.glsl"

// Asks for the faces of texels `t` not converged (at pixel q, on faces looking
// `dir`): by one pixel of each 2x2 block a frame, in turn. The request pass asked
// for the face under each pixel before this frame's trace; a face beside the view
// is read by a strip of pixels, so it is asked for within a frame or a few.
void askForTaps(ivec2 q, FaceCacheTaps t, uint dir) {
    if (faceHeader[GROTTO_FACE_UNCONVERGED] == 0u || (uint(q.x & 1) + 2u * uint(q.y & 1)) != (uint(frame.cameraCell.w) & 3u))
        return;
    for (int c = 0; c < 4; ++c)
        if (t.weight[c] > 0.0) requestFace(t.face[c], t.cell[c], dir);
}

// The cache's light at pixel q through the atlas, from its quad's record `r`: the
// region's four cells around the point, each loaded once and unconditionally (a
// region's border cells lie inside it), blended as faceCacheBlend and
// faceCacheFullLight blend the chain's taps: missing faces reweighted away.
// A branch per cell, or a second load of each, cost lavapipe a fifth of the pass.
struct AtlasLight {
    vec4 c;         // AO, sun, horizon and zenith weights (faceCacheBlend's)
    vec2 sunRange;  // the least and the most sun visibility among the cells read
    vec3 full;      // with full light, the cells' light
    bool seen;      // some cell has a face
};
AtlasLight atlasLightAt(ivec2 q, uint dir, uvec2 r) {
    vec3 p = cachedPointAt(q, dir);
    int k = int(faceCacheK());
    uint ua = faceUAxis(dir), va = faceVAxis(dir);
    float su = p[ua] * float(k) - 0.5, sv = p[va] * float(k) - 0.5;
    float fu = floor(su), fv = floor(sv);
    float wu = su - fu, wv = sv - fv;
    int I0 = int(fu) + frame.cameraCell[ua] * k, J0 = int(fv) + frame.cameraCell[va] * k;
    uint first = r.x + uint(I0) + uint(J0) * r.y;
    vec4 sum = vec4(0.0);
    vec3 full = vec3(0.0);
    float weight = 0.0;
    vec2 range = vec2(1.0, 0.0);
    for (int c = 0; c < 4; ++c) {
        uvec2 bits = atlasCells[first + uint(c & 1) + uint(c >> 1) * r.y];
        bool there = (bits.x & 0x10000u) != 0u;
        float w = there ? ((c & 1) != 0 ? wu : 1.0 - wu) * ((c >> 1) != 0 ? wv : 1.0 - wv) : 0.0;
        vec4 v = faceCacheUnpack(uvec2(bits.x & 0xFFFFu, bits.y));
        sum += w > 0.0 ? w * v : vec4(0.0);  // a light word's halfs may be NaN under full light
        if (fullLight) full += w * faceCacheDecodeLight(bits.y);
        weight += w;
        range = w > 0.0 ? vec2(min(range.x, v.y), max(range.y, v.y)) : range;
    }
    AtlasLight a;
    a.seen = weight > 0.0;
    a.c = a.seen ? sum / weight : vec4(1.0, 1.0, 0.0, 0.0);
    a.sunRange = range;
    a.full = a.seen ? full / weight : vec3(0.0);
    return a;
}

// Lists pixel q for an exact sun ray (shadow_edge.comp): lit with sun visibility
// `used`, its sun's light at full visibility is `light` (exposed).
void listShadowEdge(ivec2 q, float used, vec3 light) {
    uint slot = atomicAdd(edgeHeader[GROTTO_EDGE_COUNT], 1u);
    if (slot >= edgeHeader[GROTTO_EDGE_CAPACITY]) return;
    edges[2u * slot] = uvec4(uint(q.x) | (uint(q.y) << 16u), floatBitsToUint(used), 0u, 0u);
    edges[2u * slot + 1u] = uvec4(floatBitsToUint(light), 0u);
}
#endif

float gtaoDepth(ivec2 texel, int mip) { return 0.0; }
uint gtaoSurface(ivec2 pixel) { return 0u; }
#include "shared/gtao_kernel.h"
#include "upsample.glsl"

// Multi-bounce fit (Jimenez et al. 2016): light bouncing between bright surfaces
// brightens what plain visibility would leave dark.
vec3 multiBounce(float v, vec3 albedo) {
    vec3 a = 2.0404 * albedo - 0.3324;
    vec3 b = -4.7951 * albedo + 0.6417;
    vec3 c = 2.7552 * albedo + 0.6903;
    return max(vec3(v), ((a * v + b) * v + c) * v);
}

vec3 sky(ivec2 pixel) {
    vec2 p = vec2(pixel) + 0.5;
    vec3 ray = frame.rayOrigin.xyz + p.x * frame.rayStepX.xyz + p.y * frame.rayStepY.xyz;
    return skyRadiance(ray.y * inversesqrt(dot(ray, ray)), frame.skyZenith.rgb, frame.skyHorizon.rgb);
}

// The ambient light on a surface: a constant, or the sky's light on a surface
// facing the AO pixel's bent normal (where VBAO found one) or its own normal.
vec3 ambientLight(vec3 normal, ivec2 aoPixel) {
    if (frame.ambient.w < 0.5) return frame.ambient.rgb;
    vec3 direction = normal;
    if (withBentNormals) {
        vec3 bent = imageLoad(bentNormals, aoPixel).xyz;
        if (dot(bent, bent) > 0.25) direction = bent;
    }
    float t = (clamp(direction.y, -1.0, 1.0) * 0.5 + 0.5) * float(GROTTO_SKY_LIGHT_ROWS - 1);
    int row = min(int(t), GROTTO_SKY_LIGHT_ROWS - 2);
    return frame.ambient.rgb * mix(frame.skyLight[row].rgb, frame.skyLight[row + 1].rgb, t - float(row));
}

// Scene-linear: the exposure applied, no tone map (that is made where a display
// image is: display.comp, the image writers; shared/tone_map.h).
vec3 exposed(vec3 radiance) { return radiance * frame.exposure.x; }

// The surface's normal: its face's axis, or an object's face turned with it.
vec3 surfaceNormal(uint surface) {
    if (surfaceObject(surface) != 0u) return objects.worldNormals[surfaceKey(surface) - 1u].xyz;
    return faceAxisNormal(surfaceFace(surface));
}

// `ambient`: the light reaching the surface before AO; `aoShare`: the part of the
// AO already in it (1 where none is, the face cache's AO where its sky light is).
vec3 shadeWith(uint surface, vec3 normal, float ao, float sunReach, vec3 ambient, float aoShare) {
    float cosSun = dot(normal, frame.sunDirection.xyz);
    vec4 material = materialOf(surface);
    vec3 base = material.rgb;
    float visibility = min(mix(1.0, ao, frame.aoStrength.x), material.a);
    vec3 bounced = multiBounce(visibility, base) / max(mix(1.0, aoShare, frame.aoStrength.x), 1.0 / 255.0);
    // A glowing face shows its own light beside what it reflects.
    return base * (frame.sunRadiance.rgb * (max(cosSun, 0.0) * sunReach) + ambient * bounced) + emissionOf(surface);
}

vec3 shade(uint surface, float ao, float sunReach, ivec2 aoPixel) {
    vec3 normal = surfaceNormal(surface);
    return shadeWith(surface, normal, ao, sunReach, ambientLight(normal, aoPixel), 1.0);
}

float sunlit(ivec2 q) { return withShadow ? imageLoad(shadowImage, q).r : 1.0; }

// Full-res pixel h * scale + offset of AO pixel h's block.
void compositePixel(AoBlock block, ivec2 h, ivec2 offset) {
    ivec2 q = h * int(gtao.scale) + offset;
    if (any(greaterThanEqual(uvec2(q), frame.size))) return;
    uint surface = texelFetch(surfaceTex, q, 0).r;
    vec3 color = surface == 0u ? sky(q) : shade(surface, upsampledAo(block, h, offset, surfaceKey(surface)), sunlit(q), h);
    imageStore(outColor, q, vec4(exposed(color), 1.0));
}

#ifdef GROTTO_FACE_CACHE
// A world surface's light from the cache: its AO, its sun visibility (while the
// cache's sun is the frame's, times the objects' shadow where the shadow pass ran)
// and, with the sky's ambient, the sky light it holds, each less what objects take.
// An object's surface takes its own from the object light pass; one without it, or
// a face the cache lacks, is lit as without AO. The sky light replaces the open
// sky's ambient as the AO strength rises. One shadeWith for every case: a CPU
// device runs every branch a group of pixels takes, so each branch costs all.
vec3 shadeCached(ivec2 q, uint surface) {
    vec3 normal = surfaceNormal(surface);
    vec3 open = ambientLight(normal, q);
    vec4 objectPart = objectLight ? imageLoad(objectLightImage, q) : vec4(0.0);
    float sunReach = sunlit(q);
    bool seen;     // the surface has AO and sky weights of its own
    vec3 light;    // AO, horizon and zenith weights
    FaceCacheTaps t, faces;  // a world surface's texels, and with full light over the day its faces
    vec3 atlasFull = vec3(0.0);  // with full light through the atlas, its cells' light
    if (surfaceObject(surface) != 0u) {
        seen = objectLight;
        light = objectPart.xyz;
    } else {
        vec2 sunRange;
        vec4 c;  // AO, sun, horizon and zenith weights
        if (atlasRead) {
            AtlasLight a = atlasLightAt(q, surfaceFace(surface), texelFetch(atlasRecordTex, q, 0).xy);
            c = a.c, seen = a.seen, sunRange = a.sunRange, atlasFull = a.full;
        } else {
            t = cachedTapsAt(q, surfaceFace(surface), faces);
            if (askFaces) {
                askForTaps(q, t, surfaceFace(surface));
                dropUntraced(t);
            }
            c = faceCacheBlend(t, seen, sunRange);
        }
        // With the cache's sun, the shadow pass holds the objects' alone.
        float cosSun = dot(normal, frame.sunDirection.xyz);
        bool edge = false;
        float sun = cachedSun ? cachedSunAt(t, c, sunRange, normal, edge) : 1.0;
        // No rays where the sun gives no light (the day's, at night).
        if (shadowEdges && seen && cosSun > 0.0 && edge && frame.sunRadiance.r + frame.sunRadiance.g + frame.sunRadiance.b > 0.0)
            listShadowEdge(q, sun, exposed(materialOf(surface).rgb * frame.sunRadiance.rgb * (cosSun * sunReach)));
        if (cachedSun && seen) sunReach *= sun;
        light = vec3(max(c.x - objectPart.x, 0.0), max(c.zw - objectPart.yz, vec2(0.0)));
    }
    vec3 ambient = open;
    float aoShare = 1.0;
    if (fullLight) {
        // Full light: the light every bounce brought, occlusion and bounces
        // already in it, so neither AO nor the multi-bounce fit applies.
        // With objects (object_light.comp): the light they take from a world face
        // or give it by glowing, added; an object's face, its own light outright.
        vec3 full = open;
        if (surfaceObject(surface) != 0u) full = objectLight ? objectPart.rgb : open;
        else if (seen) full = max((atlasRead ? atlasFull : cachedFullLightAt(t, faces)) + objectPart.rgb, vec3(0.0));
        float cosSun = max(dot(normal, frame.sunDirection.xyz), 0.0);
        return materialOf(surface).rgb * (frame.sunRadiance.rgb * (cosSun * sunReach) + mix(open, full, frame.aoStrength.x)) +
               emissionOf(surface);
    }
    if (seen && frame.ambient.w >= 0.5) {
        vec3 sky = frame.ambient.rgb * (light.y * frame.skyHorizon.rgb + light.z * frame.skyZenith.rgb);
        ambient = mix(open, sky, frame.aoStrength.x);
        aoShare = light.x;
    }
    return shadeWith(surface, normal, seen ? light.x : 1.0, sunReach, ambient, aoShare);
}
#endif

void main() {
    ivec2 h = ivec2(gl_GlobalInvocationID.xy);
#ifdef GROTTO_FACE_CACHE
    if (withoutRegion) {
        if (gl_GlobalInvocationID.x >= chainHeader[0]) return;
        uint p = chainPixels[gl_GlobalInvocationID.x];
        h = ivec2(p & 0xFFFFu, p >> 16u);
    }
    if (any(greaterThanEqual(uvec2(h), frame.size))) return;
    uint cachedSurface = texelFetch(surfaceTex, h, 0).r;
    // A world pixel whose quad has no region: listed for the chain's pass.
    if (atlasRead && cachedSurface != 0u && surfaceObject(cachedSurface) == 0u && texelFetch(atlasRecordTex, h, 0).y == 0u) {
        uint slot = atomicAdd(chainHeader[0], 1u);
        chainPixels[slot] = uint(h.x) | (uint(h.y) << 16u);
        if (slot % 64u == 0u) atomicAdd(chainHeader[1], 1u);
        return;
    }
    imageStore(outColor, h, vec4(exposed(cachedSurface == 0u ? sky(h) : shadeCached(h, cachedSurface)), 1.0));
    return;
#endif
    if (!withAo) {
        if (any(greaterThanEqual(uvec2(h), frame.size))) return;
        uint surface = texelFetch(surfaceTex, h, 0).r;
        imageStore(outColor, h, vec4(exposed(surface == 0u ? sky(h) : shade(surface, 1.0, sunlit(h), h)), 1.0));
        return;
    }
    if (any(greaterThanEqual(uvec2(h), gtao.halfSize))) return;
    AoBlock block = loadAoBlock(h);
    compositePixel(block, h, ivec2(0, 0));
    if (gtao.scale == 1u) return;
    compositePixel(block, h, ivec2(1, 0));
    compositePixel(block, h, ivec2(0, 1));
    compositePixel(block, h, ivec2(1, 1));
}
