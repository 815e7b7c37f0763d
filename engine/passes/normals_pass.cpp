#include "engine/passes/normals_pass.h"

namespace grotto {

NormalsPass::NormalsPass(vk::Context& ctx)
    : ctx_(ctx),
      pass_(ctx, "normals.comp",
            {VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER,
             VK_DESCRIPTOR_TYPE_STORAGE_IMAGE}) {}

void NormalsPass::record(VkCommandBuffer cmd, const vk::Image& surface, const vk::Buffer& objectUniforms,
                         const vk::Image& normals) {
    pass_.dispatch(cmd,
                   {vk::sampledImage(ctx_.pointSampler, surface.view, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL),
                    vk::uniformBuffer(objectUniforms.buffer), vk::storageImage(normals.view)},
                   normals.extent, 16);
}

}  // namespace grotto
