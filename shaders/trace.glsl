// Exact rays through the world's solid voxels (layout: shared/trace.h). The
// includer defines GROTTO_TRACE_BINDING: the trace constants sit at that binding,
// the tiles, bricks and masks buffers at the next three. With GROTTO_TRACE_OBJECTS
// the objects' grids follow at the fourth, and traceHit and traceShortRay stop at
// objects' voxels too.
#include "shared/trace.h"

// A storage buffer, not a uniform block: lavapipe (Mesa 22) inlines uniform values
// that steer branches into a shader variant compiled at dispatch time, and with
// these constants it compiled (and leaked) one for the shadow pass every frame.
layout(set = 0, binding = GROTTO_TRACE_BINDING, std430) readonly buffer Trace { TraceConstants trace; };
layout(set = 0, binding = GROTTO_TRACE_BINDING + 1, std430) readonly buffer Tiles { ivec4 tiles[]; };
layout(set = 0, binding = GROTTO_TRACE_BINDING + 2, std430) readonly buffer Bricks { uint brickSlots[]; };
layout(set = 0, binding = GROTTO_TRACE_BINDING + 3, std430) readonly buffer Masks { uint masks[]; };
#ifdef GROTTO_TRACE_OBJECTS
layout(set = 0, binding = GROTTO_TRACE_BINDING + 4, std430) readonly buffer ObjectGrids { uint objectBits[]; };
#endif

// The slot + 1 of a tile, 0 when it holds no solid voxel.
uint traceTile(ivec3 tile) {
    uint i = occupancyHash(tile.x, tile.y, tile.z) & trace.hashMask;
    for (uint probe = 0u; probe <= trace.hashMask; ++probe) {
        ivec4 e = tiles[i];
        if (e.w == 0 || e.xyz == tile) return uint(e.w);
        i = (i + 1u) & trace.hashMask;
    }
    return 0u;
}

// The last tile's and brick's lookups, reused while a ray stays in them.
ivec3 rayTileKey = ivec3(0x7fffffff), rayBrickKey = ivec3(0x7fffffff);
uint rayTile = 0u, rayBrick = 0u;

// What the exact traversal (shared/voxel_ray.h) asks of the occupancy: -1 for a
// solid voxel, else the size (log2) of the empty block holding it: its 64^3 tile,
// its 8^3 brick or the voxel alone.
int voxelRayBlock(ivec3 voxel) {
    ivec3 tileKey = voxel >> GROTTO_TILE_SHIFT;
    if (tileKey != rayTileKey) {
        rayTileKey = tileKey;
        rayTile = traceTile(tileKey);
        rayBrickKey = ivec3(0x7fffffff);
    }
    if (rayTile == 0u) return GROTTO_TILE_SHIFT;
    ivec3 brickKey = voxel >> 3;
    if (brickKey != rayBrickKey) {
        rayBrickKey = brickKey;
        rayBrick = brickSlots[(rayTile - 1u) * 512u + occupancyBrickEntry(brickKey.x, brickKey.y, brickKey.z)];
    }
    if (rayBrick == 0u) return 3;
    uint bit = occupancyBit(voxel.x, voxel.y, voxel.z);
    return ((masks[rayBrick * 16u + (bit >> 5u)] >> (bit & 31u)) & 1u) != 0u ? -1 : 0;
}

#include "shared/voxel_ray.h"

#ifdef GROTTO_TRACE_OBJECTS
// Where a ray from grid point g along gd (cells per unit of t) first enters a solid
// cell of a grid of `size` cells whose bits start at word `first`, within tMax; -1
// for none. A plain DDA: objects are small.
float objectGridHit(vec3 g, vec3 gd, ivec3 size, uint first, float tMax) {
    vec3 dir = mix(gd, vec3(1e-30), equal(gd, vec3(0.0)));
    vec3 inv = 1.0 / dir;
    vec3 t0 = -g * inv, t1 = (vec3(size) - g) * inv;
    vec3 tNear = min(t0, t1), tFar = max(t0, t1);
    float enter = max(max(tNear.x, tNear.y), max(tNear.z, 0.0));
    float leave = min(min(tFar.x, tFar.y), min(tFar.z, tMax));
    if (enter > leave) return -1.0;
    bvec3 up = greaterThan(dir, vec3(0.0));
    ivec3 stepI = mix(ivec3(-1), ivec3(1), up);
    ivec3 cell = clamp(ivec3(floor(g + gd * enter)), ivec3(0), size - 1);
    vec3 next = (vec3(cell) + mix(vec3(0.0), vec3(1.0), up) - g) * inv;  // t of the next cell boundary per axis
    vec3 across = abs(inv);
    float t = enter;
    for (int i = 0; i < 3 * 4096; ++i) {
        uint bit = uint((cell.x * size.y + cell.y) * size.z + cell.z);
        if (((objectBits[first + (bit >> 5u)] >> (bit & 31u)) & 1u) != 0u) return t;
        t = min(next.x, min(next.y, next.z));
        if (t > leave) return -1.0;
        int axis = next.x == t ? 0 : next.y == t ? 1 : 2;
        cell[axis] += stepI[axis];
        next[axis] += across[axis];
        if (cell[axis] < 0 || cell[axis] >= size[axis]) return -1.0;
    }
    return -1.0;
}

// Where a ray from `start` along the unit direction d (world voxels) first enters an
// object's solid voxel within tMax voxels; -1 for none.
float traceObjects(VoxelRayStart start, vec3 d, float tMax) {
    vec4 p = vec4(vec3(start.voxel - trace.cameraCell.xyz) + start.fraction, 1.0);
    float nearest = -1.0;
    for (int k = 0; k < trace.objectCount.x; ++k) {
        vec4 r0 = trace.objects[k].fromWorld[0], r1 = trace.objects[k].fromWorld[1], r2 = trace.objects[k].fromWorld[2];
        ivec4 size = trace.objects[k].size;
        float t = objectGridHit(vec3(dot(r0, p), dot(r1, p), dot(r2, p)), vec3(dot(r0.xyz, d), dot(r1.xyz, d), dot(r2.xyz, d)),
                                size.xyz, uint(size.w), nearest >= 0.0 ? nearest : tMax);
        if (t >= 0.0) nearest = t;
    }
    return nearest;
}

// Does the ray from p (voxels from the camera voxel's corner, w 1) along d, or any
// ray within a cone of half-angle atan(tanSpread) around it, pass within a cell of
// the grid of `size` cells that the rows r map p into? A slab test against the
// grid grown by a cell plus the cone's width at the grid's centre.
bool objectGridNear(vec4 p, vec3 d, vec4 r0, vec4 r1, vec4 r2, vec3 size, float tanSpread) {
    vec3 g = vec3(dot(r0, p), dot(r1, p), dot(r2, p)), gd = vec3(dot(r0.xyz, d), dot(r1.xyz, d), dot(r2.xyz, d));
    float grow = 1.0 + length(0.5 * size - g) * tanSpread;
    vec3 inv = 1.0 / mix(gd, vec3(1e-30), equal(gd, vec3(0.0)));
    vec3 t0 = (vec3(-grow) - g) * inv, t1 = (size + grow - g) * inv;
    vec3 tNear = min(t0, t1), tFar = max(t0, t1);
    return max(max(tNear.x, tNear.y), max(tNear.z, 0.0)) <= min(min(tFar.x, tFar.y), tFar.z);
}

// Do rays from `start` in that cone around d pass near an object, at its pose in
// this frame or the one before: where a moving object's shadow is or was.
bool traceNearObjects(VoxelRayStart start, vec3 d, float tanSpread) {
    vec4 p = vec4(vec3(start.voxel - trace.cameraCell.xyz) + start.fraction, 1.0);
    for (int k = 0; k < trace.objectCount.x; ++k) {
        vec3 size = vec3(trace.objects[k].size.xyz);
        if (objectGridNear(p, d, trace.objects[k].fromWorld[0], trace.objects[k].fromWorld[1], trace.objects[k].fromWorld[2],
                           size, tanSpread) ||
            objectGridNear(p, d, trace.objects[k].previousFromWorld[0], trace.objects[k].previousFromWorld[1],
                           trace.objects[k].previousFromWorld[2], size, tanSpread))
            return true;
    }
    return false;
}

// The sphere (centre xyz, radius w, in the rays' space: voxels from the camera
// voxel's corner) around the grid of `size` cells that the rows map into. The rows
// are a turn times the scale s from world voxels to the object's, so their
// transpose over s^2 maps back.
vec4 objectGridSphere(vec4 r0, vec4 r1, vec4 r2, vec3 size) {
    float s2 = dot(r0.xyz, r0.xyz);
    vec3 g = 0.5 * size;
    vec3 centre = (r0.xyz * (g.x - r0.w) + r1.xyz * (g.y - r1.w) + r2.xyz * (g.z - r2.w)) / s2;
    return vec4(centre, 0.5 * length(size) * inversesqrt(s2));
}
#endif

// The camera-relative view-space point of full-res pixel q whose depth buffer
// (D32, reverse-Z) holds `depth`.
vec3 traceViewPosition(ivec2 q, float depth) {
    float z = trace.depthAB.y / (depth + trace.depthAB.x);
    vec2 m = (vec2(q) + 0.5) * trace.ndcToViewMul_Add.xy + trace.ndcToViewMul_Add.zw;
    return vec3(m * z, -z);
}

// From a camera-relative view-space position. A world face (0..5: +X -X +Y -Y +Z -Z)
// puts the point on its voxel plane, trace.normalOffset in front of it, as the
// reference does, in the open voxel in front of the face (voxelRayOpenStart); for
// any other face (an object's, turned) pass face 6 and its world normal, and the
// point moves a hundredth of a voxel along it.
VoxelRayStart traceStart(vec3 viewPosition, uint face, vec3 worldNormal) {
    vec3 world = trace.viewToWorld[0].xyz * viewPosition.x + trace.viewToWorld[1].xyz * viewPosition.y +
                 trace.viewToWorld[2].xyz * viewPosition.z;
    vec3 p = world * trace.cameraFraction.w + trace.cameraFraction.xyz;  // voxels from the camera voxel's corner
    if (face >= 6u) p += worldNormal * 0.01;
    ivec3 cell = ivec3(floor(p));
    vec3 fraction = p - vec3(cell);
    if (face < 6u) {
        uint axis = face >> 1;
        int plane = int(round(p[axis]));
        bool positive = (face & 1u) == 0u;
        cell[axis] = positive ? plane : plane - 1;
        fraction[axis] = positive ? trace.normalOffset : 1.0 - trace.normalOffset;
    }
    VoxelRayStart s;
    s.voxel = trace.cameraCell.xyz + cell;
    s.fraction = clamp(fraction, vec3(0.0), vec3(1.0));
    return face < 6u ? voxelRayOpenStart(s, int(face >> 1)) : s;
}

// How deep the solid behind a world face runs along the view ray through a
// camera-relative view-space point on it, in world units, up to maxT: the ray
// starts in the solid voxel behind the face, a hair past its plane.
float traceThickness(vec3 viewPosition, uint face, float maxT) {
    vec3 world = trace.viewToWorld[0].xyz * viewPosition.x + trace.viewToWorld[1].xyz * viewPosition.y +
                 trace.viewToWorld[2].xyz * viewPosition.z;
    vec3 p = world * trace.cameraFraction.w + trace.cameraFraction.xyz;
    ivec3 cell = ivec3(floor(p));
    vec3 fraction = p - vec3(cell);
    uint axis = face >> 1;
    int plane = int(round(p[axis]));
    bool positive = (face & 1u) == 0u;
    cell[axis] = positive ? plane - 1 : plane;
    fraction[axis] = positive ? 1.0 - trace.normalOffset : trace.normalOffset;
    VoxelRayStart s;
    s.voxel = trace.cameraCell.xyz + cell;
    s.fraction = clamp(fraction, vec3(0.0), vec3(1.0));
    float voxels = voxelRayExit(s, normalize(world), maxT * trace.cameraFraction.w);
    return voxels / trace.cameraFraction.w;
}

// The solid world voxel a ray from `start` along the unit direction d enters within
// tMax voxels (t -1: none): the exact traversal (shared/voxel_ray.h), within the
// world's bounds. From a world face the start voxel is tested (it is the open one in
// front of the face); from an object's face it counts as open, as the reference's
// rule has it.
VoxelRayHit traceWorldHit(VoxelRayStart start, vec3 d, float tMax, bool openStart) {
    VoxelRayHit hit;
    hit.t = -1.0;
    hit.voxel = start.voxel;
    hit.face = -1;
    if (trace.boundsHi.w == 0) hit = voxelRay(start, d, tMax, trace.boundsLo.xyz, trace.boundsHi.xyz, openStart, 16384);
    return hit;
}

// traceWorldHit, and the objects' voxels where the pass sees them.
VoxelRayHit traceHit(VoxelRayStart start, vec3 d, float tMax, bool openStart) {
    VoxelRayHit hit = traceWorldHit(start, d, tMax, openStart);
#ifdef GROTTO_TRACE_OBJECTS
    float object = traceObjects(start, d, hit.t >= 0.0 ? hit.t : tMax);
    if (object >= 0.0) {  // an object's voxel, nearer: no world voxel or face to name
        hit.t = object;
        hit.face = -1;
    }
#endif
    return hit;
}

// traceHit's distance for short rays (AO's few voxels) through the world's voxels:
// an incremental DDA, one compare and one add per voxel, with no skipping of empty
// bricks, which short rays rarely cross.
float traceShortWorldRay(VoxelRayStart start, vec3 d, float tMax) {
    if (trace.boundsHi.w != 0) return -1.0;  // nothing solid
    vec3 dir = mix(d, vec3(1e-30), equal(d, vec3(0.0)));
    vec3 invAbs = 1.0 / abs(dir);
    bvec3 up = greaterThan(dir, vec3(0.0));
    ivec3 stepI = mix(ivec3(-1), ivec3(1), up);
    // Past the world's bounds nothing is solid: the ray ends where it leaves them,
    // so a radius of any length costs the world's size at most. The margin is wider
    // than the sums below can round (4096 steps), so a hit within them is unchanged.
    ivec3 ahead = mix(start.voxel - trace.boundsLo.xyz, trace.boundsHi.xyz + 1 - start.voxel, up);
    vec3 room = vec3(ahead) + mix(start.fraction, -start.fraction, up);
    for (int a = 0; a < 3; ++a)  // past them already, or beside them running along them: no hit
        if (room[a] < 0.0 || (d[a] == 0.0 && (start.voxel[a] < trace.boundsLo[a] || start.voxel[a] > trace.boundsHi[a])))
            return -1.0;
    vec3 leave = room * invAbs;
    float leaveT = min(leave.x, min(leave.y, leave.z));
    tMax = min(tMax, leaveT + 2.0 + 1e-3 * leaveT);
    // Distance to the first face crossed on each axis, then from face to face.
    vec3 next = mix(start.fraction, 1.0 - start.fraction, up) * invAbs;
    ivec3 cell = start.voxel;
    ivec3 cachedBrick = ivec3(0x7fffffff);
    uint brick = 0u;
    for (uint i = 0u; i < 4096u; ++i) {
        float entered = min(next.x, min(next.y, next.z));
        if (entered > tMax) return -1.0;
        bvec3 cross = lessThanEqual(next, min(next.yzx, next.zxy));
        cell += mix(ivec3(0), stepI, cross);
        next += mix(vec3(0.0), invAbs, cross);
        ivec3 brickKey = cell >> 3;
        if (brickKey != cachedBrick) {
            cachedBrick = brickKey;
            uint tile = traceTile(cell >> GROTTO_TILE_SHIFT);
            brick = tile == 0u ? 0u : brickSlots[(tile - 1u) * 512u + occupancyBrickEntry(brickKey.x, brickKey.y, brickKey.z)];
        }
        if (brick == 0u) continue;
        uint bit = occupancyBit(cell.x, cell.y, cell.z);
        if (((masks[brick * 16u + (bit >> 5u)] >> (bit & 31u)) & 1u) != 0u) return entered;
    }
    return -1.0;
}

// traceShortWorldRay, and the objects' voxels where the pass sees them.
float traceShortRay(VoxelRayStart start, vec3 d, float tMax) {
    float t = traceShortWorldRay(start, d, tMax);
#ifdef GROTTO_TRACE_OBJECTS
    float object = traceObjects(start, d, t >= 0.0 ? t : tMax);
    if (object >= 0.0) t = object;
#endif
    return t;
}

// Ray i of a cosine-weighted set about the unit normal n: the R2 point i, offset by
// the pixel's and frame's noise, uniform on the disk and lifted onto the hemisphere.
vec3 traceCosineRay(vec3 n, vec2 noise, uint i) {
    vec3 helper = abs(n.x) < 0.9 ? vec3(1.0, 0.0, 0.0) : vec3(0.0, 1.0, 0.0);
    vec3 tangent = normalize(cross(helper, n));
    vec3 bitangent = cross(n, tangent);
    float u = fract(noise.x + float(i) * 0.7548776662), a = fract(noise.y + float(i) * 0.5698402910);
    float r = sqrt(u), phi = a * 6.28318530718;
    return tangent * (r * cos(phi)) + bitangent * (r * sin(phi)) + n * sqrt(max(1.0 - u, 0.0));
}
