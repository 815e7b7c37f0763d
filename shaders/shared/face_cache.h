// The face cache as the GPU keeps it (voxel/face_cache.h has what a texel means),
// written once for GLSL and C++: the C++ side is the twin the tests hold the
// layout to. Three arrays:
//   bricks:  a hash table of the 8^3 bricks holding exposed faces, uvec4
//            (brick x, y, z, record + 1; 0 = free), probed linearly from
//            occupancyHash(brick) & hashMask;
//   records: per brick, 6 x 16 mask words (direction d's word w at d * 16 + w; bit
//            occupancyBit(voxel) set where that voxel's face looking d is exposed),
//            then 6 bases: the index of the direction's first face;
//   texels:  k x k per face (faces in record, direction, bit order; texel j * k + i),
//            one uint each: AO, sun visibility, and the horizon and zenith sky
//            weights per ray, 8-bit unorm from the low byte up.
// The includer defines, before including it (or GROTTO_FACE_CACHE_LAYOUT_ONLY):
//   uvec4 faceCacheBrickEntry(uint slot); uint faceCacheRecordWord(uint word);
//   uint faceCacheTexelWord(uint texel); uint faceCacheHashMask(); uint faceCacheK();
#ifndef GROTTO_SHARED_FACE_CACHE_H
#define GROTTO_SHARED_FACE_CACHE_H
#include "common.h"
#include "quad.h"
#include "trace.h"

#ifdef __cplusplus
#include <bit>
#include <cmath>
#define GROTTO_OUT(T) T&
#else
#define GROTTO_OUT(T) out T
#endif

GROTTO_NAMESPACE_BEGIN
#ifdef __cplusplus
using glm::ivec3;
using glm::uvec4;
inline int bitCount(uint v) { return std::popcount(v); }
using std::floor;
#endif

#define GROTTO_FACE_RECORD_WORDS 102u  // 6 x 16 mask words, then 6 bases
#ifndef GROTTO_FACE_CACHE_LAYOUT_ONLY  // the layout's builder needs the constants alone

// The record of the brick holding `cell`, + 1; 0 when it has no exposed face.
GROTTO_FUNCTION uint faceCacheRecord(ivec3 brick) {
    uint mask = faceCacheHashMask();
    for (uint i = occupancyHash(brick.x, brick.y, brick.z) & mask, n = 0u; n <= mask; i = (i + 1u) & mask, ++n) {
        uvec4 e = faceCacheBrickEntry(i);
        if (e.w == 0u) return 0u;
        if (int(e.x) == brick.x && int(e.y) == brick.y && int(e.z) == brick.z) return e.w;
    }
    return 0u;
}

// The index of the exposed face of `cell` looking `dir`, or -1 when it is not one.
GROTTO_FUNCTION int faceCacheFace(ivec3 cell, uint dir) {
    ivec3 brick = ivec3(cell.x >> 3, cell.y >> 3, cell.z >> 3);
    uint record = faceCacheRecord(brick);
    if (record == 0u) return -1;
    uint base = (record - 1u) * GROTTO_FACE_RECORD_WORDS;
    uint bit = occupancyBit(cell.x, cell.y, cell.z);
    uint word = faceCacheRecordWord(base + dir * 16u + (bit >> 5u));
    uint below = (1u << (bit & 31u)) - 1u;
    if (((word >> (bit & 31u)) & 1u) == 0u) return -1;
    uint index = faceCacheRecordWord(base + 96u + dir) + uint(bitCount(word & below));
    for (uint w = 0u; w < (bit >> 5u); ++w) index += uint(bitCount(faceCacheRecordWord(base + dir * 16u + w)));
    return int(index);
}

GROTTO_FUNCTION vec4 faceCacheUnpack(uint packed) {
    return vec4(float(packed & 255u), float((packed >> 8u) & 255u), float((packed >> 16u) & 255u),
                float(packed >> 24u)) / 255.0f;
}

// AO, sun visibility and the two sky weights at point `p` (voxel index units,
// camera-relative whole voxels removed is fine as long as `origin` restores them:
// p + origin is the absolute voxel position) on the plane of a face looking `dir`:
// the four nearest texel centres bilinearly, across coplanar exposed faces,
// reweighted where some are missing. `found`: false where none is.
GROTTO_FUNCTION vec4 faceCacheAt(vec3 p, ivec3 origin, uint dir, GROTTO_OUT(bool) found) {
    uint k = faceCacheK();
    uint axis = faceAxis(dir), ua = faceUAxis(dir), va = faceVAxis(dir);
    int plane = int(floor(p[axis] + 0.5f)) + origin[axis];
    ivec3 cell = origin;
    cell[axis] = facePositive(dir) ? plane - 1 : plane;
    float su = p[ua] * float(k) - 0.5f, sv = p[va] * float(k) - 0.5f;
    float fu = floor(su), fv = floor(sv);
    float wu = su - fu, wv = sv - fv;
    vec4 sum = vec4(0.0f);
    float weight = 0.0f;
    for (int c = 0; c < 4; ++c) {
        int I = int(fu) + (c & 1) + origin[ua] * int(k), J = int(fv) + (c >> 1) + origin[va] * int(k);
        float w = ((c & 1) != 0 ? wu : 1.0f - wu) * ((c >> 1) != 0 ? wv : 1.0f - wv);
        if (w <= 0.0f) continue;
        // Floor division: texel I lies on the face of cell floor(I / k).
        int cu = I >= 0 ? I / int(k) : -((-I + int(k) - 1) / int(k));
        int cv = J >= 0 ? J / int(k) : -((-J + int(k) - 1) / int(k));
        ivec3 q = cell;
        q[ua] = cu;
        q[va] = cv;
        int face = faceCacheFace(q, dir);
        if (face < 0) continue;
        uint texel = uint(face) * k * k + uint(J - cv * int(k)) * k + uint(I - cu * int(k));
        sum += w * faceCacheUnpack(faceCacheTexelWord(texel));
        weight += w;
    }
    found = weight > 0.0f;
    return found ? sum / weight : vec4(1.0f, 1.0f, 0.0f, 0.0f);
}

#endif  // GROTTO_FACE_CACHE_LAYOUT_ONLY
GROTTO_NAMESPACE_END
#endif
