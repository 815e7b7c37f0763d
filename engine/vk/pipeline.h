#pragma once
// Shader modules from the SPIR-V compiled at build time, push-descriptor set
// layouts and compute pipelines. Graphics pipelines are built by their pass.
#include "engine/vk/context.h"

#include <string>
#include <vector>

namespace grotto::vk {

// Loads <shader dir>/<name>.spv; the directory is GROTTO_SHADER_DIR if set, else
// the build's shader directory.
VkShaderModule loadShader(Context& ctx, const std::string& name);

// A set layout for push descriptors: binding i has types[i], visible to stages.
VkDescriptorSetLayout pushDescriptorLayout(Context& ctx, const std::vector<VkDescriptorType>& types,
                                           VkShaderStageFlags stages);

VkPipelineLayout pipelineLayout(Context& ctx, VkDescriptorSetLayout set, uint32_t pushConstantBytes,
                                VkShaderStageFlags pushStages);

// `specialization`: 32-bit values for constant_id 0, 1, 2, ... (floats bit-cast).
VkPipeline computePipeline(Context& ctx, VkPipelineLayout layout, const std::string& shader,
                           const std::vector<uint32_t>& specialization = {});

// One write of a push-descriptor binding (image or buffer).
struct Binding {
    VkDescriptorType type;
    VkDescriptorImageInfo image{};
    VkDescriptorBufferInfo buffer{};
};
Binding sampledImage(VkSampler sampler, VkImageView view, VkImageLayout layout);
Binding storageImage(VkImageView view);
Binding uniformBuffer(VkBuffer buffer, VkDeviceSize size = VK_WHOLE_SIZE);
void pushBindings(Context& ctx, VkCommandBuffer cmd, VkPipelineBindPoint point, VkPipelineLayout layout,
                  const std::vector<Binding>& bindings);

}  // namespace grotto::vk
