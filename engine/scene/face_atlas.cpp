#include "engine/scene/face_atlas.h"

#include "voxel/face_cache_twin.h"

#include <algorithm>

namespace grotto {

uint32_t packAtlasBox(const voxel::MeshQuad& quad) {
    const uint32_t dir = quad.face();
    const uint32_t axis = gpu::faceAxis(dir), ua = gpu::faceUAxis(dir), va = gpu::faceVAxis(dir);
    glm::ivec3 lo = quad.corner(0), hi = lo;
    for (int i = 1; i < 4; ++i) lo = glm::min(lo, quad.corner(i)), hi = glm::max(hi, quad.corner(i));
    const uint32_t width = uint32_t(std::max(hi[int(ua)] - lo[int(ua)], 1)), height = uint32_t(std::max(hi[int(va)] - lo[int(va)], 1));
    return uint32_t(lo[int(axis)]) | uint32_t(lo[int(ua)]) << 6 | uint32_t(lo[int(va)]) << 11 | (width - 1) << 16 |
           (height - 1) << 21 | dir << 26;
}

AtlasBox unpackAtlasBox(uint32_t w) {
    return {.dir = (w >> 26) & 7u, .plane = w & 63u, .u = (w >> 6) & 31u, .v = (w >> 11) & 31u,
            .width = ((w >> 16) & 31u) + 1, .height = ((w >> 21) & 31u) + 1};
}

uint64_t atlasRegionCells(const AtlasBox& box, uint32_t k) {
    return uint64_t(atlasStride(box, k)) * (uint64_t(k) * box.height + 2);
}

namespace {
// The absolute texel column and row of a region's first cell (one before the box's first texel).
glm::ivec2 firstTexel(glm::ivec3 origin, const AtlasBox& box, uint32_t k) {
    const int ik = int(k);
    return {(origin[int(gpu::faceUAxis(box.dir))] + int(box.u)) * ik - 1, (origin[int(gpu::faceVAxis(box.dir))] + int(box.v)) * ik - 1};
}
}  // namespace

glm::uvec2 atlasRecord(glm::ivec3 origin, const AtlasBox& box, uint64_t first, uint32_t k) {
    const uint32_t stride = atlasStride(box, k);
    const glm::ivec2 t = firstTexel(origin, box, k);
    return {uint32_t(first) - uint32_t(t.x) - uint32_t(t.y) * stride, stride};  // wraps as the shader's sum does
}

void fillAtlasRegion(const voxel::FaceCacheArrays& arrays, glm::ivec3 origin, const AtlasBox& box,
                     std::span<glm::uvec2> cells) {
    const voxel::FaceCacheTwin twin(arrays);
    const uint32_t k = arrays.texelsPerSide, axis = gpu::faceAxis(box.dir);
    const int ik = int(k), ua = int(gpu::faceUAxis(box.dir)), va = int(gpu::faceVAxis(box.dir));
    const uint32_t stride = atlasStride(box, k), rows = k * box.height + 2;
    const glm::ivec2 t0 = firstTexel(origin, box, k);
    // The voxels whose faces lie on the plane: behind it for a face looking +, in front for -.
    const int plane = origin[int(axis)] + int(box.plane);
    glm::ivec3 cell(0);
    cell[int(axis)] = gpu::facePositive(box.dir) ? plane - 1 : plane;
    for (uint32_t b = 0; b < rows; ++b) {
        const int J = t0.y + int(b), cv = gpu::faceCacheFloorDiv(J, ik);
        cell[va] = cv;
        int cu = INT32_MIN, face = -1;
        for (uint32_t a = 0; a < stride; ++a) {
            const int I = t0.x + int(a), u = gpu::faceCacheFloorDiv(I, ik);
            if (u != cu) cu = u, cell[ua] = u, face = gpu::faceCacheFace(cell, box.dir);
            glm::uvec2& out = cells[size_t(b) * stride + a];
            if (face < 0) {
                out = glm::uvec2(0u);
                continue;
            }
            const uint32_t texel = uint32_t(face) * k * k + uint32_t(J - cv * ik) * k + uint32_t(I - cu * ik);
            const glm::uvec2 bits = gpu::faceCacheTexel(texel);
            out = glm::uvec2(bits.x | kAtlasFaceBit, bits.y);
        }
    }
}

void FaceAtlasLayout::place(glm::ivec3 origin, std::span<const uint32_t> boxes) {
    uint64_t cells = 0;
    for (uint32_t w : boxes) cells += atlasRegionCells(unpackAtlasBox(w), k_);
    auto it = chunks_.find(origin);
    if (it != chunks_.end() && (cells > it->second.cells || boxes.empty())) {
        slots_.release(it->second.first, it->second.cells);
        chunks_.erase(it);
        it = chunks_.end();
    }
    if (boxes.empty()) return;
    if (it == chunks_.end()) {
        const uint32_t size = slotQuads(uint32_t(cells));
        std::optional<uint64_t> first = slots_.allocate(size);
        if (!first) {
            // The range grows by what is asked or a sixteenth, whichever is more: a
            // whole world laid out chunk by chunk ends within a sixteenth of its need.
            slots_.grow(slots_.capacity() + std::max<uint64_t>(size, slots_.capacity() / 16));
            first = slots_.allocate(size);
        }
        it = chunks_.emplace(origin, Chunk{.first = *first, .cells = size}).first;
    }
    Chunk& c = it->second;
    c.regions.clear();
    uint64_t at = c.first;
    for (uint32_t w : boxes) {
        c.regions.push_back(at);
        at += atlasRegionCells(unpackAtlasBox(w), k_);
    }
}

void FaceAtlasLayout::remove(glm::ivec3 origin) { place(origin, {}); }

const FaceAtlasLayout::Chunk* FaceAtlasLayout::find(glm::ivec3 origin) const {
    const auto it = chunks_.find(origin);
    return it == chunks_.end() ? nullptr : &it->second;
}

}  // namespace grotto
