#pragma once
// Sun shadows at full resolution (shadow.comp): one exact ray per pixel toward the
// sun through the world's voxels. Reads: the G-buffer's depth and surface ids, the
// objects' normal tables, the trace constants and the occupancy. Writes: R32F
// shadow, 1 = sunlit, 0 = blocked or facing away. Objects' voxels block the rays
// as the world's do (their grids: engine/scene/object_grids.h); with the face
// cache's sun, world surfaces test the objects alone (`objectsOnlyOnWorld`).
// A soft sun (soft_shadow.comp) jitters each ray within the sun's disc per frame
// and also reads the last frame's RGBA32F history and writes the next; the shadow
// is the accumulated visibility.
#include "engine/scene/occupancy.h"
#include "engine/frame/frame_plan.h"
#include "engine/frame/pass_decl.h"
#include "engine/passes/compute_pass.h"
#include "engine/passes/gbuffer_pass.h"

#include <tuple>

namespace grotto {

class ShadowPass {
public:
    ShadowPass(vk::Context& ctx, bool soft, bool objectsOnlyOnWorld);
    static bool runs(const FramePlan& plan) { return plan.tracedShadows; }
    static auto key(const FramePlan& plan) { return std::tuple(plan.softShadows, plan.cachedSun); }
    // A soft sun's pass reads history image `history` and writes the other.
    PassDecl declare() const;
    // A soft pass needs `history` (read) and `nextHistory` (written), both in GENERAL.
    void record(VkCommandBuffer cmd, const GBufferTargets& gbuffer, const vk::Buffer& objectUniforms,
                const vk::Image& shadow, const vk::Buffer& traceConstants, const GpuOccupancy& occupancy,
                const vk::Buffer& objectGrids, const vk::Image* history = nullptr, const vk::Image* nextHistory = nullptr);

private:
    vk::Context& ctx_;
    bool soft_;
    ComputePass pass_;
};

}  // namespace grotto
