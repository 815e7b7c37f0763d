#pragma once
// Depth prefilter. Reads: full-res depth (D32), the AO constants.
// Writes: the AO-resolution view-depth MIP chain (AoTargets::depthAtlas). No history.
// For VBAO's voxels thickness (depth_prefilter_thickness.comp) it also reads the
// surface ids and the world's occupancy and writes AoTargets::thickness.
#include "engine/frame/frame_plan.h"
#include "engine/frame/pass_decl.h"
#include "engine/passes/ao_targets.h"
#include "engine/passes/compute_pass.h"
#include "engine/scene/occupancy.h"

#include <tuple>

namespace grotto {

class DepthPrefilterPass {
public:
    DepthPrefilterPass(vk::Context& ctx, bool thickness);
    static bool runs(const FramePlan& plan) { return plan.chain; }
    static auto key(const FramePlan& plan) { return std::tuple(voxelThickness(plan.ao)); }
    PassDecl declare() const;
    // `surface`, `traceConstants` and `occupancy` only with the thickness.
    void record(VkCommandBuffer cmd, const vk::Image& depth, const vk::Image& surface, const AoTargets& ao,
                const vk::Buffer& constants, const vk::Buffer& traceConstants, const GpuOccupancy* occupancy);

private:
    vk::Context& ctx_;
    bool thickness_;
    ComputePass pass_;
};

}  // namespace grotto
