#pragma once
// Composite pass. Reads: the surface id, the palette, frame uniforms and, with AO,
// the AO chain's half-res output, full-res depth and the GTAO constants (it
// upsamples the AO itself, see upsample.glsl) and, with shadows, the shadow image.
// Writes: RGBA32F display colour: sun Lambert x shadow + ambient x AO (multi-bounce
// from albedo), and the sky, through the exposure and tone map. No history. Object faces are lit with their turned normals (the
// objects' uniforms, shaders/shared/objects.h).
#include "engine/passes/compute_pass.h"
#include "engine/passes/gbuffer_pass.h"

namespace grotto {

class CompositePass {
public:
    CompositePass(vk::Context& ctx, bool withAo, bool withShadow);
    // Without AO, `aoHalf` and `gtaoConstants` are placeholders the shader ignores;
    // without shadows, so is `shadow`.
    void record(VkCommandBuffer cmd, const GBufferTargets& gbuffer, const vk::Image& aoHalf, const vk::Image& color,
                const vk::Buffer& frame, const vk::Buffer& palette, const vk::Buffer& gtaoConstants,
                const vk::Buffer& objectUniforms, const vk::Image& shadow);

private:
    vk::Context& ctx_;
    bool withAo_;
    ComputePass pass_;
};

}  // namespace grotto
