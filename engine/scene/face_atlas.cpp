#include "engine/scene/face_atlas.h"

#include "grotto/error.h"
#include "voxel/face_cache_twin.h"

#include <algorithm>
#include <cstdint>

namespace grotto {

uint32_t packAtlasBox(const gpu::PackedQuad& rect) {
    const uint32_t dir = gpu::quadFace(rect.bits), axis = gpu::faceAxis(dir);
    const uint32_t plane = gpu::quadCoord(rect.bits, axis) + (gpu::facePositive(dir) ? 1u : 0u);
    return plane | gpu::quadCoord(rect.bits, gpu::faceUAxis(dir)) << 6 | gpu::quadCoord(rect.bits, gpu::faceVAxis(dir)) << 11 |
           (gpu::quadWidth(rect.bits) - 1) << 16 | (gpu::quadHeight(rect.bits) - 1) << 21 | dir << 26;
}

namespace {
// A face of a chunk: its voxel (chunk-relative) and direction, in one word.
uint32_t faceKey(glm::ivec3 cell, uint32_t dir) {
    return uint32_t(cell.x) | uint32_t(cell.y) << 5 | uint32_t(cell.z) << 10 | dir << 15;
}
}  // namespace

std::vector<uint32_t> atlasRectsOf(std::span<const gpu::PackedQuad> rects, std::span<const uint32_t> corners) {
    // Every face of each rectangle (they cover each face once), then each quad's
    // least corner's face: a quad lies within its rectangle. One table a thread,
    // every face a chunk may have, left empty again after each chunk.
    thread_local std::vector<uint32_t> rectOf(size_t(6) << 15, UINT32_MAX);
    auto eachFace = [&](auto&& visit) {
        for (uint32_t r = 0; r < rects.size(); ++r) {
            const uint32_t bits = rects[r].bits, dir = gpu::quadFace(bits);
            glm::ivec3 cell(int(gpu::quadCoord(bits, 0)), int(gpu::quadCoord(bits, 1)), int(gpu::quadCoord(bits, 2)));
            const int ua = int(gpu::faceUAxis(dir)), va = int(gpu::faceVAxis(dir)), u = cell[ua], v = cell[va];
            for (uint32_t b = 0; b < gpu::quadHeight(bits); ++b)
                for (uint32_t a = 0; a < gpu::quadWidth(bits); ++a) {
                    cell[ua] = u + int(a), cell[va] = v + int(b);
                    visit(faceKey(cell, dir), r);
                }
        }
    };
    eachFace([&](uint32_t key, uint32_t r) { rectOf[key] = r; });
    std::vector<uint32_t> of(corners.size() / 4);
    for (size_t q = 0; q < of.size(); ++q) {
        voxel::MeshQuad quad;
        std::copy_n(corners.begin() + 4 * std::ptrdiff_t(q), 4, quad.corners.begin());
        const uint32_t dir = quad.face(), axis = gpu::faceAxis(dir);
        glm::ivec3 lo = quad.corner(0);
        for (int i = 1; i < 4; ++i) lo = glm::min(lo, quad.corner(i));
        if (gpu::facePositive(dir)) lo[int(axis)] -= 1;  // the voxel behind the plane
        of[q] = rectOf[faceKey(lo, dir)];
    }
    eachFace([&](uint32_t key, uint32_t) { rectOf[key] = UINT32_MAX; });
    if (std::find(of.begin(), of.end(), UINT32_MAX) != of.end())
        throw Error::internal("atlasRectsOf", "a quad outside every rectangle");
    return of;
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
    // The region's voxel columns: the first (the border's) and how many. Each row
    // of voxels is looked up once (a chain of look-ups each) for its k rows of texels.
    const int firstU = gpu::faceCacheFloorDiv(t0.x, ik);
    std::vector<int> faces(size_t(gpu::faceCacheFloorDiv(t0.x + int(stride) - 1, ik) - firstU + 1));
    int cv = INT32_MIN;
    for (uint32_t b = 0; b < rows; ++b) {
        const int J = t0.y + int(b);
        if (gpu::faceCacheFloorDiv(J, ik) != cv) {
            cv = gpu::faceCacheFloorDiv(J, ik), cell[va] = cv;
            for (size_t u = 0; u < faces.size(); ++u) cell[ua] = firstU + int(u), faces[u] = gpu::faceCacheFace(cell, box.dir);
        }
        for (uint32_t a = 0; a < stride; ++a) {
            const int I = t0.x + int(a), cu = gpu::faceCacheFloorDiv(I, ik), face = faces[size_t(cu - firstU)];
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
