// A full-res pixel's surface for the passes that trace from it: its world normal
// and its camera-relative view-space point. The includer declares `depthBuffer`
// (full-res D32, reverse-Z), `objects` (shared/objects.h) and `trace` (trace.glsl).

// A world face's axis exactly; an object's face turned with it.
vec3 surfaceWorldNormal(uint surface) {
    if (surfaceObject(surface) != 0u) return objects.worldNormals[surfaceKey(surface) - 1u].xyz;
    return faceAxisNormal(surfaceFace(surface));
}

vec3 surfaceViewPosition(ivec2 q) { return traceViewPosition(q, texelFetch(depthBuffer, q, 0).r); }

// Where rays from the pixel's surface start (trace.glsl's traceStart).
VoxelRayStart surfaceRayStart(vec3 position, uint surface, vec3 normal) {
    return traceStart(position, surfaceObject(surface) == 0u ? surfaceFace(surface) : 6u, normal);
}
