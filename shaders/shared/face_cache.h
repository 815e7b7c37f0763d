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
//            3 bytes each, packed one after another into uints (texel t at bytes
//            3t .. 3t + 2, little-endian): from bit 0 up, AO as an 8-bit unorm,
//            sun visibility as 5 bits, and the horizon and zenith sky weights per
//            ray as 5 and 6 bits (zenith light is most of an open floor's).
// The includer defines, before including it (or GROTTO_FACE_CACHE_LAYOUT_ONLY):
//   uvec4 faceCacheBrickEntry(uint slot); uint faceCacheRecordWord(uint word);
//   uint faceCacheTexelWord(uint word); uint faceCacheHashMask(); uint faceCacheK();
#ifndef GROTTO_SHARED_FACE_CACHE_H
#define GROTTO_SHARED_FACE_CACHE_H
#include "common.h"
#include "quad.h"
#include "trace.h"

#ifdef __cplusplus
#include <algorithm>
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
using std::max;
using std::min;
#endif

#define GROTTO_FACE_RECORD_WORDS 102u  // 6 x 16 mask words, then 6 bases
#define GROTTO_FACE_TEXEL_BYTES 3u
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

// The index of the exposed face of `cell` looking `dir` in brick record `record`
// (faceCacheRecord's), or -1 when it is not one.
GROTTO_FUNCTION int faceCacheFaceIn(uint record, ivec3 cell, uint dir) {
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

// The index of the exposed face of `cell` looking `dir`, or -1 when it is not one.
GROTTO_FUNCTION int faceCacheFace(ivec3 cell, uint dir) {
    return faceCacheFaceIn(faceCacheRecord(ivec3(cell.x >> 3, cell.y >> 3, cell.z >> 3)), cell, dir);
}

// Floor division by k > 0.
GROTTO_FUNCTION int faceCacheFloorDiv(int i, int k) { return i >= 0 ? i / k : -((-i + k - 1) / k); }

// Texel `texel`'s 24 bits.
GROTTO_FUNCTION uint faceCacheTexel(uint texel) {
    uint byte = GROTTO_FACE_TEXEL_BYTES * texel, shift = (byte & 3u) * 8u;
    uint bits = faceCacheTexelWord(byte >> 2u) >> shift;
    if (shift > 8u) bits |= faceCacheTexelWord((byte >> 2u) + 1u) << (32u - shift);
    return bits & 0xFFFFFFu;
}

GROTTO_FUNCTION vec4 faceCacheUnpack(uint bits) {
    return vec4(float(bits & 255u) / 255.0f, float((bits >> 8u) & 31u) / 31.0f, float((bits >> 13u) & 31u) / 31.0f,
                float(bits >> 18u) / 63.0f);
}

// The texels a point reads: the four texel centres nearest to it on its face
// plane, each with its face's index (-1: no exposed face there) and cell, the
// texel's index and its bilinear weight (0 where the face is missing).
struct FaceCacheTaps {
    int face[4];
    ivec3 cell[4];
    uint texel[4];
    float weight[4];
};

// The taps at point `p` (voxel index units, camera-relative whole voxels removed is
// fine as long as `origin` restores them: p + origin is the absolute voxel
// position) on the plane of a face looking `dir`, across coplanar exposed faces.
GROTTO_FUNCTION FaceCacheTaps faceCacheTaps(vec3 p, ivec3 origin, uint dir) {
    int k = int(faceCacheK());
    uint axis = faceAxis(dir), ua = faceUAxis(dir), va = faceVAxis(dir);
    int plane = int(floor(p[axis] + 0.5f)) + origin[axis];
    ivec3 cell = origin;
    cell[axis] = facePositive(dir) ? plane - 1 : plane;
    float su = p[ua] * float(k) - 0.5f, sv = p[va] * float(k) - 0.5f;
    float fu = floor(su), fv = floor(sv);
    float wu = su - fu, wv = sv - fv;
    // The four centres' texel columns and rows, and the faces they lie on: one to
    // four, most often one or two, each looked up once (and its brick once).
    int I0 = int(fu) + origin[ua] * k, J0 = int(fv) + origin[va] * k;
    int cu0 = faceCacheFloorDiv(I0, k), cu1 = faceCacheFloorDiv(I0 + 1, k);
    int cv0 = faceCacheFloorDiv(J0, k), cv1 = faceCacheFloorDiv(J0 + 1, k);
    FaceCacheTaps t;
    ivec3 q = cell;
    q[ua] = cu0;
    q[va] = cv0;
    ivec3 brick = ivec3(q.x >> 3, q.y >> 3, q.z >> 3);
    uint record = faceCacheRecord(brick);
    t.face[0] = faceCacheFaceIn(record, q, dir);
    t.cell[0] = q;
    for (int c = 1; c < 4; ++c) {
        int cu = (c & 1) != 0 ? cu1 : cu0, cv = (c >> 1) != 0 ? cv1 : cv0;
        q[ua] = cu;
        q[va] = cv;
        t.cell[c] = q;
        if (cu == cu0 && cv == cv0) { t.face[c] = t.face[0]; continue; }
        if (c == 3 && cu1 == cu0) { t.face[3] = t.face[2]; continue; }
        if (c == 3 && cv1 == cv0) { t.face[3] = t.face[1]; continue; }
        ivec3 b = ivec3(q.x >> 3, q.y >> 3, q.z >> 3);
        if (b.x != brick.x || b.y != brick.y || b.z != brick.z) {
            brick = b;
            record = faceCacheRecord(brick);
        }
        t.face[c] = faceCacheFaceIn(record, q, dir);
    }
    for (int c = 0; c < 4; ++c) {
        float w = ((c & 1) != 0 ? wu : 1.0f - wu) * ((c >> 1) != 0 ? wv : 1.0f - wv);
        t.weight[c] = t.face[c] < 0 ? 0.0f : w;
        int I = I0 + (c & 1), J = J0 + (c >> 1);
        int cu = (c & 1) != 0 ? cu1 : cu0, cv = (c >> 1) != 0 ? cv1 : cv0;
        t.texel[c] = t.face[c] < 0 ? 0u : uint(t.face[c]) * uint(k * k) + uint(J - cv * k) * uint(k) + uint(I - cu * k);
    }
    return t;
}

// AO, sun visibility and the two sky weights at point `p` (as faceCacheTaps),
// blended; `found`: false where no tap has a face.
// The taps blended bilinearly, reweighted where some are missing; `sunRange`: the
// least and the most sun visibility among them.
GROTTO_FUNCTION vec4 faceCacheBlend(FaceCacheTaps t, GROTTO_OUT(bool) found, GROTTO_OUT(vec2) sunRange) {
    vec4 sum = vec4(0.0f);
    float weight = 0.0f;
    sunRange = vec2(1.0f, 0.0f);
    for (int c = 0; c < 4; ++c) {
        if (t.weight[c] <= 0.0f) continue;
        vec4 v = faceCacheUnpack(faceCacheTexel(t.texel[c]));
        sum += t.weight[c] * v;
        weight += t.weight[c];
        sunRange = vec2(min(sunRange.x, v.y), max(sunRange.y, v.y));
    }
    found = weight > 0.0f;
    return found ? sum / weight : vec4(1.0f, 1.0f, 0.0f, 0.0f);
}

GROTTO_FUNCTION vec4 faceCacheAt(vec3 p, ivec3 origin, uint dir, GROTTO_OUT(bool) found) {
    vec2 sunRange;
    return faceCacheBlend(faceCacheTaps(p, origin, dir), found, sunRange);
}

#endif  // GROTTO_FACE_CACHE_LAYOUT_ONLY
GROTTO_NAMESPACE_END
#endif
