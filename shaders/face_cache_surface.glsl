// The face cache read at a full-resolution pixel's world surface. The includer
// declares `depthBuffer` (full-res D32, reverse-Z), the trace constants as `trace`
// (shared/trace.h) and the cache (face_cache.glsl).

// The light cached where the pixel's view ray meets the voxel plane of world face
// `face` (0..5): the depth only picks the plane, the ray gives the point on it, so
// the point is exact to the plane whatever the depth buffer's precision.
vec4 cachedLightAt(ivec2 q, uint face, out bool found) {
    float z = trace.depthAB.y / (texelFetch(depthBuffer, q, 0).r + trace.depthAB.x);
    vec2 m = (vec2(q) + 0.5) * trace.ndcToViewMul_Add.xy + trace.ndcToViewMul_Add.zw;
    // The view ray at unit depth, in voxels from the camera voxel's corner.
    vec3 ray = (trace.viewToWorld[0].xyz * m.x + trace.viewToWorld[1].xyz * m.y - trace.viewToWorld[2].xyz) *
               trace.cameraFraction.w;
    vec3 start = trace.cameraFraction.xyz;
    vec3 p = start + ray * z;
    uint axis = faceAxis(face);
    float plane = round(p[axis]);
    if (abs(ray[axis]) > 1e-6 * abs(plane - start[axis])) p = start + ray * ((plane - start[axis]) / ray[axis]);
    p[axis] = plane;
    return faceCacheAt(p, trace.cameraCell.xyz, face, found);
}
