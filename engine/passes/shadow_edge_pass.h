#pragma once
// Sharp shadow edges over the face cache's sun (shaders/shadow_edge.comp): the
// composite lists the pixels whose texels a shadow edge crosses (composite.comp),
// and this pass traces exact sun rays for each (one toward a point sun, 16 over a
// disc) and corrects its colour. Reads the G-buffer's
// depth and surface ids, the trace constants and the occupancy; writes the colour.
// Owns the list (a frame's pixels / 8 at most: the rest keep the texels' sun;
// every pixel with the day's sun, whose first and last hour list all the ground).
#include "engine/frame/frame_plan.h"
#include "engine/frame/pass_decl.h"
#include "engine/passes/compute_pass.h"
#include "engine/passes/gbuffer_pass.h"
#include "engine/scene/occupancy.h"

#include <tuple>

namespace grotto {

class ShadowEdgePass {
public:
    ShadowEdgePass(vk::Context& ctx, uint32_t width, uint32_t height, bool daySun);
    static bool runs(const FramePlan& plan) { return plan.shadowEdges; }
    static auto key(const FramePlan& plan) { return std::tuple(plan.width, plan.height, plan.daySun); }  // its list's size
    ~ShadowEdgePass();
    ShadowEdgePass(const ShadowEdgePass&) = delete;
    ShadowEdgePass& operator=(const ShadowEdgePass&) = delete;

    static PassDecl declare() {
        return {"shadow edges",
                {{TargetId::Depth, Access::Sampled}, {TargetId::Surface, Access::Sampled}, {TargetId::Color, Access::Write}}};
    }
    // The list the composite appends to.
    const vk::Buffer& edges() const { return edges_; }
    // After the composite; empties the list for the next frame's.
    void record(VkCommandBuffer cmd, const GBufferTargets& gbuffer, const vk::Image& color,
                const vk::Buffer& traceConstants, const GpuOccupancy& occupancy);

private:
    vk::Context& ctx_;
    ComputePass args_, trace_;
    vk::Buffer edges_;
};

}  // namespace grotto
