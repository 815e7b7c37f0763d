// The face cache read at a full-resolution pixel's world surface. The includer
// declares `depthBuffer` (full-res D32, reverse-Z), the frame uniforms as `frame`
// (shared/frame.h) and the cache (face_cache.glsl).

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

// The light cached at that point.
vec4 cachedLightAt(ivec2 q, uint face, out bool found) {
    vec2 sunRange;
    return faceCacheBlend(cachedTapsAt(q, face), found, sunRange);
}

