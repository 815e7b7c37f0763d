#version 460
#extension GL_GOOGLE_include_directive : require
// Voxel-traced AO at half resolution: the reference's own estimator (docs/metrics.md)
// with a few rays per frame. From each AO pixel's surface point, `specRays`
// cosine-weighted directions about its normal, each open when it enters no solid
// voxel within the AO radius; the noise turns the set per pixel and per frame, so
// the temporal pass averages fresh rays every frame. Same inputs and output as
// gtao.comp, plus the trace inputs, so denoise, temporal and upsample are shared.
//
// Built with GROTTO_HYBRID (hybrid.comp): GTAO's horizons and the rays together.
// GTAO sees what the depth buffer holds at little noise; the rays see what it does
// not (behind silhouettes, under thin walls, off screen). Their mean halves GTAO's
// bias and the rays' noise variance; the smaller of the two, tried first, keeps
// every occluder but doubles down on the rays' noise toward dark (docs/tradeoff.md).
#include "shared/gtao.h"
#include "shared/quad.h"

layout(constant_id = 0) const uint specSlices = 3u;
layout(constant_id = 1) const uint specSteps = 3u;
layout(constant_id = 2) const float specPower = 2.0;
layout(constant_id = 3) const uint specRays = 6u;
#define kGtaoSlices specSlices
#define kGtaoSteps specSteps
#define kGtaoPower specPower

#include "ao_estimator.glsl"
#define GROTTO_TRACE_BINDING 4
#define GROTTO_TRACE_OBJECTS  // objects block the rays as the world does
#include "trace.glsl"

// The share of rays from the pixel's surface point that stay open within the radius.
float voxelVisibility(ivec2 pixel, float z) {
    uint surface = gtaoSurface(pixel * int(gtao.scale));
    vec3 v = gtaoViewNormal(pixel);
    vec3 normal = normalize(trace.viewToWorld[0].xyz * v.x + trace.viewToWorld[1].xyz * v.y + trace.viewToWorld[2].xyz * v.z);
    uint face = 6u;
    if (surfaceObject(surface) == 0u) {  // a world face: its axis, exactly
        face = surfaceFace(surface);
        normal = faceAxisNormal(face);
    }
    VoxelRayStart start = traceStart(gtaoViewPosition(vec2(pixel), z), face, normal);
    vec2 noise = gtaoNoise(uvec2(pixel), gtao.frameIndex);
    uint open = 0u;
    for (uint i = 0u; i < specRays; ++i)
        if (traceShortRay(start, traceCosineRay(normal, noise, i), trace.radiusVoxels) < 0.0) ++open;
    return float(open) / float(specRays);
}

void main() {
    ivec2 p = ivec2(gl_GlobalInvocationID.xy);
    if (any(greaterThanEqual(uvec2(p), gtao.halfSize))) return;
    float z = gtaoDepth(p, 0);
    float fade = gtaoDistanceFade(z);
#ifdef GROTTO_HYBRID
    vec2 result = gtaoPixel(p);  // the distance fade is in it already
    if (z < kGtaoSky && fade < 1.0) result.x = 0.5 * (result.x + mix(voxelVisibility(p, z), 1.0, fade));
#else
    vec2 result = vec2(1.0, gtaoPixelEdges(p));
    if (z < kGtaoSky && fade < 1.0) result.x = mix(voxelVisibility(p, z), 1.0, fade);
#endif
    aoStore(p, result);
}
