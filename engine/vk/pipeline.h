#pragma once
// Shader modules from the SPIR-V built into the library (embedded_shaders.h), push-
// descriptor set layouts and compute pipelines. Graphics pipelines are built by
// their pass.
#include "engine/vk/context.h"

#include <string>
#include <vector>

namespace grotto::vk {

// The built-in shader `name` (e.g. "gtao.comp"), or GROTTO_SHADER_DIR/<name>.spv
// when that variable names a directory (for shader experiments); a missing or
// malformed file there is refused naming it (grotto::Error, input).
class ShaderModule;
ShaderModule loadShader(Context& ctx, const std::string& name);

// A loaded shader, destroyed with this object (a pipeline keeps what it needs), so
// a pipeline that fails to build leaks no module.
class ShaderModule {
public:
    ShaderModule(Context& ctx, VkShaderModule module) : device_(ctx.device), module_(module) {}
    ~ShaderModule() { vkDestroyShaderModule(device_, module_, nullptr); }
    ShaderModule(const ShaderModule&) = delete;
    ShaderModule& operator=(const ShaderModule&) = delete;
    VkShaderModule handle() const { return module_; }

private:
    VkDevice device_;
    VkShaderModule module_;
};

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
Binding storageBuffer(VkBuffer buffer, VkDeviceSize size = VK_WHOLE_SIZE);
void pushBindings(Context& ctx, VkCommandBuffer cmd, VkPipelineBindPoint point, VkPipelineLayout layout,
                  const std::vector<Binding>& bindings);

}  // namespace grotto::vk
