#include "voxel/face_cache_layout.h"

#include "voxel/face_brick_table.h"
#include "voxel/world.h"

#define GROTTO_FACE_CACHE_LAYOUT_ONLY
#include "shaders/shared/face_cache.h"

#include <glm/gtc/type_precision.hpp>
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/parallel_sort.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <tuple>

namespace grotto::voxel {

static_assert(kDaySunPositions == GROTTO_DAY_SUN_POSITIONS && kDayLightWords == GROTTO_DAY_LIGHT_WORDS,
              "the shaders' day sizes are the cache's");

namespace {

uint32_t unorm(double v, uint32_t bits) {
    const double top = double((1u << bits) - 1u);
    return uint32_t(std::lround(std::clamp(v, 0.0, 1.0) * top));
}

struct BrickLess {
    bool operator()(const glm::ivec3& a, const glm::ivec3& b) const {
        return std::tie(a.x, a.y, a.z) < std::tie(b.x, b.y, b.z);
    }
};

}  // namespace

glm::uvec2 packFaceTexel(const FaceTexel& t, bool fullLight) {
    const double n = t.samples ? double(t.samples) : 1.0;
    const uint32_t light = fullLight ? gpu::faceCacheEncodeLight(t.light)
                                     : glm::packHalf2x16(glm::vec2(float(t.skyHorizon / n), float(t.skyZenith / n)));
    return {unorm(t.ao(), 8) | unorm(t.sun(), 8) << 8, light};
}

glm::uvec2 packedTexel(std::span<const uint32_t> words, size_t texel) {
    const size_t pair = 3 * (texel / 2), odd = texel % 2;
    return {(words[pair + 2] >> (16 * odd)) & 0xFFFFu, words[pair + odd]};
}

FaceTexel unpackFaceTexel(glm::uvec2 bits, uint32_t rays, uint32_t sunRays, bool fullLight) {
    FaceTexel t;
    t.samples = rays;
    t.open = uint32_t(std::lround(double(bits.x & 255u) / 255.0 * rays));
    t.sunSamples = sunRays;
    t.sunOpen = uint32_t(std::lround(double(bits.x >> 8) / 255.0 * sunRays));
    if (fullLight) {
        t.light = gpu::faceCacheDecodeLight(bits.y);
    } else {
        const glm::vec2 sky = glm::unpackHalf2x16(bits.y);
        t.skyHorizon = sky.x * float(rays), t.skyZenith = sky.y * float(rays);
    }
    return t;
}

size_t faceCacheGpuBytes(std::span<const ExposedFace> faces, uint32_t texelsPerSide, bool daySun, bool dayLight) {
    std::vector<glm::ivec3> bricks;
    bricks.reserve(faces.size());
    for (const ExposedFace& f : faces) bricks.push_back(f.cell >> 3);
    std::sort(bricks.begin(), bricks.end(), BrickLess{});
    bricks.erase(std::unique(bricks.begin(), bricks.end()), bricks.end());
    return faceCacheGpuBytes(ExposedFaceCount{faces.size(), bricks.size()}, texelsPerSide, daySun, dayLight);
}

size_t faceCacheGpuBytes(const ExposedFaceCount& count, uint32_t texelsPerSide, bool daySun, bool dayLight) {
    const size_t texels = count.faces * texelsPerSide * texelsPerSide;
    const size_t texelWords = 3 * ((texels + 1) / 2) + (daySun ? texels : 0) +
                              (dayLight ? texels + count.faces * kDayLightWords : 0);
    const size_t levelWords = (count.faces + 15) / 16;  // each face's level for the GPU's tracer, 2 bits
    return faceBrickTableBytes(count.bricks) + count.bricks * GROTTO_FACE_RECORD_WORDS * 4 + texelWords * 4 + levelWords * 4;
}

FaceCacheArrays layFaceCache(std::span<const ExposedFace> faces, std::span<const FaceTexel> texels,
                             uint32_t texelsPerSide, bool fullLight, std::vector<uint32_t> storage) {
    const uint32_t perFace = texelsPerSide * texelsPerSide;
    // Each brick's faces by direction and bit: the order the GPU counts them in,
    // sorted in parallel on the brick as one 64-bit key (x, y, z from the least
    // brick, 21 bits each) and the direction and bit as another; a world wider
    // than 2^24 voxels compares the bricks themselves.
    struct Entry {
        uint64_t brick;
        uint32_t dirBit, face;
    };
    glm::ivec3 least(0), most(0);
    for (size_t f = 0; f < faces.size(); ++f) {
        const glm::ivec3 b = faces[f].cell >> 3;
        least = f ? glm::min(least, b) : b, most = f ? glm::max(most, b) : b;
    }
    const glm::i64vec3 span = glm::i64vec3(most) - glm::i64vec3(least);
    const bool wide = span.x >= (1 << 21) || span.y >= (1 << 21) || span.z >= (1 << 21);
    std::vector<Entry> entries(faces.size());
    tbb::parallel_for(tbb::blocked_range<size_t>(0, faces.size(), 16384), [&](const tbb::blocked_range<size_t>& r) {
        for (size_t f = r.begin(); f < r.end(); ++f) {
            const glm::ivec3 c = faces[f].cell;
            const glm::u64vec3 b = glm::u64vec3(glm::i64vec3(c >> 3) - glm::i64vec3(least));
            entries[f] = {wide ? 0 : b.x << 42 | b.y << 21 | b.z, faces[f].dir << 9 | gpu::occupancyBit(c.x, c.y, c.z),
                          uint32_t(f)};
        }
    });
    tbb::parallel_sort(entries.begin(), entries.end(), [&](const Entry& a, const Entry& b) {
        if (wide) {
            const glm::ivec3 ba = faces[a.face].cell >> 3, bb = faces[b.face].cell >> 3;
            if (ba != bb) return BrickLess{}(ba, bb);
        }
        return a.brick != b.brick ? a.brick < b.brick : a.dirBit < b.dirBit;
    });
    FaceCacheArrays out;
    out.texelsPerSide = texelsPerSide;
    out.faceCount = uint32_t(faces.size());
    out.faceOrder.reserve(faces.size());
    out.fullLight = fullLight;
    std::vector<glm::ivec3> positions;  // record i's brick
    for (size_t first = 0, end = 0; first < entries.size(); first = end) {
        const glm::ivec3 brick = faces[entries[first].face].cell >> 3;
        while (end < entries.size() && (faces[entries[end].face].cell >> 3) == brick) ++end;
        const size_t base = out.records.size();
        out.records.resize(base + GROTTO_FACE_RECORD_WORDS, 0u);
        // Each direction's first face: the faces before it, the brick's in earlier directions included.
        for (uint32_t d = 0; d < 6; ++d) out.records[base + 96 + d] = uint32_t(first);
        for (size_t n = first; n < end; ++n) {
            const uint32_t dir = entries[n].dirBit >> 9, bit = entries[n].dirBit & 511u;
            for (uint32_t d = dir + 1; d < 6; ++d) ++out.records[base + 96 + d];
            out.records[base + dir * 16 + (bit >> 5)] |= 1u << (bit & 31u);
            if (bit < 256) out.records[base + 102 + dir / 3] += 1u << (dir % 3 * 9);  // in the first half
            out.faceOrder.push_back(entries[n].face);
        }
        positions.push_back(brick);
    }
    // The texels in the faces' order, a pair of them to three words; in parallel, a pair at a time.
    const size_t count = out.faceOrder.size() * perFace;
    auto packed = [&](size_t texel) {
        if (texel >= count) return glm::uvec2(0u);
        const size_t face = out.faceOrder[texel / perFace];
        return packFaceTexel(texels[face * perFace + texel % perFace], fullLight);
    };
    // Every word is written below: the storage's old words need no clearing.
    out.texels = std::move(storage);
    const size_t words = 3 * ((texels.size() + 1) / 2);
    if (out.texels.capacity() < words) out.texels.reserve(words + words / 8);  // room for the next edit's faces
    out.texels.resize(words);
    tbb::parallel_for(tbb::blocked_range<size_t>(0, (count + 1) / 2, 4096), [&](const tbb::blocked_range<size_t>& r) {
        for (size_t pair = r.begin(); pair < r.end(); ++pair) {
            const glm::uvec2 even = packed(2 * pair), odd = packed(2 * pair + 1);
            out.texels[3 * pair] = even.y;
            out.texels[3 * pair + 1] = odd.y;
            out.texels[3 * pair + 2] = even.x | odd.x << 16;
        }
    });
    FaceBrickTable table = layFaceBrickTable(positions);
    out.bricks = std::move(table.slots);
    out.records.insert(out.records.begin(), table.seeds.begin(), table.seeds.end());  // the seeds first
    out.table = table.shape;
    return out;
}

void appendFaceMaterials(FaceCacheArrays& a, std::span<const ExposedFace> faces, const World& world) {
    a.materialsFirst = uint32_t(a.texels.size());
    a.texels.resize(a.texels.size() + (a.faceOrder.size() + 3) / 4, 0u);
    for (size_t g = 0; g < a.faceOrder.size(); ++g)
        a.texels[a.materialsFirst + g / 4] |= uint32_t(world.material(faces[a.faceOrder[g]].cell) & 0xFF) << (8 * (g % 4));
}

void appendDaySun(FaceCacheArrays& a, std::span<const FaceTexel> texels) {
    const size_t perFace = size_t(a.texelsPerSide) * a.texelsPerSide;
    a.daySunFirst = uint32_t(a.texels.size());
    a.texels.reserve(a.texels.size() + a.faceOrder.size() * perFace);
    for (const uint32_t f : a.faceOrder)
        for (size_t t = 0; t < perFace; ++t) a.texels.push_back(texels[f * perFace + t].daySun);
}

void appendDayLight(FaceCacheArrays& a, std::span<const FaceTexel> texels, std::span<const glm::vec3> dayLight) {
    const size_t perFace = size_t(a.texelsPerSide) * a.texelsPerSide;
    a.dayLightFirst = uint32_t(a.texels.size());
    a.texels.reserve(a.texels.size() + a.faceOrder.size() * (perFace + kDayLightWords));
    for (const uint32_t f : a.faceOrder)
        for (size_t t = 0; t < perFace; ++t) a.texels.push_back(packFaceTexel(texels[f * perFace + t], false).y);
    a.dayFacesFirst = uint32_t(a.texels.size());
    for (const uint32_t f : a.faceOrder)
        for (size_t w = 0; w < kDayLightWords; ++w) a.texels.push_back(gpu::faceCacheEncodeLight(dayLight[f * kDayLightWords + w]));
}

}  // namespace grotto::voxel
