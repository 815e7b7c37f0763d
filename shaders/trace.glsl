// Exact rays through the world's solid voxels (layout: shared/trace.h). The
// includer defines GROTTO_TRACE_BINDING: the trace constants sit at that binding,
// the tiles, bricks and masks buffers at the next three.
#include "shared/trace.h"

// A storage buffer, not a uniform block: lavapipe (Mesa 22) inlines uniform values
// that steer branches into a shader variant compiled at dispatch time, and with
// these constants it compiled (and leaked) one for the shadow pass every frame.
layout(set = 0, binding = GROTTO_TRACE_BINDING, std430) readonly buffer Trace { TraceConstants trace; };
layout(set = 0, binding = GROTTO_TRACE_BINDING + 1, std430) readonly buffer Tiles { ivec4 tiles[]; };
layout(set = 0, binding = GROTTO_TRACE_BINDING + 2, std430) readonly buffer Bricks { uint brickSlots[]; };
layout(set = 0, binding = GROTTO_TRACE_BINDING + 3, std430) readonly buffer Masks { uint masks[]; };

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

// The solid voxel a ray from `start` along the unit direction d enters within tMax
// voxels (t -1: none): the exact traversal (shared/voxel_ray.h), within the world's
// bounds. From a world face the start voxel is tested (it is the open one in front
// of the face); from an object's face it counts as open, as the reference's rule
// has it.
VoxelRayHit traceHit(VoxelRayStart start, vec3 d, float tMax, bool openStart) {
    if (trace.boundsHi.w != 0) {
        VoxelRayHit none;
        none.t = -1.0;
        none.voxel = start.voxel;
        none.face = -1;
        return none;
    }
    return voxelRay(start, d, tMax, trace.boundsLo.xyz, trace.boundsHi.xyz, openStart, 16384);
}

// traceRay for short rays (AO's few voxels): an incremental DDA, one compare and
// one add per voxel, with no skipping of empty bricks, which short rays rarely cross.
float traceShortRay(VoxelRayStart start, vec3 d, float tMax) {
    vec3 dir = mix(d, vec3(1e-30), equal(d, vec3(0.0)));
    vec3 invAbs = 1.0 / abs(dir);
    bvec3 up = greaterThan(dir, vec3(0.0));
    ivec3 stepI = mix(ivec3(-1), ivec3(1), up);
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
