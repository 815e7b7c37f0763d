#pragma once
// Objects' solid voxels for rays: each object's as a dense grid of bits over its
// bounds (objects are small), all in one storage buffer, and each frame the map
// from the rays' camera-relative world voxels into every grid at the object's
// pose (shaders/shared/trace.h's ObjectTrace). Sun rays and voxel AO rays stop at
// objects' voxels through them.
#include "engine/vk/resources.h"
#include "shaders/shared/trace.h"
#include "voxel/light_edit.h"
#include "voxel/object_pose.h"

#include <glm/vec3.hpp>

#include <cstdint>
#include <span>
#include <string>
#include <vector>

namespace grotto {
namespace voxel { class World; }

struct ObjectGrid {
    glm::ivec3 lo{0};          // the voxel index of cell (0, 0, 0)
    glm::ivec3 size{0};        // cells per axis
    double voxelSize = 1.0;    // the object's own, world units
    glm::dvec3 origin{0.0};    // object-local world position of voxel corner (0, 0, 0)
    std::vector<uint32_t> bits;  // cell (x, y, z) at bit (x * size.y + y) * size.z + z
    // Its exposed faces whose material glows (voxel index units of its own), with
    // their radiance: the lights the object gives the face cache's full light.
    std::vector<voxel::GlowingFace> glowing;
};

ObjectGrid objectGrid(const voxel::World& object);
// Refuses with grotto::Error (input), naming `where`, objects (`grids`, and
// `adding` when given) that glow on more faces in all than the object light pass
// samples (GROTTO_MAX_GLOW_FACES).
void requireGlowFits(const std::string& where, std::span<const ObjectGrid> grids, const ObjectGrid* adding = nullptr);

// The grids one after another in a storage buffer (one zero word when there are
// none, so the binding always has a buffer); first[k] is grid k's first word.
struct GpuObjectGrids {
    vk::Buffer buffer;
    std::vector<uint32_t> first;
};
GpuObjectGrids uploadObjectGrids(vk::Context& ctx, std::span<const ObjectGrid> grids);

// Fills t.objectCount, t.objects and t.glow for objects at `poses` (and
// `previous`, their poses in the frame before), from t.cameraCell (set first, by
// traceConstants) and the world's voxel size and origin.
void setObjectTraces(gpu::TraceConstants& t, std::span<const ObjectGrid> grids, std::span<const uint32_t> first,
                     std::span<const voxel::ObjectPose> poses, std::span<const voxel::ObjectPose> previous,
                     double voxelSize, glm::dvec3 worldOrigin);

}  // namespace grotto
