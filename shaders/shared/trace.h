// The world's solid voxels on the GPU, for exact rays (sun shadows, voxel-traced
// AO), and the per-frame constants of the passes that trace them. Shared by C++
// and GLSL.
//
// Three storage buffers (engine/scene/occupancy.h builds and updates them):
//   tiles:  an open-addressing hash table of the non-empty 64^3-voxel tiles, one
//           uvec4 per entry (x, y, z of the tile as ints, tile slot + 1; 0 = empty),
//           probed linearly from occupancyHash(tile) & hashMask;
//   bricks: per tile slot, 512 brick slots of its 8^3 bricks (bx * 64 + by * 8 + bz,
//           coordinates within the tile; 0 = an empty brick);
//   masks:  per brick slot, 512 bits in 16 uints, voxel x * 64 + y * 8 + z as in
//           OpenVDB's leaves; slot 0 is all empty.
// A tile is one hash probe per ray that enters it and an empty brick or tile is
// stepped over in one go, so a long shadow ray through open air costs little.
#ifndef GROTTO_SHARED_TRACE_H
#define GROTTO_SHARED_TRACE_H
#include "common.h"
#include "objects.h"

GROTTO_NAMESPACE_BEGIN

#define GROTTO_TILE_SHIFT 6
#define GROTTO_TRACE_GROUP 8u

GROTTO_INLINE uint occupancyHash(int x, int y, int z) {
    return (uint(x) * 73856093u) ^ (uint(y) * 19349663u) ^ (uint(z) * 83492791u);
}
GROTTO_INLINE uint occupancyBrickEntry(int bx, int by, int bz) {
    return (uint(bx & 7) << 6) | (uint(by & 7) << 3) | uint(bz & 7);
}
GROTTO_INLINE uint occupancyBit(int x, int y, int z) {
    return (uint(x & 7) << 6) | (uint(y & 7) << 3) | uint(z & 7);
}

// An object for rays (engine/scene/object_grids.h): its solid voxels are a dense
// grid of bits, cell (x, y, z) at bit (x * size.y + y) * size.z + z from the grid's
// first bit, and this frame's pose maps the rays' camera-relative world voxels
// into the grid's cells.
struct ObjectTrace {
    vec4 fromWorld[3];          // rows: cell = fromWorld * (voxels from the camera voxel's corner, 1)
    vec4 previousFromWorld[3];  // the same at the object's pose in the frame before
    ivec4 size;                 // xyz: cells per axis; w: the grid's first word in the object grids buffer
};
GROTTO_STATIC_ASSERT(sizeof(ObjectTrace) == 112);

// A glowing face of an object, as a light the object light pass samples
// (object_light.comp): a parallelogram in the rays' camera-relative world voxels.
#define GROTTO_MAX_GLOW_FACES 128u
struct GlowFace {
    vec4 corner;    // xyz: a corner
    vec4 edgeU;     // xyz: the edge along one side
    vec4 edgeV;     // xyz: the other; the face's outward normal is along cross(edgeU, edgeV)
    vec4 radiance;  // rgb: what it sends, the same in every direction
};
GROTTO_STATIC_ASSERT(sizeof(GlowFace) == 64);

struct TraceConstants {
    vec4 ndcToViewMul_Add;   // view xy = ((full-res pixel + 0.5) * mul + add) * view depth
    vec4 depthAB;            // x, y: view depth = y / (depth buffer value + x)
    vec4 viewToWorld[3];     // the camera's axes (right, up, back): view -> camera-relative world
    ivec4 cameraCell;        // xyz: the voxel holding the camera (index space)
    vec4 cameraFraction;     // xyz: the camera's position within that voxel, in voxels; w: 1 / voxel size
    ivec4 boundsLo;          // xyz: the world's solid voxels lie in [boundsLo, boundsHi]
    ivec4 boundsHi;          // w of boundsHi: 1 when the world has no solid voxel
    vec4 sunDirection;       // xyz: unit, toward the sun
    uint hashMask;           // tiles table entries - 1 (a power of two minus one)
    uint rays;               // voxel AO: rays per AO pixel per frame
    float radiusVoxels;      // voxel AO: ray length R in voxels
    float normalOffset;      // rays leave the surface this many voxels along its normal
    // A soft sun (shadow.comp built with GROTTO_SOFT_SUN): one jittered direction per
    // pixel and frame, accumulated in a full-res history reprojected like the AO's.
    mat4 currentToPrevious;         // current view space -> the shadow history's view space
    vec4 previousNdcToViewMul_Add;  // as ndcToViewMul_Add, for the history's camera
    float sunCosRadius;             // cos of the sun's angular radius (1: a point, hard shadows)
    uint frameIndex;                // turns the directions' noise per frame
    uint shadowHistory;             // the history's length cap, in frames
    uint shadowReset;               // bit 0: no usable history; bit 1: objects move (their pixels restart)
    // Objects block sun rays and voxel AO rays (passes built with GROTTO_TRACE_OBJECTS).
    ivec4 objectCount;              // x: the entries of `objects` in use; y: of `glow`
    ObjectTrace objects[GROTTO_MAX_OBJECTS];
    // With the face cache's full light (object_light.comp): the light objects take
    // from world faces, give them by glowing, and take themselves.
    uvec4 faceCache;                // x: the cache's table shape; y: texels per face side;
                                    // z: its faces' materials' first texel word; w: 1 with full light
    vec4 skyZenith, skyHorizon;     // rgb: the sky's radiance at the zenith and the horizon
    vec4 sunRadiance;               // rgb: the sun's light on a face turned to it (irradiance / pi)
    uvec4 dayLight;                 // full light over the day: FrameUniforms::dayLight
    uvec4 daySun;                   // the day's sun from the cache: FrameUniforms::daySun
    GlowFace glow[GROTTO_MAX_GLOW_FACES];
};
GROTTO_STATIC_ASSERT(sizeof(TraceConstants) == 2 * 16 + 3 * 16 + 5 * 16 + 16 + 64 + 16 + 16 + 16 +
                                                   112 * GROTTO_MAX_OBJECTS + 6 * 16 + 64 * GROTTO_MAX_GLOW_FACES);

GROTTO_NAMESPACE_END
#endif
