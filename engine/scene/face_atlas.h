#pragma once
// The face cache laid out for reading (--ao cache). Each greedy rectangle of the
// full-detail mesh gets a region of atlas cells, which the quads cut from it to
// meet their neighbours (voxel/watertight.h) share: the cache's texels over the
// rectangle on its plane, k a voxel along the face's U and V, with a one-texel border of
// what lies beyond the box on the same plane. The G-buffer writes each pixel's
// quad record (where its region lies, its row length), so the composite reads a
// pixel's four texels as four independent loads instead of through the cache's
// chain of look-ups (shaders/shared/face_cache.h: bucket, slot, record, rank).
// A cell holds what that chain finds at its texel: the AO and sun half with a
// bit saying a face is there, and the light word; zero where no face lies. So the
// read through the atlas is the chain's, tap for tap, wherever the atlas is current.
// Regions are placed chunk by chunk, each chunk in one range of cells with room to
// grow (quad_slots.h, as the vertex buffer's slots): an edit re-places only the
// chunks it re-meshed, a chunk that still fits its range stays where it is, and the
// free ranges merge, so what is lost to fragments is bounded as the vertex
// buffer's is. Pure CPU, no Vulkan.
#include "engine/scene/quad_slots.h"
#include "voxel/face_cache_layout.h"
#include "voxel/mesh.h"

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include <map>
#include <cstdint>
#include <span>
#include <tuple>
#include <vector>

namespace grotto {

// A greedy rectangle's box on its plane, chunk-relative: the plane's voxel-corner
// coordinate along the face's axis, the box's least U and V corner and its size in faces.
struct AtlasBox {
    uint32_t dir = 0, plane = 0, u = 0, v = 0, width = 1, height = 1;
};
// One word a rectangle (the host keeps it per chunk): plane 0-5, u 6-10, v 11-15,
// width - 1 16-20, height - 1 21-25, dir 26-28.
uint32_t packAtlasBox(const gpu::PackedQuad& rect);
AtlasBox unpackAtlasBox(uint32_t word);
// The rectangle of `rects` each quad (4 packed corners each, as drawn) was cut from.
std::vector<uint32_t> atlasRectsOf(std::span<const gpu::PackedQuad> rects, std::span<const uint32_t> corners);

// The cells of a box's region at k texels a side, and its rows' length.
uint64_t atlasRegionCells(const AtlasBox& box, uint32_t k);
inline uint32_t atlasStride(const AtlasBox& box, uint32_t k) { return k * box.width + 2; }

// The record the G-buffer writes for a pixel of a quad of that rectangle (chunk corner `origin`,
// region from cell `first`): x + I + J * y (mod 2^32) is the cell of absolute
// texel (I, J) along the face's U and V. y = 0: no region (coarser levels, objects).
glm::uvec2 atlasRecord(glm::ivec3 origin, const AtlasBox& box, uint64_t first, uint32_t k);

// A cell as the composite reads it: x the texel's AO and sun half | 1 << 16 where
// a face lies, y its light word; (0, 0) where none does.
inline constexpr uint32_t kAtlasFaceBit = 1u << 16;

// Fills the region of `box` (chunk corner `origin`) with what the chain finds in
// `arrays` (the laid-out cache), row by row: `cells` holds atlasRegionCells.
void fillAtlasRegion(const voxel::FaceCacheArrays& arrays, glm::ivec3 origin, const AtlasBox& box,
                     std::span<glm::uvec2> cells);

class FaceAtlasLayout {
public:
    explicit FaceAtlasLayout(uint32_t k) : k_(k) {}
    uint32_t texelsPerSide() const { return k_; }

    // The chunk at corner `origin` with these rectangles' boxes (packAtlasBox):
    // kept where it is while its regions fit its range, else moved to a new one.
    void place(glm::ivec3 origin, std::span<const uint32_t> boxes);
    void remove(glm::ivec3 origin);

    struct Chunk {
        uint64_t first = 0, cells = 0;  // its range of cells
        std::vector<uint64_t> regions;  // each box's first cell, in its quads' order
    };
    const Chunk* find(glm::ivec3 origin) const;
    uint64_t capacity() const { return slots_.capacity(); }

private:
    struct Less {
        bool operator()(const glm::ivec3& a, const glm::ivec3& b) const {
            return std::tie(a.x, a.y, a.z) < std::tie(b.x, b.y, b.z);
        }
    };
    uint32_t k_;
    QuadSlots slots_;  // ranges of cells (its unit is a cell here, not a quad)
    std::map<glm::ivec3, Chunk, Less> chunks_;
};

}  // namespace grotto
