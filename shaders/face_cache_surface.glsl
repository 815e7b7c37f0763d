// The face cache read at a full-resolution pixel's world surface. The includer
// declares `depthBuffer` (full-res D32, reverse-Z), the frame uniforms as `frame`
// (shared/frame.h) and the cache (face_cache.glsl). It may define what the frame
// reads as constants (the composite's pipelines); else the uniforms say.
#ifndef GROTTO_CACHE_READS_DAY_LIGHT
#define GROTTO_CACHE_READS_DAY_LIGHT (frame.dayLight.x != 0u)
#endif
#ifndef GROTTO_CACHE_READS_DAY_SUN
#define GROTTO_CACHE_READS_DAY_SUN (frame.daySun.x != 0u)
#endif

// Where the pixel's view ray meets the voxel plane of world face `face` (0..5), in
// voxels from the camera's voxel (frame.cameraCell): the depth only picks the
// plane, the ray gives the point on it, so the point is exact to the plane
// whatever the depth buffer's precision.
vec3 cachedPointAt(ivec2 q, uint face) {
    float z = frame.depthAB.y / (texelFetch(depthBuffer, q, 0).r + frame.depthAB.x);
    vec2 c = vec2(q) + 0.5;
    // The view ray at unit view depth, in voxels.
    vec3 ray = (frame.rayOrigin.xyz + c.x * frame.rayStepX.xyz + c.y * frame.rayStepY.xyz) * frame.cameraFraction.w;
    vec3 start = frame.cameraFraction.xyz;
    vec3 p = start + ray * z;
    uint axis = faceAxis(face);
    float plane = round(p[axis]);
    if (abs(ray[axis]) > 1e-6 * abs(plane - start[axis])) p = start + ray * ((plane - start[axis]) / ray[axis]);
    p[axis] = plane;
    return p;
}

// The texels read at that point.
FaceCacheTaps cachedTapsAt(ivec2 q, uint face) {
    return faceCacheTaps(cachedPointAt(q, face), frame.cameraCell.xyz, face);
}
// ... and, with full light over the day, in `faces` the four faces whose centres
// lie nearest, whose words cachedFullLightAt blends (one look-up for both).
FaceCacheTaps cachedTapsAt(ivec2 q, uint face, out FaceCacheTaps faces) {
    if (!GROTTO_CACHE_READS_DAY_LIGHT) return cachedTapsAt(q, face);
    return faceCacheTapsWithFaces(cachedPointAt(q, face), frame.cameraCell.xyz, face, int(faceCacheK()), faces);
}


// The cache's sun visibility at taps `t` of a surface with normal `normal` (c and
// sunRange: faceCacheBlend's): with the day's sun, from the positions either side
// of the hour; else the texels' own. `edge`: the texels cannot say, and a ray per
// pixel must (a point sun's texels not all lit nor all shadowed: a texel reads
// part lit where an edge of sunlight crosses it, however thin; a disc's
// disagreeing by over a quarter: a penumbra narrower than the texels apart; the
// day's positions or texels disagreeing).
float cachedSunAt(FaceCacheTaps t, vec4 c, vec2 sunRange, vec3 normal, out bool edge) {
    if (GROTTO_CACHE_READS_DAY_SUN) {
        // A position behind the face reads dark, as the face is then: where the
        // sun crosses the face's plane between the two, they disagree.
        float sun = faceCacheDaySun(t, frame.daySun.x, (1u << frame.daySun.y) | (1u << frame.daySun.z), edge);
        edge = edge || frame.daySun.w != 0u || (dot(normal, frame.daySunBefore.xyz) <= 0.0 && dot(normal, frame.daySunAfter.xyz) <= 0.0);
        return sun;
    }
    edge = frame.sunDirection.w > 0.5 ? sunRange.y > 0.5 / 255.0 && sunRange.x < 1.0 - 0.5 / 255.0
                                      : sunRange.y - sunRange.x > 0.25;
    return c.y;
}

// With full light, the light a world surface's texel taps `t` receive at the
// frame's hour (irradiance over pi): their light words, and with full light over
// the day the sky's light from the texels' weights and the bounced light from the
// words of the faces `faces` (cachedTapsAt's), at the hour's colours. A face keeps one value of
// each word, so those are blended between the four faces whose centres lie
// nearest, as the texels are between theirs: no face shows as a tile.
vec3 cachedFullLightAt(FaceCacheTaps t, FaceCacheTaps faces) {
    vec3 light = faceCacheFullLight(t);
    if (!GROTTO_CACHE_READS_DAY_LIGHT) return light;
    vec3 zenith = frame.ambient.rgb * frame.skyZenith.rgb, horizon = frame.ambient.rgb * frame.skyHorizon.rgb;
    vec2 weights = vec2(0.0);
    float weight = 0.0;
    for (int c = 0; c < 4; ++c) {
        if (t.weight[c] <= 0.0) continue;
        weights += t.weight[c] * faceCacheDaySkyWeights(t.texel[c], frame.dayLight);
        weight += t.weight[c];
    }
    if (weight <= 0.0) return light;
    vec3 bounce = vec3(0.0);
    float faceWeight = 0.0;
    for (int c = 0; c < 4; ++c) {
        if (faces.weight[c] <= 0.0) continue;
        bounce += faces.weight[c] * faceCacheDayBounce(faces.texel[c], frame.dayLight, zenith, horizon, frame.sunRadiance.rgb);
        faceWeight += faces.weight[c];
    }
    return light + (zenith * weights.y + horizon * weights.x) / weight + (faceWeight > 0.0 ? bounce / faceWeight : vec3(0.0));
}
