// A full-res history of a per-surface quantity accumulated over the frames (the
// soft sun's visibility, objects' light over the face cache), carried to each pixel
// from where its surface point was in the history's view. The includer declares
// `trace` (trace.glsl) and, before this, historySize() and historyTap(t, depth,
// key): the history pixel t's value, the view depth it was taken at and its
// surface key (0: sky).

// The history pixel's full-res position of a view-space point under a camera's
// ndcToViewMul_Add.
vec2 historyPixelOf(vec3 v, vec4 m) { return (v.xy / -v.z - m.zw) / m.xy - 0.5; }

// The history's value at the pixel whose surface point is `position` (view space)
// with `worldNormal` and `key`; `found` false without a usable one. Bilinear between
// the four history pixels around where the point was, each only if it saw the same
// face on the same plane: the nearest pixel alone would, under sub-pixel motion,
// keep handing each pixel its own history and smear edges along the motion.
vec4 surfaceHistory(ivec2 q, vec3 position, vec3 worldNormal, uint key, out bool found) {
    found = false;
    vec3 previous = (trace.currentToPrevious * vec4(position, 1.0)).xyz;
    float previousDepth = -previous.z;
    if (previousDepth <= 0.0) return vec4(0.0);
    // The motion as a difference of two identical computations: a still camera maps
    // every pixel exactly onto itself.
    vec4 m = trace.previousNdcToViewMul_Add;
    vec2 uv = vec2(q) + (historyPixelOf(previous, m) - historyPixelOf(position, trace.ndcToViewMul_Add));
    vec3 viewNormal = vec3(dot(trace.viewToWorld[0].xyz, worldNormal), dot(trace.viewToWorld[1].xyz, worldNormal),
                           dot(trace.viewToWorld[2].xyz, worldNormal));
    vec3 previousNormal = mat3(trace.currentToPrevious) * viewNormal;
    vec2 base = floor(uv), f = uv - base;
    vec4 sum = vec4(0.0);
    float weight = 0.0;
    for (int j = 0; j < 2; ++j)
        for (int i = 0; i < 2; ++i) {
            ivec2 t = ivec2(base) + ivec2(i, j);
            float w = (i == 0 ? 1.0 - f.x : f.x) * (j == 0 ? 1.0 - f.y : f.y);
            if (w <= 0.0 || any(greaterThanEqual(uvec2(t), uvec2(historySize())))) continue;
            float depth;
            uint tapKey;
            vec4 value = historyTap(t, depth, tapKey);
            vec3 tap = vec3(((vec2(t) + 0.5) * m.xy + m.zw) * depth, -depth);
            if (tapKey != key || abs(dot(tap - previous, previousNormal)) > 1e-3 * previousDepth) continue;
            sum += value * w;
            weight += w;
        }
    found = weight > 1e-3;
    return found ? sum / weight : vec4(0.0);
}
