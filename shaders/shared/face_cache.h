// The face cache as the GPU keeps it (voxel/face_cache.h has what a texel means),
// written once for GLSL and C++: the C++ side is the twin the tests hold the
// layout to. Three arrays:
//   bricks:  a perfect hash of the 8^3 bricks holding exposed faces ("hash and
//            displace"), uvec4 slots (brick x, y, z, record + 1; 0 = free). A
//            brick's bucket picks a seed (the records' first words), and the seed
//            its one slot: a read is two loads and no probing, whether the brick
//            is there or not (voxel/face_brick_table.h finds the seeds);
//   records: a seed per bucket, then per brick, 6 x 16 mask words (direction d's word w at d * 16 + w; bit
//            occupancyBit(voxel) set where that voxel's face looking d is exposed),
//            then 6 bases: the index of the direction's first face, then 2 words
//            of the faces in each direction's first 8 mask words, 9 bits each
//            (directions 0-2, then 3-5), so a face's index counts at most 7 words;
//   texels:  k x k per face (faces in record, direction, bit order; texel j * k + i),
//            6 bytes each, in pairs of three words: the two texels' light words,
//            then a word of their AO and sun halves (the even texel's low). The
//            half: AO and sun visibility as 8-bit unorms. The light word: with
//            sky light, the horizon and zenith sky weights per ray as two halfs
//            (a float's range, so a texel that sees a sliver of sky keeps it);
//            with full light, the texel's light (irradiance over pi) as RGB9E5,
//            three 9-bit mantissas sharing a 5-bit exponent.
//            A cache baked for the day's moving sun has a word more a texel after
//            them (faceCacheDaySun): a bit for each of 32 sun positions along the day.
//            With full light over the day (faceCacheDayLight) the light word holds
//            the glowing faces' light alone; after the words above come each
//            texel's sky weights (two halfs), then GROTTO_DAY_LIGHT_WORDS RGB9E5
//            words a face: its bounced light of a white zenith and horizon sky and
//            of a white sun at each of the day's bounce positions.
// The includer defines, before including it (or GROTTO_FACE_CACHE_LAYOUT_ONLY):
//   uvec4 faceCacheBrickEntry(uint slot); uint faceCacheRecordWord(uint word);
//   uint faceCacheTexelWord(uint word); uint faceCacheK(); and
//   uint faceCacheTable(): the bricks' table, its slots << 5 | log2(its buckets).
#ifndef GROTTO_SHARED_FACE_CACHE_H
#define GROTTO_SHARED_FACE_CACHE_H
#include "common.h"
#include "quad.h"
#include "trace.h"

#ifdef __cplusplus
#include <glm/common.hpp>
#include <glm/gtc/packing.hpp>

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
using glm::uvec3;
using glm::uvec4;
inline vec2 unpackHalf2x16(uint v) { return glm::unpackHalf2x16(v); }
inline float exp2(float v) { return std::exp2(v); }
inline float log2(float v) { return std::log2(v); }
inline int bitCount(uint v) { return std::popcount(v); }
inline float uintBitsToFloat(uint v) { return std::bit_cast<float>(v); }
using glm::mix;
inline int findLSB(int v) { return std::countr_zero(uint(v)); }
using std::clamp;
using std::floor;
using std::max;
using std::min;
#endif

#define GROTTO_FACE_RECORD_WORDS 104u  // 6 x 16 mask words, 6 bases, 2 words of half counts
#define GROTTO_FACE_TEXEL_BYTES 6u
#define GROTTO_DAY_SUN_POSITIONS 32u  // voxel::kDaySunPositions
#define GROTTO_DAY_LIGHT_WORDS 18u  // voxel::kDayLightWords: 2 skies and 16 bounce positions

// The words `texels` texels take.
GROTTO_INLINE uint faceCacheTexelWords(uint texels) { return 3u * ((texels + 1u) / 2u); }

// RGB9E5 (as Vulkan's E5B9G9R9): non-negative RGB to 32 bits and back, relative
// precision 1/512 of the largest channel, up to 65408.
GROTTO_FUNCTION uint faceCacheEncodeLight(vec3 c) {
    float top = max(max(c.x, c.y), c.z);
    if (!(top > 1.0e-20f)) return 0u;  // NaN and nothing read 0
    top = min(top, 65408.0f);
    int e = max(-16, int(floor(log2(top)))) + 1;  // 2^(e-1) <= top < 2^e
    float scale = exp2(float(9 - e));
    if (uint(floor(top * scale + 0.5f)) > 511u) scale *= 0.5f, e += 1;
    uvec3 m = uvec3(floor(min(max(c, vec3(0.0f)), vec3(65408.0f)) * scale + 0.5f));
    m = min(m, uvec3(511u));
    return m.x | (m.y << 9u) | (m.z << 18u) | (uint(e + 15) << 27u);
}
GROTTO_FUNCTION vec3 faceCacheDecodeLight(uint bits) {
    float scale = exp2(float(int(bits >> 27u) - 15 - 9));
    return vec3(float(bits & 511u), float((bits >> 9u) & 511u), float((bits >> 18u) & 511u)) * scale;
}

// A 32-bit mix (a bijection), so neighbouring bricks scatter over the table.
GROTTO_INLINE uint faceCacheMix(uint v) {
    v ^= v >> 16u;
    v *= 0x7feb352du;
    v ^= v >> 15u;
    v *= 0x846ca68bu;
    return v ^ (v >> 16u);
}

// The bucket of `brick` among bucketMask + 1.
GROTTO_INLINE uint faceCacheBucket(int x, int y, int z, uint bucketMask) {
    return faceCacheMix(occupancyHash(x, y, z)) & bucketMask;
}

// The high 32 bits of a * b, in 32-bit products (a GPU's 64-bit product costs far more).
GROTTO_INLINE uint faceCacheMulHigh(uint a, uint b) {
    uint low = (a & 0xFFFFu) * (b & 0xFFFFu);
    uint mid = (a >> 16u) * (b & 0xFFFFu) + (low >> 16u);
    uint mid2 = (a & 0xFFFFu) * (b >> 16u) + (mid & 0xFFFFu);
    return (a >> 16u) * (b >> 16u) + (mid >> 16u) + (mid2 >> 16u);
}

// The slot of `brick` among `slots` under `seed`. The seed enters first and each
// coordinate after it through a bijection, so two bricks land together only by
// the seed's chance, never for every seed.
GROTTO_INLINE uint faceCacheSlot(int x, int y, int z, uint seed, uint slots) {
    uint h = (uint(x) ^ seed) * 0x9E3779B1u;
    h ^= h >> 16u;
    h = (h ^ uint(y)) * 0x85EBCA77u;
    h ^= h >> 13u;
    h = (h ^ uint(z)) * 0xC2B2AE3Du;
    return faceCacheMulHigh(h ^ (h >> 16u), slots);
}
#ifndef GROTTO_FACE_CACHE_LAYOUT_ONLY  // the layout's builder needs the constants alone

// The record of the brick holding `cell`, + 1; 0 when it has no exposed face.
GROTTO_FUNCTION uint faceCacheRecord(ivec3 brick) {
    uint table = faceCacheTable();
    uint seed = faceCacheRecordWord(faceCacheBucket(brick.x, brick.y, brick.z, (1u << (table & 31u)) - 1u));
    uvec4 e = faceCacheBrickEntry(faceCacheSlot(brick.x, brick.y, brick.z, seed, table >> 5u));
    return int(e.x) == brick.x && int(e.y) == brick.y && int(e.z) == brick.z ? e.w : 0u;
}

// Record `record`'s first word (faceCacheRecord's, > 0): after the seeds.
GROTTO_FUNCTION uint faceCacheRecordBase(uint record) {
    return (1u << (faceCacheTable() & 31u)) + (record - 1u) * GROTTO_FACE_RECORD_WORDS;
}

// The faces looking `dir` before bit `bit` of the record at `base`: the index
// that bit's face has, or would have.
GROTTO_FUNCTION uint faceCacheRank(uint base, uint dir, uint bit) {
    uint index = faceCacheRecordWord(base + 96u + dir);
    // In the second half, the first half's count; then the own half's words before.
    uint from = (bit >> 5u) & 8u;
    if (from != 0u) index += (faceCacheRecordWord(base + 102u + dir / 3u) >> (dir % 3u * 9u)) & 511u;
    for (uint w = from; w < (bit >> 5u); ++w) index += uint(bitCount(faceCacheRecordWord(base + dir * 16u + w)));
    uint below = (1u << (bit & 31u)) - 1u;
    return index + uint(bitCount(faceCacheRecordWord(base + dir * 16u + (bit >> 5u)) & below));
}

// The index of the exposed face of `cell` looking `dir` in brick record `record`
// (faceCacheRecord's), or -1 when it is not one.
GROTTO_FUNCTION int faceCacheFaceIn(uint record, ivec3 cell, uint dir) {
    if (record == 0u) return -1;
    uint base = faceCacheRecordBase(record);
    uint bit = occupancyBit(cell.x, cell.y, cell.z);
    if (((faceCacheRecordWord(base + dir * 16u + (bit >> 5u)) >> (bit & 31u)) & 1u) == 0u) return -1;
    return int(faceCacheRank(base, dir, bit));
}

// The index of the exposed face of `cell` looking `dir`, or -1 when it is not one.
GROTTO_FUNCTION int faceCacheFace(ivec3 cell, uint dir) {
    return faceCacheFaceIn(faceCacheRecord(ivec3(cell.x >> 3, cell.y >> 3, cell.z >> 3)), cell, dir);
}

// Floor division by k > 0.
GROTTO_FUNCTION int faceCacheFloorDiv(int i, int k) { return i >= 0 ? i / k : -((-i + k - 1) / k); }

// Texel `texel`: x its AO and sun half (16 bits), y its light word.
GROTTO_FUNCTION uvec2 faceCacheTexel(uint texel) {
    uint pair = 3u * (texel >> 1u), odd = texel & 1u;
    return uvec2((faceCacheTexelWord(pair + 2u) >> (16u * odd)) & 0xFFFFu, faceCacheTexelWord(pair + odd));
}

// AO, sun visibility, and the horizon and zenith weights (with sky light).
GROTTO_FUNCTION vec4 faceCacheUnpack(uvec2 bits) {
    vec2 sky = unpackHalf2x16(bits.y);
    return vec4(float(bits.x & 255u) / 255.0f, float(bits.x >> 8u) / 255.0f, sky.x, sky.y);
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
// At k texels a side (faceCacheTaps: the cache's k; 1: the four faces whose
// centres are nearest, each tap's texel then its face).
GROTTO_FUNCTION FaceCacheTaps faceCacheTapsAtK(vec3 p, ivec3 origin, uint dir, int k) {
    uint axis = faceAxis(dir), ua = faceUAxis(dir), va = faceVAxis(dir);
    int plane = int(floor(p[axis] + 0.5f)) + origin[axis];
    ivec3 cell = origin;
    cell[axis] = facePositive(dir) ? plane - 1 : plane;
    float su = p[ua] * float(k) - 0.5f, sv = p[va] * float(k) - 0.5f;
    float fu = floor(su), fv = floor(sv);
    float wu = su - fu, wv = sv - fv;
    // The four centres' texel columns and rows, and the cells they lie on: one to four.
    int I0 = int(fu) + origin[ua] * k, J0 = int(fv) + origin[va] * k;
    int cu0 = faceCacheFloorDiv(I0, k), cu1 = faceCacheFloorDiv(I0 + 1, k);
    int cv0 = faceCacheFloorDiv(J0, k), cv1 = faceCacheFloorDiv(J0 + 1, k);
    FaceCacheTaps t;
    for (int c = 0; c < 4; ++c) {
        t.cell[c] = cell;
        t.cell[c][ua] = (c & 1) != 0 ? cu1 : cu0;
        t.cell[c][va] = (c >> 1) != 0 ? cv1 : cv0;
    }
    // The first cell's brick holds the others but near its sides. There, a cell
    // one further along u or v is 1, 8 or 64 bits further on in the same mask, so
    // the first cell's rank and the four mask words from its own count them all.
    ivec3 brick = ivec3(t.cell[0].x >> 3, t.cell[0].y >> 3, t.cell[0].z >> 3);
    uint record = faceCacheRecord(brick);
    uint bit0 = occupancyBit(t.cell[0].x, t.cell[0].y, t.cell[0].z);
    uint rank0 = 0u;
    uvec4 words = uvec4(0u);
    if (record != 0u) {
        uint base = faceCacheRecordBase(record), first = base + dir * 16u + (bit0 >> 5u);  // within the record
        rank0 = faceCacheRank(base, dir, bit0);
        words = uvec4(faceCacheRecordWord(first), faceCacheRecordWord(first + 1u), faceCacheRecordWord(first + 2u),
                      faceCacheRecordWord(first + 3u));
    }
    uint start = bit0 & 31u;
    int elsewhere = 0;  // bit c: cell c is in another brick
    for (int c = 0; c < 4; ++c) {
        ivec3 q = t.cell[c];
        if ((q.x >> 3) != brick.x || (q.y >> 3) != brick.y || (q.z >> 3) != brick.z) {
            elsewhere |= 1 << c;
            continue;
        }
        // Bit `at` of the four words from bit0's (at most 31 + 64 + 8 = 103).
        uint at = start + occupancyBit(q.x, q.y, q.z) - bit0;
        uint j = at >> 5u;
        uint word = j == 0u ? words.x : j == 1u ? words.y : j == 2u ? words.z : words.w;
        uint between = uint(bitCount(word & ((1u << (at & 31u)) - 1u))) - uint(bitCount(words.x & ((1u << start) - 1u)));
        between += j > 0u ? uint(bitCount(words.x)) : 0u;
        between += j > 1u ? uint(bitCount(words.y)) : 0u;
        between += j > 2u ? uint(bitCount(words.z)) : 0u;
        t.face[c] = ((word >> (at & 31u)) & 1u) != 0u ? int(rank0 + between) : -1;
    }
    // Those in other bricks, looked up whole: a loop that most groups of pixels skip.
    for (int m = elsewhere; m != 0; m &= m - 1) {
        int c = findLSB(m);
        t.face[c] = faceCacheFace(t.cell[c], dir);
    }
    for (int c = 0; c < 4; ++c) {
        float w = ((c & 1) != 0 ? wu : 1.0f - wu) * ((c >> 1) != 0 ? wv : 1.0f - wv);
        t.weight[c] = t.face[c] < 0 ? 0.0f : w;
        int I = I0 + (c & 1), J = J0 + (c >> 1);
        int cu = t.cell[c][ua], cv = t.cell[c][va];
        t.texel[c] = t.face[c] < 0 ? 0u : uint(t.face[c]) * uint(k * k) + uint(J - cv * k) * uint(k) + uint(I - cu * k);
    }
    return t;
}
GROTTO_FUNCTION FaceCacheTaps faceCacheTaps(vec3 p, ivec3 origin, uint dir) {
    return faceCacheTapsAtK(p, origin, dir, int(faceCacheK()));
}

// The taps at `p` on the texels (k a side), and in `faces` those on the four faces
// whose centres are nearest (faceCacheTapsAtK at 1), from one look-up: the texels'
// cells always lie among the faces' (a texel centre is less than half a voxel from
// the point, so its cell is the point's or its neighbour towards the nearest
// face centres), so each texel takes its face from there.
GROTTO_FUNCTION FaceCacheTaps faceCacheTapsWithFaces(vec3 p, ivec3 origin, uint dir, int k, GROTTO_OUT(FaceCacheTaps) faces) {
    faces = faceCacheTapsAtK(p, origin, dir, 1);
    uint ua = faceUAxis(dir), va = faceVAxis(dir);
    float su = p[ua] * float(k) - 0.5f, sv = p[va] * float(k) - 0.5f;
    float fu = floor(su), fv = floor(sv);
    float wu = su - fu, wv = sv - fv;
    int I0 = int(fu) + origin[ua] * k, J0 = int(fv) + origin[va] * k;
    FaceCacheTaps t;
    for (int c = 0; c < 4; ++c) {
        int I = I0 + (c & 1), J = J0 + (c >> 1);
        int cu = faceCacheFloorDiv(I, k), cv = faceCacheFloorDiv(J, k);
        int at = clamp(cu - faces.cell[0][ua], 0, 1) + 2 * clamp(cv - faces.cell[0][va], 0, 1);
        t.cell[c] = faces.cell[at];
        t.face[c] = faces.face[at];
        float w = ((c & 1) != 0 ? wu : 1.0f - wu) * ((c >> 1) != 0 ? wv : 1.0f - wv);
        t.weight[c] = t.face[c] < 0 ? 0.0f : w;
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

// With full light: the texels' light (irradiance over pi), blended as faceCacheBlend.
GROTTO_FUNCTION vec3 faceCacheFullLight(FaceCacheTaps t) {
    vec3 sum = vec3(0.0f);
    float weight = 0.0f;
    for (int c = 0; c < 4; ++c) {
        if (t.weight[c] <= 0.0f) continue;
        sum += t.weight[c] * faceCacheDecodeLight(faceCacheTexel(t.texel[c]).y);
        weight += t.weight[c];
    }
    return weight > 0.0f ? sum / weight : vec3(0.0f);
}

// Full light over the day, at the hour `day` describes (x: the texels' sky
// weights' first word; y: the faces' day words' first; z: the bounce positions
// either side of the hour, before | after << 16; w: the second's weight, as
// float bits). A texel's sky weights (horizon, zenith: its direct light per
// unit radiance of each colour) ...
GROTTO_FUNCTION vec2 faceCacheDaySkyWeights(uint texel, uvec4 day) {
    return unpackHalf2x16(faceCacheTexelWord(day.x + texel));
}
// ... and what face `face` (in record order) receives bounced, under a sky of
// `zenith` and `horizon` radiance and a sun of `sun` (irradiance over pi on a
// face turned to it): its words' light at those colours, the sun's interpolated.
GROTTO_FUNCTION vec3 faceCacheDayBounce(uint face, uvec4 day, vec3 zenith, vec3 horizon, vec3 sun) {
    uint words = day.y + face * GROTTO_DAY_LIGHT_WORDS;
    vec3 before = faceCacheDecodeLight(faceCacheTexelWord(words + 2u + (day.z & 0xFFFFu)));
    vec3 after = faceCacheDecodeLight(faceCacheTexelWord(words + 2u + (day.z >> 16u)));
    return zenith * faceCacheDecodeLight(faceCacheTexelWord(words)) +
           horizon * faceCacheDecodeLight(faceCacheTexelWord(words + 1u)) + sun * mix(before, after, uintBitsToFloat(day.w));
}
// Both: what texel `texel` (k texels a side) receives beside its light word.
GROTTO_FUNCTION vec3 faceCacheDayLight(uint texel, uint k, uvec4 day, vec3 zenith, vec3 horizon, vec3 sun) {
    vec2 weights = faceCacheDaySkyWeights(texel, day);
    return zenith * weights.y + horizon * weights.x + faceCacheDayBounce(texel / (k * k), day, zenith, horizon, sun);
}

// The day's sun at the taps (a cache baked with it: each texel's bits, one a
// position along the day, 0 where the sun is behind the face; a word a texel
// from word `first` of the texels), read at the bits `positions` (the two either
// side of the hour): the share of them lit, over the taps; `edge` where they
// disagree (a shadow edge passing through, in space or in time): the frame
// traces the sun there.
GROTTO_FUNCTION float faceCacheDaySun(FaceCacheTaps t, uint first, uint positions, GROTTO_OUT(bool) edge) {
    uint lit = 0u, dark = 0u;
    float sum = 0.0f, weight = 0.0f;
    for (int c = 0; c < 4; ++c) {
        if (t.weight[c] <= 0.0f) continue;
        uint bits = faceCacheTexelWord(first + t.texel[c]) & positions;
        lit |= bits;
        dark |= positions & ~bits;
        sum += t.weight[c] * float(bitCount(bits));
        weight += t.weight[c];
    }
    edge = lit != 0u && dark != 0u;
    return weight <= 0.0f ? 0.0f : sum / (weight * float(bitCount(positions)));
}

GROTTO_FUNCTION vec4 faceCacheAt(vec3 p, ivec3 origin, uint dir, GROTTO_OUT(bool) found) {
    vec2 sunRange;
    return faceCacheBlend(faceCacheTaps(p, origin, dir), found, sunRange);
}

#endif  // GROTTO_FACE_CACHE_LAYOUT_ONLY
GROTTO_NAMESPACE_END
#endif
