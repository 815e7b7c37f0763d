#include "engine/scene/view_draw.h"

#include "engine/frame/chunk_culling.h"
#include "engine/frame/frustum.h"
#include "shaders/shared/quad.h"

#include <algorithm>
#include <cmath>

namespace grotto {

ViewDraw countViewDraw(std::span<const voxel::MeshChunkQuads> chunks, double voxelSize, glm::dvec3 worldOrigin,
                       const Camera& camera, double lodBias) {
    const Frustum frustum(camera);
    const double focalPixels = double(camera.height) / (2.0 * std::tan(0.5 * camera.fovY));
    ViewDraw draw;
    for (const voxel::MeshChunkQuads& c : chunks) {
        if (c.quads.empty()) continue;
        // The chunk's bounds at every level, camera-relative, as placeChunk makes them.
        glm::ivec3 lo(GROTTO_CHUNK_SIZE), hi(0);
        auto grow = [&](const std::vector<voxel::MeshQuad>& quads) {
            for (const voxel::MeshQuad& q : quads)
                for (int i = 0; i < 4; ++i) {
                    lo = glm::min(lo, q.corner(i));
                    hi = glm::max(hi, q.corner(i));
                }
        };
        grow(c.quads);
        for (const voxel::MeshLevel& l : c.coarser) grow(l.quads);
        const glm::vec3 offset(worldOrigin + glm::dvec3(c.origin) * voxelSize - camera.position);
        const glm::vec3 boxLo = offset + glm::vec3(lo) * float(voxelSize), boxHi = offset + glm::vec3(hi) * float(voxelSize);
        if (frustum.outside(boxLo, boxHi)) continue;
        // The level culling picks on a first frame, and only where it saves quads.
        auto quadsAt = [&](size_t level) { return level ? c.coarser[level - 1].quads.size() : c.quads.size(); };
        const double voxelPixels = voxelSize * focalPixels / nearestDepth(camera, boxLo, boxHi);
        size_t level = size_t(chooseLevel(voxelPixels, lodBias, -1, int(c.coarser.size()) + 1));
        while (level > 0 && quadsAt(level) >= quadsAt(level - 1)) --level;
        const std::array<uint32_t, 6>& faceCount = level ? c.coarser[level - 1].faceCount : c.faceCount;
        const std::array<uint32_t, 6> clusters =
            faceClusters(faceCount, level ? c.coarser[level - 1].quads : c.quads);
        for (uint32_t f = 0; f < 6; ++f) {
            const uint32_t axis = gpu::faceAxis(f);
            if (gpu::facePositive(f) ? boxLo[axis] >= 0.0f : boxHi[axis] <= 0.0f) continue;  // seen only from behind
            draw.quads += faceCount[f];
            draw.clusters += clusters[f];
        }
    }
    return draw;
}

}  // namespace grotto
