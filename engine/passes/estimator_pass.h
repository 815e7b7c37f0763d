#pragma once
// The AO estimator pass at AO resolution: GTAO (gtao.comp), voxel-traced AO
// (voxel.comp), the hybrid of both (hybrid.comp), or one of the baselines SSAO
// (ssao.comp) and HBAO (hbao.comp), which read and write exactly what GTAO does
// (shaders/ao_estimator.glsl); voxel and hybrid also bind the trace inputs. Reads: the depth MIP chain, the
// full-res surface ids (normals), GTAO constants. Writes: AoTargets::raw
// (visibility, packed edges, depth, face). No history; the noise follows
// GtaoConstants::frameIndex.
#include "engine/ao_settings.h"
#include "engine/scene/occupancy.h"
#include "engine/frame/frame_plan.h"
#include "engine/frame/pass_decl.h"
#include "engine/passes/ao_targets.h"
#include "engine/passes/compute_pass.h"

#include <tuple>
#include <vector>

namespace grotto {

class EstimatorPass {
public:
    // The loop shape (GTAO: slices, steps, distribution power; SSAO: samples;
    // HBAO: directions, steps; voxel and hybrid: rays too) is compiled in from `ao`;
    // VBAO writes its bent normals too when `bentNormals`.
    // `constants`: constants(ao, bentNormals).
    EstimatorPass(vk::Context& ctx, AoMethod method, const std::vector<uint32_t>& constants);
    static std::vector<uint32_t> constants(const AoOptions& ao, bool bentNormals);
    static bool runs(const FramePlan& plan) { return plan.chain; }
    static auto key(const FramePlan& plan) {
        return std::tuple(plan.ao.method, constants(plan.ao, plan.bentNormals));
    }
    // Timed under the method's name (aoMethodName).
    PassDecl declare() const;
    // `traceConstants`, `occupancy` and `objectGrids` only for the methods that trace voxels.
    void record(VkCommandBuffer cmd, const vk::Image& surface, const AoTargets& ao, const vk::Buffer& constants,
                const vk::Buffer& traceConstants, const GpuOccupancy* occupancy, const vk::Buffer* objectGrids);

private:
    vk::Context& ctx_;
    AoMethod method_;
    bool traces_;
    ComputePass pass_;
};

// For read-backs with AOVs of VBAO frames without bent normals: its estimator again
// with them (the same kernel on the same inputs and noise).
class BentNormalsPass : public EstimatorPass {
public:
    using EstimatorPass::EstimatorPass;
    static bool runs(const FramePlan& plan) {
        return plan.chain && plan.aoAov && plan.ao.method == AoMethod::Vbao && !plan.bentNormals;
    }
    static auto key(const FramePlan& plan) { return std::tuple(plan.ao.method, constants(plan.ao, true)); }
};

}  // namespace grotto
