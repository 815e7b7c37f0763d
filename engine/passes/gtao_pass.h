#pragma once
// The AO estimator pass at half resolution: GTAO (gtao.comp), or one of the
// baselines SSAO (ssao.comp) and HBAO (hbao.comp), which read and write exactly
// what GTAO does (shaders/ao_estimator.glsl). Reads: the depth MIP chain, the
// full-res surface ids (normals), GTAO constants. Writes: AoTargets::raw
// (visibility, packed edges, depth, face). No history; the noise follows
// GtaoConstants::frameIndex.
#include "engine/ao_settings.h"
#include "engine/passes/ao_targets.h"
#include "engine/passes/compute_pass.h"

namespace grotto {

class GtaoPass {
public:
    // The loop shape (GTAO: slices, steps, distribution power; SSAO: samples;
    // HBAO: directions, steps) is compiled in from `ao`.
    GtaoPass(vk::Context& ctx, const AoOptions& ao);
    void record(VkCommandBuffer cmd, const vk::Image& surface, const AoTargets& ao, const vk::Buffer& constants);

private:
    vk::Context& ctx_;
    ComputePass pass_;
};

}  // namespace grotto
