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

bool traceSolid(ivec3 cell) {
    uint tile = traceTile(cell >> GROTTO_TILE_SHIFT);
    if (tile == 0u) return false;
    uint brick = brickSlots[(tile - 1u) * 512u + occupancyBrickEntry(cell.x >> 3, cell.y >> 3, cell.z >> 3)];
    uint bit = occupancyBit(cell.x, cell.y, cell.z);
    return ((masks[brick * 16u + (bit >> 5u)] >> (bit & 31u)) & 1u) != 0u;
}

// A point on a surface, in voxel index space: the open voxel in front of the face
// and the position within it (0..1 on each axis).
struct TraceStart {
    ivec3 cell;
    vec3 fraction;
};

// From a camera-relative view-space position. A world face (0..5: +X -X +Y -Y +Z -Z)
// puts the point on its voxel plane, trace.normalOffset in front of it, as the
// reference does; for any other face (an object's, turned) pass face 6 and its
// world normal, and the point moves a hundredth of a voxel along it.
TraceStart traceStart(vec3 viewPosition, uint face, vec3 worldNormal) {
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
    TraceStart s;
    s.cell = trace.cameraCell.xyz + cell;
    s.fraction = clamp(fraction, vec3(0.0), vec3(1.0));
    return s;
}

// How far along the unit direction d a ray from `start` enters a solid voxel,
// or -1 when it enters none within tMax (voxels). The start voxel counts as open
// (the reference's rule). Exact cell by cell inside non-empty bricks; an empty
// brick or tile is crossed in one step.
float traceRay(TraceStart start, vec3 d, float tMax) {
    vec3 dir = mix(d, vec3(1e-30), equal(d, vec3(0.0)));  // no division by zero; moves toward +
    vec3 invD = 1.0 / dir;
    vec3 far = step(vec3(0.0), dir);  // the side of a box the ray leaves through
    vec3 o = start.fraction;
    float t = 0.0, entered = 0.0;
    // The last tile's and brick's lookups, reused while the ray stays in them.
    ivec3 cachedTile = ivec3(0x7fffffff), cachedBrick = ivec3(0x7fffffff);
    uint tile = 0u, brick = 0u;
    for (uint i = 0u; i < 16384u; ++i) {
        ivec3 rel = ivec3(floor(o + d * t));
        ivec3 cell = start.cell + rel;
        ivec3 tileKey = cell >> GROTTO_TILE_SHIFT;
        if (tileKey != cachedTile) {
            cachedTile = tileKey;
            tile = traceTile(tileKey);
            cachedBrick = ivec3(0x7fffffff);
        }
        int size = 1;
        ivec3 lo = cell;
        if (tile == 0u) {
            size = 1 << GROTTO_TILE_SHIFT;
            lo = tileKey << GROTTO_TILE_SHIFT;
        } else {
            ivec3 brickKey = cell >> 3;
            if (brickKey != cachedBrick) {
                cachedBrick = brickKey;
                brick = brickSlots[(tile - 1u) * 512u + occupancyBrickEntry(brickKey.x, brickKey.y, brickKey.z)];
            }
            if (brick == 0u) {
                size = 8;
                lo = brickKey << 3;
            } else if (rel != ivec3(0)) {  // the start voxel is never tested
                uint bit = occupancyBit(cell.x, cell.y, cell.z);
                if (((masks[brick * 16u + (bit >> 5u)] >> (bit & 31u)) & 1u) != 0u) return entered;
            }
        }
        vec3 exits = (vec3(lo - start.cell) + far * float(size) - o) * invD;
        float exitT = min(min(exits.x, exits.y), exits.z);
        if (exitT > tMax) return -1.0;
        entered = exitT;
        // A nudge past the face, larger than the rounding of o + d * t.
        t = exitT + 1e-4 + exitT * 5e-7;
    }
    return -1.0;
}

// traceRay for short rays (AO's few voxels): an incremental DDA, one compare and
// one add per voxel, with no skipping of empty bricks, which short rays rarely cross.
float traceShortRay(TraceStart start, vec3 d, float tMax) {
    vec3 dir = mix(d, vec3(1e-30), equal(d, vec3(0.0)));
    vec3 invAbs = 1.0 / abs(dir);
    bvec3 up = greaterThan(dir, vec3(0.0));
    ivec3 stepI = mix(ivec3(-1), ivec3(1), up);
    // Distance to the first face crossed on each axis, then from face to face.
    vec3 next = mix(start.fraction, 1.0 - start.fraction, up) * invAbs;
    ivec3 cell = start.cell;
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

// How far a ray from `start` runs before it leaves the world's solid bounds (voxels);
// 0 when the world is empty or the ray misses them.
float traceBoundsExit(TraceStart start, vec3 d) {
    if (trace.boundsHi.w != 0) return 0.0;
    vec3 dir = mix(d, vec3(1e-30), equal(d, vec3(0.0)));
    vec3 lo = vec3(trace.boundsLo.xyz - start.cell) - start.fraction;
    vec3 hi = vec3(trace.boundsHi.xyz + 1 - start.cell) - start.fraction;
    vec3 a = lo / dir, b = hi / dir;
    vec3 tFar = max(a, b);
    return max(min(min(tFar.x, tFar.y), tFar.z), 0.0);
}
