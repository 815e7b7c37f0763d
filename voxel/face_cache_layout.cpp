#include "voxel/face_cache_layout.h"

#define GROTTO_FACE_CACHE_LAYOUT_ONLY
#include "shaders/shared/face_cache.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <map>
#include <tuple>

namespace grotto::voxel {

namespace {

uint32_t unorm8(double v) { return uint32_t(std::lround(std::clamp(v, 0.0, 1.0) * 255.0)); }

struct BrickLess {
    bool operator()(const glm::ivec3& a, const glm::ivec3& b) const {
        return std::tie(a.x, a.y, a.z) < std::tie(b.x, b.y, b.z);
    }
};

}  // namespace

uint32_t packFaceTexel(const FaceTexel& t) {
    const double n = t.samples ? double(t.samples) : 1.0;
    return unorm8(t.ao()) | unorm8(t.sun()) << 8 | unorm8(t.skyHorizon / n) << 16 | unorm8(t.skyZenith / n) << 24;
}

size_t faceCacheGpuBytes(std::span<const ExposedFace> faces, uint32_t texelsPerSide) {
    std::vector<glm::ivec3> bricks;
    bricks.reserve(faces.size());
    for (const ExposedFace& f : faces) bricks.push_back(f.cell >> 3);
    std::sort(bricks.begin(), bricks.end(), BrickLess{});
    bricks.erase(std::unique(bricks.begin(), bricks.end()), bricks.end());
    return faceCacheGpuBytes(ExposedFaceCount{faces.size(), bricks.size()}, texelsPerSide);
}

size_t faceCacheGpuBytes(const ExposedFaceCount& count, uint32_t texelsPerSide) {
    const size_t slots = std::bit_ceil(std::max<size_t>(2 * count.bricks, 2));
    return slots * 16 + count.bricks * GROTTO_FACE_RECORD_WORDS * 4 + count.faces * texelsPerSide * texelsPerSide * 4;
}

FaceCacheArrays layFaceCache(std::span<const ExposedFace> faces, std::span<const FaceTexel> texels,
                             uint32_t texelsPerSide) {
    const uint32_t perFace = texelsPerSide * texelsPerSide;
    // Each brick's faces by direction and bit: the order the GPU counts them in.
    struct Entry { uint32_t dir, bit, face; };
    std::map<glm::ivec3, std::vector<Entry>, BrickLess> bricks;
    for (uint32_t f = 0; f < faces.size(); ++f) {
        const glm::ivec3 c = faces[f].cell;
        bricks[c >> 3].push_back({faces[f].dir, gpu::occupancyBit(c.x, c.y, c.z), f});
    }
    FaceCacheArrays out;
    out.texelsPerSide = texelsPerSide;
    out.bricks.assign(std::bit_ceil(std::max<size_t>(2 * bricks.size(), 2)), glm::uvec4(0));
    out.records.reserve(bricks.size() * GROTTO_FACE_RECORD_WORDS);
    out.texels.reserve(texels.size());
    uint32_t record = 0, next = 0;
    for (auto& [brick, entries] : bricks) {
        std::sort(entries.begin(), entries.end(),
                  [](const Entry& a, const Entry& b) { return std::tie(a.dir, a.bit) < std::tie(b.dir, b.bit); });
        const size_t base = out.records.size();
        out.records.resize(base + GROTTO_FACE_RECORD_WORDS, 0u);
        for (uint32_t d = 0; d < 6; ++d) out.records[base + 96 + d] = next + uint32_t(std::count_if(
            entries.begin(), entries.end(), [d](const Entry& e) { return e.dir < d; }));
        for (const Entry& e : entries) {
            out.records[base + e.dir * 16 + (e.bit >> 5)] |= 1u << (e.bit & 31u);
            for (uint32_t t = 0; t < perFace; ++t) out.texels.push_back(packFaceTexel(texels[size_t(e.face) * perFace + t]));
        }
        next += uint32_t(entries.size());
        uint32_t slot = gpu::occupancyHash(brick.x, brick.y, brick.z) & out.hashMask();
        while (out.bricks[slot].w != 0) slot = (slot + 1) & out.hashMask();
        out.bricks[slot] = glm::uvec4(uint32_t(brick.x), uint32_t(brick.y), uint32_t(brick.z), ++record);
    }
    return out;
}

}  // namespace grotto::voxel
