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
#include "engine/frame/pass_decl.h"
#include "engine/passes/ao_targets.h"
#include "engine/passes/compute_pass.h"

namespace grotto {

class EstimatorPass {
public:
    // The loop shape (GTAO: slices, steps, distribution power; SSAO: samples;
    // HBAO: directions, steps; voxel and hybrid: rays too) is compiled in from `ao`;
    // VBAO writes its bent normals too when `bentNormals`.
    EstimatorPass(vk::Context& ctx, const AoOptions& ao, bool bentNormals = false);
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

}  // namespace grotto
