// A full-res pixel's surface for the passes that trace from it: its world normal
// and its camera-relative view-space point. The includer declares `depthBuffer`
// (full-res D32, reverse-Z), `objects` (shared/objects.h) and `trace` (trace.glsl).

// A world face's axis exactly; an object's face turned with it.
vec3 surfaceWorldNormal(uint surface) {
    if (surfaceObject(surface) != 0u) return objects.worldNormals[surfaceKey(surface) - 1u].xyz;
    uint face = surfaceFace(surface);
    vec3 normal = vec3(0.0);
    normal[faceAxis(face)] = facePositive(face) ? 1.0 : -1.0;
    return normal;
}

vec3 surfaceViewPosition(ivec2 q) {
    float z = trace.depthAB.y / (texelFetch(depthBuffer, q, 0).r + trace.depthAB.x);
    vec2 m = (vec2(q) + 0.5) * trace.ndcToViewMul_Add.xy + trace.ndcToViewMul_Add.zw;
    return vec3(m * z, -z);
}

// Where rays from the pixel's surface start (trace.glsl's traceStart).
VoxelRayStart surfaceRayStart(vec3 position, uint surface, vec3 normal) {
    return traceStart(position, surfaceObject(surface) == 0u ? surfaceFace(surface) : 6u, normal);
}
