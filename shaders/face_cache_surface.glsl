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

// The light cached at that point. With GROTTO_FACE_REQUEST_BINDING (the
// composite), its texels' faces that have not converged are asked for too, for
// the next frame's tracer (face_cache_requests.glsl, included before this), by a
// quarter of the pixels each frame, and only while some face has not converged.
// `sunRange`: the least and most sun visibility of the texels read (a shadow edge
// crosses them where they differ).
vec4 cachedLightAt(ivec2 q, uint face, out bool found, out vec2 sunRange) {
    FaceCacheTaps t = faceCacheTaps(cachedPointAt(q, face), frame.cameraCell.xyz, face);
#ifdef GROTTO_FACE_REQUEST_BINDING
    // A pixel of each 2x2 block a frame, in turn: a face beside the view is read
    // by a strip of pixels, so it is asked for within a frame or a few all the same.
    if (faceHeader[GROTTO_FACE_UNCONVERGED] > 0u && (uint(q.x & 1) + 2u * uint(q.y & 1)) == (uint(frame.cameraCell.w) & 3u))
        for (int c = 0; c < 4; ++c)
            if (t.weight[c] > 0.0) requestFace(t.face[c], t.cell[c], face);
#endif
    return faceCacheBlend(t, found, sunRange);
}

vec4 cachedLightAt(ivec2 q, uint face, out bool found) {
    vec2 sunRange;
    return cachedLightAt(q, face, found, sunRange);
}

