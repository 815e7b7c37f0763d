// The GTAO kernel, written once for GLSL and C++ (GLM): the GPU pass includes it
// in its shader, the CPU twin in a class. The includer provides
//   GtaoConstants gtao;                       the constants (shared/gtao.h)
//   float gtaoDepth(ivec2 texel, int mip);    prefiltered view depth (kGtaoSky = none) at
//                                             AO pixel texel (always inside the AO image)
//                                             from MIP mip, i.e. MIP texel texel >> mip
//   uint  gtaoSurface(ivec2 fullResPixel);    G-buffer surface id (shared/quad.h)
//   float gtaoThickness(ivec2 texel, int mip); with GROTTO_VBAO only: the traced thickness
//                                             behind the depth at that texel and MIP
//                                             (world units along the view ray)
//   kVbaoBentNormals, and                     with GROTTO_VBAO only: whether to find the bent
//   void vbaoBentNormal(ivec2 texel, vec3 n); normal, and where it goes: a world-space unit
//                                             vector, or zero for the sky
// and, in C++, `using namespace glm` around it. Float literals carry an f so both
// languages read them the same way.
//
// Half-resolution pixel (x, y) stands for full-resolution pixel (2x, 2y): its depth,
// normal and position are that pixel's exactly (see depth_prefilter.comp). With
// gtao.scale = 1 (the full-resolution comparison) the AO pixel is the full one.

#define kGtaoSky 1.0e15f

// The loop shape. The GTAO pass defines these as specialization constants (same
// values as the settings), so the compiler sees constants, unrolls both loops and
// folds pow(t, 2): about 30 % of the pass on lavapipe.
#ifndef kGtaoSlices
#define kGtaoSlices gtao.settings.sliceCount
#define kGtaoSteps gtao.settings.stepsPerSlice
#define kGtaoPower gtao.settings.sampleDistributionPower
#endif
#define kGtaoPi 3.14159265358979f

float gtaoSaturate(float x) { return clamp(x, 0.0f, 1.0f); }

#include "noise.h"

// Where MIP `mip` sits in the depth atlas (xy offset, zw size): MIP 0 at the
// origin, MIPs 1-4 in a column of equal slots to its right. Plain arithmetic, so a
// sample's varying MIP costs no indexed constant load.
ivec2 gtaoMipOffset(int mip) {
    ivec2 half0 = ivec2(gtao.halfSize);
    return mip == 0 ? ivec2(0) : ivec2(half0.x, (mip - 1) * ((half0.y + 1) >> 1));
}

ivec4 gtaoMipRect(int mip) {
    ivec2 size = (ivec2(gtao.halfSize) + ((1 << mip) - 1)) >> mip;
    return ivec4(gtaoMipOffset(mip), size);
}

// floor(log2(x)) for positive normal floats (-127 for zero): the IEEE exponent.
int gtaoExponent(float x) { return (floatBitsToInt(x) >> 23) - 127; }

vec3 gtaoViewPosition(vec2 halfPixel, float depth) {
    vec2 p = halfPixel * float(gtao.scale) + 0.5f;
    vec4 m = gtao.ndcToViewMul_Add;  // no swizzles: GLM has none by default
    return vec3((p * vec2(m.x, m.y) + vec2(m.z, m.w)) * depth, -depth);
}

// The AO pixel coordinates of a view-space point: the inverse of gtaoViewPosition
// for the projection given by ndcToView (a GtaoConstants::ndcToViewMul_Add).
vec2 gtaoPixelOf(vec3 v, vec4 ndcToView) {
    vec2 full = (vec2(v.x, v.y) / -v.z - vec2(ndcToView.z, ndcToView.w)) / vec2(ndcToView.x, ndcToView.y) - 0.5f;
    return full / float(gtao.scale);
}

// The view position behind a sample: a coarse MIP's depth stands for its whole
// block of half-res pixels, so it is placed at the block's centre.
vec3 gtaoSamplePosition(ivec2 halfPixel, int mip) {
    vec2 block = vec2((halfPixel >> mip) << mip) + 0.5f * float((1 << mip) - 1);
    return gtaoViewPosition(block, gtaoDepth(halfPixel, mip));
}

// Depth MIP reduction: an average around the farthest of the four, with samples
// nearer than it by more than (a fraction of) the AO radius fading out, as
// XeGTAO does. Favouring the far side keeps a block that straddles a surface and
// the sky or a far background from placing near depth higher on screen, where it
// would occlude an open floor.
float gtaoMipFilter(float d0, float d1, float d2, float d3) {
    float farthest = max(max(d0, d1), max(d2, d3));
    float radius = 0.75f * gtao.settings.radius * gtao.settings.radiusMultiplier;
    float range = max(gtao.settings.falloffRange * radius, 1e-6f);
    float from = radius * (1.0f - gtao.settings.falloffRange);
    float mul = -1.0f / range, add = from / range + 1.0f;
    float w0 = gtaoSaturate((farthest - d0) * mul + add);
    float w1 = gtaoSaturate((farthest - d1) * mul + add);
    float w2 = gtaoSaturate((farthest - d2) * mul + add);
    float w3 = gtaoSaturate((farthest - d3) * mul + add);
    return (w0 * d0 + w1 * d1 + w2 * d2 + w3 * d3) / (w0 + w1 + w2 + w3);
}

// Edge weights to the left, right, top and bottom neighbours (1 = same surface),
// tolerant of planar slopes, from view depths.
vec4 gtaoEdges(float c, float l, float r, float t, float b) {
    vec4 e = vec4(l, r, t, b) - c;
    float slopeLR = (e.y - e.x) * 0.5f;
    float slopeTB = (e.w - e.z) * 0.5f;
    vec4 alongSlope = e + vec4(slopeLR, -slopeLR, slopeTB, -slopeTB);
    e = min(abs(e), abs(alongSlope));
    return clamp(vec4(1.25f) - e / (c * 0.011f), vec4(0.0f), vec4(1.0f));
}

// Four edges in two bits each, as a value in [0, 1].
float gtaoPackEdges(vec4 e) {
    uvec4 q = uvec4(floor(clamp(e, vec4(0.0f), vec4(1.0f)) * 3.0f + 0.5f));
    return float((q.x << 6u) | (q.y << 4u) | (q.z << 2u) | q.w) / 255.0f;
}

vec4 gtaoUnpackEdges(float packed) {
    uint v = uint(packed * 255.0f + 0.5f);
    return vec4(float((v >> 6u) & 3u), float((v >> 4u) & 3u), float((v >> 2u) & 3u), float(v & 3u)) / 3.0f;
}

// The packed edges of an AO pixel from its own and its four neighbours' depths
// (what every AO estimator writes beside its visibility for the denoiser).
float gtaoPixelEdges(ivec2 pixel) {
    ivec2 last = ivec2(gtao.halfSize) - 1;
    float z = gtaoDepth(pixel, 0);
    float zl = gtaoDepth(ivec2(max(pixel.x - 1, 0), pixel.y), 0);
    float zr = gtaoDepth(ivec2(min(pixel.x + 1, last.x), pixel.y), 0);
    float zt = gtaoDepth(ivec2(pixel.x, max(pixel.y - 1, 0)), 0);
    float zb = gtaoDepth(ivec2(pixel.x, min(pixel.y + 1, last.y)), 0);
    return gtaoPackEdges(gtaoEdges(z, zl, zr, zt, zb));
}

// How far the max distance fades AO out at view depth z: 0 = full AO, 1 = open.
// The fade spans the last tenth of the distance so no line shows where AO stops.
float gtaoDistanceFade(float z) {
    float d = gtao.settings.maxDistance;
    return d > 0.0f ? gtaoSaturate((z - 0.9f * d) / (0.1f * d)) : 0.0f;
}

// The view-space normal of an AO pixel's surface (its full-res pixel's face, turned
// with its object's rotation: shared/objects.h).
vec3 gtaoViewNormal(ivec2 pixel) {
    return vec3(gtao.viewNormals[surfaceKey(gtaoSurface(pixel * int(gtao.scale))) - 1u]);
}

// A view-space direction in world space: the view-space world axes are the first
// six face normals (+X -X +Y -Y +Z -Z).
vec3 gtaoWorldDirection(vec3 v) {
    return vec3(dot(v, vec3(gtao.viewNormals[0])), dot(v, vec3(gtao.viewNormals[2])), dot(v, vec3(gtao.viewNormals[4])));
}

#ifdef GROTTO_VBAO
// Where the solid behind a depth sample ends along the sample's view ray, as a
// multiple of its view position: the settings' thickness in world units
// (constant) or as a share of the view depth (distance), or what the depth
// prefilter traced through the voxels at that texel and MIP (voxels; the includer
// provides gtaoThickness then).
float vbaoBackScale(vec3 front, ivec2 texel, int mip) {
    uint mode = gtao.settings.thicknessMode;
    float t = gtao.settings.thickness;
    if (mode == kVbaoThicknessVoxels) return 1.0f + gtaoThickness(texel, mip) / max(length(front), 1e-30f);
    return mode == kVbaoThicknessDistance ? 1.0f + t : 1.0f + t / max(-front.z, 1e-30f);
}

// The sectors one sample hides: from its front to its back, the point its own
// view ray leaves the solid (view positions scale with view depth along a pixel's
// ray), as shares of the slice's measure. side: +1 for samples toward the slice's
// direction, -1 against; lowCos: the cosine of the hemisphere's edge on that side.
// The falloff weight pulls the front's cosine toward that edge's exactly as GTAO
// pulls a horizon's, so with no back (infinite thickness) the two agree up to the
// sectors, a thicker occluder never hides less, and a weight of 0 hides nothing.
struct VbaoSample {
    float front, back;    // shares of the slice's measure
    float zFront, zBack;  // view depths of the solid along the sample's ray
    bool hides;
};

VbaoSample vbaoSample(VbaoSlice slice, vec3 position, vec3 horizon, vec3 delta, float backScale, float weight,
                      vec3 viewVec, float lowCos, float side) {
    VbaoSample s;
    vec3 front = position + delta;
    s.front = vbaoSliceCdf(slice, mix(lowCos, dot(horizon, viewVec), weight), side);
    s.back = vbaoSliceCdf(slice, dot(normalize(front * backScale - position), viewVec), side);
    s.zFront = -front.z;
    s.zBack = -front.z * backScale;
    s.hides = side * (s.back - s.front) > 0.0f;
    return s;
}

uint vbaoSampleSectors(VbaoSample s) { return s.hides ? vbaoSectorsBetween(s.front, s.back) : 0u; }

// Two consecutive samples on one side whose solids overlap in view depth are one
// occluder: the surface between them hides the sectors between their fronts too.
// (Also joining samples whose faces share a plane gained 0.35 dB on thin and
// nothing elsewhere, for 3 ms more on lavapipe: the face fetch per sample.)
uint vbaoBridge(VbaoSample a, VbaoSample b) {
    bool joined = a.hides && b.hides && max(a.zFront, b.zFront) <= min(a.zBack, b.zBack);
    return joined ? vbaoSectorsBetween(a.front, b.front) : 0u;
}

#endif
// Visibility in [0, 1] (1 = open) at a half-resolution pixel, and its packed edges.
vec2 gtaoPixel(ivec2 pixel) {
    GtaoSettings s = gtao.settings;
    ivec2 last = ivec2(gtao.halfSize) - 1;
    float z = gtaoDepth(pixel, 0);
    float edges = gtaoPixelEdges(pixel);
    float distanceFade = gtaoDistanceFade(z);
    if (z >= kGtaoSky || distanceFade >= 1.0f) {
#ifdef GROTTO_VBAO
        if (kVbaoBentNormals)
            vbaoBentNormal(pixel, z >= kGtaoSky ? vec3(0.0f) : gtaoWorldDirection(gtaoViewNormal(pixel)));
#endif
        return vec2(1.0f, edges);
    }

    vec3 normal = gtaoViewNormal(pixel);
    vec3 position = gtaoViewPosition(vec2(pixel), z);
    vec3 viewVec = normalize(-position);

    float effectRadius = s.radius * s.radiusMultiplier;
    float falloffRange = max(s.falloffRange * effectRadius, 1e-6f);
    float falloffFrom = effectRadius * (1.0f - s.falloffRange);
    float falloffMul = -1.0f / falloffRange;
    float falloffAdd = falloffFrom / falloffRange + 1.0f;
    // Screen-space radius in half-res pixels; tiny radii fade towards open.
    float screenRadius = effectRadius / (z * gtao.pixelViewSize);
    float visibility = gtaoSaturate((10.0f - screenRadius) / 100.0f) * 0.5f;
    float visible = 0.0f, unoccluded = 0.0f;
    float minS = 1.3f / screenRadius;  // skip the centre pixel itself
    vec2 noise = gtaoNoise(uvec2(pixel), gtao.frameIndex);
    float mipScale = exp2(1.0f - 2.0f * s.depthMipSamplingOffset);  // (2^(0.5 - offset))^2
    float thinStretch = (1.0f + s.thinOccluderCompensation) * (1.0f + s.thinOccluderCompensation) - 1.0f;
#ifdef GROTTO_VBAO
    vec3 bent = vec3(0.0f);  // the open directions' cosine-weighted sum over the slices
#endif

    // Slice directions by rotation: one sin/cos pair for the first and for the step.
    float phi0 = noise.x / float(kGtaoSlices) * kGtaoPi, dPhi = kGtaoPi / float(kGtaoSlices);
    vec2 sliceDir = vec2(cos(phi0), sin(phi0)), sliceStep = vec2(cos(dPhi), sin(dPhi));
    for (uint slice = 0u; slice < kGtaoSlices; ++slice) {
        float cosPhi = sliceDir.x, sinPhi = sliceDir.y;
        sliceDir = vec2(cosPhi * sliceStep.x - sinPhi * sliceStep.y, sinPhi * sliceStep.x + cosPhi * sliceStep.y);
        vec2 omega = vec2(cosPhi, -sinPhi) * screenRadius;  // pixels: y points down
        vec3 direction = vec3(cosPhi, sinPhi, 0.0f);        // view space: y points up
        vec3 orthoDirection = direction - dot(direction, viewVec) * viewVec;
        vec3 axis = normalize(cross(orthoDirection, viewVec));
        vec3 projectedNormal = normal - axis * dot(normal, axis);
        float signNorm = dot(orthoDirection, projectedNormal) >= 0.0f ? 1.0f : -1.0f;
        float projectedLength = max(length(projectedNormal), 1e-6f);
        float cosNorm = gtaoSaturate(dot(projectedNormal, viewVec) / projectedLength);
        float n = signNorm * acos(cosNorm);
        float sinN = signNorm * sqrt(max(1.0f - cosNorm * cosNorm, 0.0f));  // sin n, without a sin
        // The hemisphere's own horizons: cos(n + pi/2) = -sin n, cos(n - pi/2) = sin n.
        float lowCos0 = -sinN, lowCos1 = sinN;
        float horizonCos0 = lowCos0, horizonCos1 = lowCos1;
#ifdef GROTTO_VBAO
        float sliceWeight = projectedLength;  // |N| in the slice: its cosines' scale
        uint occluded = 0u;  // the slice's sectors hidden by some sample's front-to-back span
        VbaoSlice sectors = vbaoSlice(n, cosNorm, sinN);
        VbaoSample last0, last1;
        last0.hides = false;
        last1.hides = false;
#endif

        for (uint stepIndex = 0u; stepIndex < kGtaoSteps; ++stepIndex) {
            // Golden-ratio jitter per step decorrelates steps sharing the pixel's noise.
            float stepNoise = fract(noise.y + float(slice + stepIndex * kGtaoSteps) * 0.6180339887f);
            float t = pow((float(stepIndex) + stepNoise) / float(kGtaoSteps), kGtaoPower) + minS;
            // Bounded so the integer pixel offset cannot overflow at extreme radii;
            // such a sample is off-screen, and open, either way.
            vec2 offset = clamp(t * omega, vec2(-32768.0f), vec2(32768.0f));
            // MIP floor(log2|offset| - mipOffset + 0.5), read off the float exponent of
            // the scaled squared length: no log2 or sqrt per step.
            int mip = clamp((gtaoExponent(dot(offset, offset) * mipScale) >> 1), 0, GROTTO_GTAO_DEPTH_MIPS - 1);
            ivec2 rounded = ivec2(floor(offset + 0.5f));
            ivec2 p0 = pixel + rounded, p1 = pixel - rounded;
            ivec2 c0 = clamp(p0, ivec2(0), last), c1 = clamp(p1, ivec2(0), last);
            vec3 delta0 = gtaoSamplePosition(c0, mip) - position;
            vec3 delta1 = gtaoSamplePosition(c1, mip) - position;
            float squared0 = dot(delta0, delta0), squared1 = dot(delta1, delta1);
            float inverse0 = inversesqrt(max(squared0, 1e-30f)), inverse1 = inversesqrt(max(squared1, 1e-30f));
            vec3 horizon0 = delta0 * inverse0, horizon1 = delta1 * inverse1;
            // Thin-occluder compensation: stretching the view-axis distance fades
            // samples that sit far in front of or behind the centre sooner.
            float falloff0 = sqrt(squared0 + delta0.z * delta0.z * thinStretch);
            float falloff1 = sqrt(squared1 + delta1.z * delta1.z * thinStretch);
            // Tangent bias: a sample on or below the centre's tangent plane cannot
            // occlude. Snapping samples to pixel centres moves in-plane samples off
            // the slice, which would otherwise read as occlusion on flat floors.
            // Off-screen samples are unknown and count as open: clamping them to the
            // border would lift slanted planes into false occluders.
            float inside0 = all(equal(p0, c0)) ? 1.0f : 0.0f;
            float inside1 = all(equal(p1, c1)) ? 1.0f : 0.0f;
            float weight0 = gtaoSaturate(falloff0 * falloffMul + falloffAdd) * gtaoSaturate(dot(horizon0, normal) * 32.0f) * inside0;
            float weight1 = gtaoSaturate(falloff1 * falloffMul + falloffAdd) * gtaoSaturate(dot(horizon1, normal) * 32.0f) * inside1;
#ifdef GROTTO_VBAO
            VbaoSample s0 = vbaoSample(sectors, position, horizon0, delta0, vbaoBackScale(position + delta0, c0, mip),
                                       weight0, viewVec, lowCos0, 1.0f);
            VbaoSample s1 = vbaoSample(sectors, position, horizon1, delta1, vbaoBackScale(position + delta1, c1, mip),
                                       weight1, viewVec, lowCos1, -1.0f);
            occluded |= vbaoSampleSectors(s0) | vbaoSampleSectors(s1) | vbaoBridge(last0, s0) | vbaoBridge(last1, s1);
            last0 = s0;
            last1 = s1;
#else
            float shc0 = mix(lowCos0, dot(horizon0, viewVec), weight0);
            float shc1 = mix(lowCos1, dot(horizon1, viewVec), weight1);
            horizonCos0 = max(horizonCos0, shc0);
            horizonCos1 = max(horizonCos1, shc1);
#endif
        }
        // Cosine-weighted integral of the visible arc between the two horizons, and
        // of the whole arc (horizons at n -/+ pi/2, where it is cos n + n sin n).
        projectedLength = mix(projectedLength, 1.0f, 0.05f);
#ifdef GROTTO_VBAO
        visible += vbaoVisibility(occluded, n, projectedLength);
        if (kVbaoBentNormals) {
            vec2 open = vbaoOpenDirection(sectors, occluded);
            bent += sliceWeight * (normalize(orthoDirection) * open.x + viewVec * open.y);
        }
#else
        // cos(2h - n) by the angle formulas from cos h, which the search found, so
        // only the angles themselves need an acos.
        float c0 = clamp(horizonCos1, -1.0f, 1.0f), c1 = clamp(horizonCos0, -1.0f, 1.0f);
        float h0 = -acos(c0), h1 = acos(c1);
        float sin0 = -sqrt(max(1.0f - c0 * c0, 0.0f)), sin1 = sqrt(max(1.0f - c1 * c1, 0.0f));
        float cos2h0n = (2.0f * c0 * c0 - 1.0f) * cosNorm + 2.0f * sin0 * c0 * sinN;
        float cos2h1n = (2.0f * c1 * c1 - 1.0f) * cosNorm + 2.0f * sin1 * c1 * sinN;
        float arc0 = (cosNorm + 2.0f * h0 * sinN - cos2h0n) / 4.0f;
        float arc1 = (cosNorm + 2.0f * h1 * sinN - cos2h1n) / 4.0f;
        visible += projectedLength * (arc0 + arc1);
#endif
        unoccluded += projectedLength * (cosNorm + n * sinN);
    }
    // Normalised by the unoccluded integral of the same slices: an open plane is
    // exactly 1 whatever the view angle and slice count. (The plain average over a
    // few slices swings between 0.77 and 1.21 per slice 40 degrees off-axis.) The
    // small-radius fade is added once, not per slice, so no preset dilutes it.
    visibility = gtaoSaturate(visible / max(unoccluded, 1e-6f) + visibility);
    visibility = max(pow(visibility, s.finalValuePower), 0.03f);
#ifdef GROTTO_VBAO
    // Fully hidden, or fading out with distance: toward the surface's normal.
    if (kVbaoBentNormals) {
        float found = length(bent);
        vec3 direction = found > 1e-6f ? bent / found : normal;
        vbaoBentNormal(pixel, gtaoWorldDirection(normalize(mix(direction, normal, distanceFade))));
    }
#endif
    return vec2(mix(visibility, 1.0f, distanceFade), edges);
}
