#pragma once
// Normals pass, for an embedding game only (it composites its own characters and
// effects over the frame). Reads: the G-buffer's surface ids and the objects' normal
// table. Writes: RGBA16F, xyz the world-space unit normal of the face seen (an
// object's turned by its pose), w 1 on a surface and 0 where the sky is (normal 0).
// No history.
#include "engine/frame/frame_plan.h"
#include "engine/frame/pass_decl.h"
#include "engine/passes/compute_pass.h"
#include "engine/vk/resources.h"

namespace grotto {

class NormalsPass {
public:
    explicit NormalsPass(vk::Context& ctx);
    static bool runs(const FramePlan& plan) { return plan.normals; }
    static PassDecl declare() {
        return {"normals", {{TargetId::Surface, Access::Sampled}, {TargetId::Normals, Access::Write}}};
    }
    void record(VkCommandBuffer cmd, const vk::Image& surface, const vk::Buffer& objectUniforms,
                const vk::Image& normals);

private:
    vk::Context& ctx_;
    ComputePass pass_;
};

}  // namespace grotto
