#pragma once
// --ao cache's AOVs, for a read-back only (face_cache_aov.comp): the face cache's
// AO at each full-res pixel into the full-res AO image and, while its sun is the
// frame's, its sun visibility into the shadow image: over the world pixels it
// holds when the shadow pass ran (`tracedShadows`), over every pixel else. The AO
// is less what objects take, and objects' own on their faces (`objectLight`: the
// object light pass's image). And the light the cache holds there (irradiance over
// pi: the full light, or the sky's light from its weights) into the light image.
// Reads the G-buffer's depth and surface ids, the frame uniforms and the cache.
#include "engine/frame/frame_plan.h"
#include "engine/frame/pass_decl.h"
#include "engine/passes/compute_pass.h"
#include "engine/passes/gbuffer_pass.h"
#include "engine/scene/face_cache_gpu.h"

#include <tuple>

namespace grotto {

class FaceCacheAovPass {
public:
    FaceCacheAovPass(vk::Context& ctx, bool cachedSun, bool tracedShadows, bool objectLight);
    // For read-backs with AOVs.
    static bool runs(const FramePlan& plan) { return plan.faceCache && plan.aoAov; }
    static auto key(const FramePlan& plan) { return std::tuple(plan.cachedSun, plan.tracedShadows, plan.objectLight); }
    // Untimed: a read-back's work, not the frame's.
    static PassDecl declare() {
        return {nullptr, {{TargetId::Surface, Access::Sampled}, {TargetId::Depth, Access::Sampled},
                          {TargetId::AoFull, Access::Write}, {TargetId::Shadow, Access::Write},
                          {TargetId::ObjectLight, Access::Read}, {TargetId::CacheLight, Access::Write}}};
    }
    void record(VkCommandBuffer cmd, const GBufferTargets& gbuffer, const vk::Buffer& frame, const GpuFaceCache& cache,
                const vk::Image& ao, const vk::Image& sun, const vk::Image& objectLight, const vk::Image& light);

private:
    vk::Context& ctx_;
    ComputePass pass_;
};

}  // namespace grotto
