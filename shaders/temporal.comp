#version 460
#extension GL_GOOGLE_include_directive : require
// The final spatial blur and temporal accumulation of half-res AO, in one pass so
// the spatially denoised AO is never stored and loaded again (lavapipe pays for
// every image access). Each pixel's surface point is carried into the previous
// view (the world is static, so the camera change is the whole motion) and the
// previous output is read there, bilinearly, from taps that lie on the same face
// plane: anything else is a disocclusion and restarts the pixel's history. The
// history is clamped to the range of this frame's raw (not yet denoised) AO over
// the 3x3 neighbourhood widened by GROTTO_TEMPORAL_CLAMP_MARGIN, so the clamp
// allows for the estimator's own noise yet cuts off stale values (a halo that
// moved on), then blended with weight 1 / length, the length capped at
// temporalHistory frames. Pixels whose surface lies in a box an edit invalidated
// (TemporalConstants::boxMin/boxMax, for one frame) restart their history too.
#include "shared/gtao.h"
#include "shared/quad.h"
#include "shared/temporal.h"

// Set by TemporalPass from the number of denoise passes: whether this pass runs
// the final blur (at least one), and whether its input is the raw AO (at most one),
// whose nine values the blur reads anyway.
layout(constant_id = 0) const bool blur = true;
layout(constant_id = 1) const bool sourceIsRaw = true;

layout(local_size_x = GROTTO_GTAO_GROUP, local_size_y = GROTTO_GTAO_GROUP) in;
layout(set = 0, binding = 0, std140) uniform Constants { GtaoConstants gtao; };
layout(set = 0, binding = 1, std140) uniform Temporal { TemporalConstants temporal; };
layout(set = 0, binding = 2, rgba32f) uniform readonly image2D denoiseSource;  // the final blur's input
layout(set = 0, binding = 3, rgba32f) uniform readonly image2D history;  // AO, history length, view depth, surface key
layout(set = 0, binding = 4, rgba32f) uniform writeonly image2D target;  // same layout as history
layout(set = 0, binding = 5, rgba32f) uniform readonly image2D raw;      // GTAO before denoising: the clamp's range

#ifdef GROTTO_TEMPORAL_OBJECTS
// Built a second time for worlds with objects (temporal_objects.comp): surface keys
// name an object's faces too, whose normals in the previous view come from the
// objects' table; where objects move (`motion`), each pixel's previous position
// comes from the G-buffer's motion target instead of the camera change alone.
layout(constant_id = 2) const bool motion = false;
layout(set = 0, binding = 6, std140) uniform Objects { ObjectUniforms objects; };
layout(set = 0, binding = 7) uniform sampler2D motionTex;  // previous pixel - current (full res), previous view depth
#define previousViewNormal(key) vec3(objects.previousViewNormals[(key) - 1u])
#else
#define previousViewNormal(key) vec3(temporal.previousViewNormals[(key) - 1u])
#endif

float gtaoDepth(ivec2 texel, int mip) { return 0.0; }
uint gtaoSurface(ivec2 pixel) { return 0u; }
#include "shared/gtao_kernel.h"
#include "denoise_blur.glsl"

// Whether a surface point (view space) lies in a box where an edit restarts the
// history: its AO there may come from voxels that changed.
bool nearEdit(vec3 view) {
    vec3 w = temporal.viewToWorld[0].xyz * view.x + temporal.viewToWorld[1].xyz * view.y +
             temporal.viewToWorld[2].xyz * view.z;
    for (uint i = 0u; i < temporal.boxCount; ++i)
        if (all(greaterThanEqual(w, temporal.boxMin[i].xyz)) && all(lessThanEqual(w, temporal.boxMax[i].xyz)))
            return true;
    return false;
}

void main() {
    ivec2 p = ivec2(gl_GlobalInvocationID.xy);
    if (any(greaterThanEqual(uvec2(p), gtao.halfSize))) return;
    vec4 c = imageLoad(denoiseSource, p);
    uint face = uint(c.w);
    if (face == 0u) {  // sky: nothing to accumulate
        imageStore(target, p, vec4(1.0, 0.0, c.z, 0.0));
        return;
    }
    ivec2 last = ivec2(gtao.halfSize) - 1;
    // The clamp's range: the raw 3x3, which the blur has read when its input is raw.
    vec2 range = vec2(1.0, 0.0), blurRange;
    float spatial = blur ? denoiseBlur(p, denoiseBeta(true), blurRange) : c.x;
    if (blur && sourceIsRaw)
        range = blurRange;
    else
        for (int j = -1; j <= 1; ++j)
            for (int i = -1; i <= 1; ++i) {
                float v = imageLoad(raw, clamp(p + ivec2(i, j), ivec2(0), last)).x;
                range = vec2(min(range.x, v), max(range.y, v));
            }
    float lo = min(range.x, spatial) - GROTTO_TEMPORAL_CLAMP_MARGIN;
    float hi = max(range.y, spatial) + GROTTO_TEMPORAL_CLAMP_MARGIN;

    vec3 position = gtaoViewPosition(vec2(p), c.z);
    vec3 previous = (temporal.currentToPrevious * vec4(position, 1.0)).xyz;
#ifdef GROTTO_TEMPORAL_OBJECTS
    vec4 moved = vec4(0.0);
    if (motion) {  // the surface point where the G-buffer says it was: its pixel there and its depth
        moved = texelFetch(motionTex, p * int(gtao.scale), 0);
        vec2 q = vec2(p * int(gtao.scale)) + 0.5 + moved.xy;
        vec4 m = temporal.previousNdcToViewMul_Add;
        previous = vec3((q * vec2(m.x, m.y) + vec2(m.z, m.w)) * moved.z, -moved.z);
    }
#endif
    float previousDepth = -previous.z;
    vec3 normal = previousViewNormal(face);
    float sumAo = 0.0, sumLength = 0.0, weight = 0.0;
    if (temporal.reset == 0u && previousDepth > 0.0 && !nearEdit(position)) {
        // The motion as a difference of two identical computations, so a camera
        // that did not move reprojects every pixel exactly onto itself.
        vec2 uv = vec2(p) + (gtaoPixelOf(previous, temporal.previousNdcToViewMul_Add) -
                             gtaoPixelOf(position, gtao.ndcToViewMul_Add));
#ifdef GROTTO_TEMPORAL_OBJECTS
        if (motion) uv = vec2(p) + moved.xy / float(gtao.scale);
#endif
        vec2 base = floor(uv), f = uv - base;
        for (int j = 0; j < 2; ++j)
            for (int i = 0; i < 2; ++i) {
                ivec2 t = ivec2(base) + ivec2(i, j);
                float w = (i == 0 ? 1.0 - f.x : f.x) * (j == 0 ? 1.0 - f.y : f.y);
                if (w <= 0.0 || any(greaterThan(uvec2(t), uvec2(last)))) continue;
                vec4 h = imageLoad(history, t);
                vec2 q = vec2(t) * float(gtao.scale) + 0.5;
                vec4 m = temporal.previousNdcToViewMul_Add;
                vec3 tap = vec3((q * vec2(m.x, m.y) + vec2(m.z, m.w)) * h.z, -h.z);
                // Same face and on the same plane: the same surface, seen again.
                if (uint(h.w) != face || abs(dot(tap - previous, normal)) > 1e-3 * previousDepth) continue;
                sumAo += w * h.x;
                sumLength += w * h.y;
                weight += w;
            }
    }
    float ao = spatial, frames = 1.0;
    if (weight > 1e-3) {
        float historyAo = clamp(sumAo / weight, lo, hi);
        frames = min(sumLength / weight + 1.0, float(max(gtao.settings.temporalHistory, 1u)));
        ao = mix(historyAo, spatial, 1.0 / frames);
    }
    imageStore(target, p, vec4(ao, frames, c.z, c.w));
}
