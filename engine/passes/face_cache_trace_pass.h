#pragma once
// The face cache traced on the GPU, a budget of rays each frame (shaders/shared/
// face_trace.h): the faces in view whose texels have not converged are listed
// from the G-buffer (face_cache_request.comp), the budget is shared out
// (face_cache_plan.comp), and their texels are traced whole, the CPU bake's own
// rays (face_cache_trace.comp), before the composite reads them. A face never
// traced gets a coarse look at once, whatever the budget, so no surface in view
// shows a placeholder; the budget then converges them, least converged first.
// The first frame after an edit gives the faces it reached in view their first
// look alone (the budget is 0 for it), so an edit shows in a frame of its own
// cost, not the budget's, and the budget refines from the next.
// After a frame with nothing in view left to trace, the budget goes to the
// backlog: the faces out of view not converged (shared/face_trace.h).
// Once every face has converged the passes do (almost) nothing. Reads the G-buffer's depth and surface
// ids, the frame uniforms, the trace constants and the occupancy; writes the
// cache's texels and levels.
#include "engine/frame/frame_plan.h"
#include "engine/frame/pass_decl.h"
#include "engine/passes/compute_pass.h"
#include "engine/passes/gbuffer_pass.h"
#include "engine/scene/face_cache_gpu.h"
#include "engine/scene/occupancy.h"
#include "shaders/shared/face_trace.h"

namespace grotto {

// Rays per frame when the settings leave it to the device: a CPU (lavapipe)
// traces a few million in tens of milliseconds, a GPU many times that.
uint32_t defaultCacheRays(const vk::Context& ctx);

class FaceCacheTracePass {
public:
    explicit FaceCacheTracePass(vk::Context& ctx);
    static bool runs(const FramePlan& plan) { return plan.cacheTracing; }
    static PassDecl declare() {
        return {"cache trace", {{TargetId::Depth, Access::Sampled}, {TargetId::Surface, Access::Sampled}}};
    }
    void record(VkCommandBuffer cmd, const GBufferTargets& gbuffer, VkExtent2D size, const vk::Buffer& frame,
                const vk::Buffer& traceConstants, const GpuOccupancy& occupancy, const GpuFaceCache& cache,
                uint32_t budget);

private:
    vk::Context& ctx_;
    ComputePass gate_, request_, backlog_, plan_, trace_;
    uint64_t traced_ = 0;  // the GpuFaceCache::id this pass traced last
};

}  // namespace grotto
