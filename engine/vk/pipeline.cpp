#include "engine/vk/pipeline.h"

#include "common/file_kind.h"
#include "engine/vk/embedded_shaders.h"

#include <algorithm>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <iterator>
#include <span>

namespace grotto::vk {

namespace {

// What a driver would choke on (some crash on malformed SPIR-V rather than fail),
// checked by the module's structure: the header, every instruction's length, a
// capability first, one memory model, and a "main" entry point for the stage the
// name says (.comp, .vert, .frag). Empty when it passes.
std::string spirvProblem(const std::vector<uint32_t>& w, const std::string& name) {
    const uint32_t version = w[1];
    if ((version & 0xff0000ffu) != 0 || version < 0x00010000u || version > 0x00010600u)
        return "unknown SPIR-V version word " + std::to_string(version);
    if (w[3] == 0 || w[4] != 0) return "bad header (id bound or schema)";
    const std::string stage = name.substr(name.rfind('.') + 1);
    const uint32_t model = stage == "comp" ? 5u : stage == "vert" ? 0u : stage == "frag" ? 4u : ~0u;  // GLCompute, Vertex, Fragment
    int memoryModels = 0;
    bool entry = false;
    for (size_t i = 5; i < w.size();) {
        const uint32_t count = w[i] >> 16, opcode = w[i] & 0xffffu;
        if (count == 0 || i + count > w.size()) return "instruction at word " + std::to_string(i) + " overruns the module";
        if (i == 5 && opcode != 17) return "it does not start with OpCapability";
        memoryModels += opcode == 14;
        // OpEntryPoint: model, function id, then the name as a nul-terminated string.
        if (opcode == 15 && count >= 5 && w[i + 1] == model &&
            std::strncmp(reinterpret_cast<const char*>(&w[i + 3]), "main", 5) == 0)
            entry = true;
        i += count;
    }
    if (memoryModels != 1) return "it has " + std::to_string(memoryModels) + " memory models (1 expected)";
    if (!entry) return "no \"main\" entry point for a ." + stage + " shader";
    return {};
}

// GROTTO_SHADER_DIR/<name>.spv: shaders compiled elsewhere, for experiments. What
// the driver would reject with a bare error code is refused here, naming the file.
std::vector<char> shaderFile(const std::string& dir, const std::string& name) {
    const std::string path = dir + "/" + name + ".spv";
    requireInputFile(path, "GROTTO_SHADER_DIR names a directory without it as a regular file");
    std::ifstream in(path, std::ios::binary);
    if (!in) throw Error(path, "no such compiled shader", "GROTTO_SHADER_DIR names a directory without it");
    std::vector<char> code{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
    uint32_t magic = 0;
    if (code.size() >= 4) std::memcpy(&magic, code.data(), 4);
    if (code.size() < 20 || code.size() % 4 != 0 || magic != 0x07230203u)
        throw Error(path, "is not SPIR-V (" + std::to_string(code.size()) + " bytes)",
                    "compile it with glslangValidator -V, or unset GROTTO_SHADER_DIR");
    std::vector<uint32_t> words(code.size() / 4);
    std::memcpy(words.data(), code.data(), code.size());
    if (const std::string why = spirvProblem(words, name); !why.empty())
        throw Error(path, "is not a usable SPIR-V shader: " + why,
                    "compile " + name + " with glslangValidator -V, or unset GROTTO_SHADER_DIR");
    return code;
}

}  // namespace

ShaderModule loadShader(Context& ctx, const std::string& name) {
    std::vector<char> file;
    std::span<const unsigned char> code;
    if (const char* dir = std::getenv("GROTTO_SHADER_DIR"); dir && *dir) {
        file = shaderFile(dir, name);
        code = {reinterpret_cast<const unsigned char*>(file.data()), file.size()};
    } else {
        const auto shaders = embeddedShaders();
        const auto it = std::find_if(shaders.begin(), shaders.end(), [&](const EmbeddedShader& s) { return s.name == name; });
        if (it == shaders.end()) throw Error::internal(name, "no such shader is built in");
        code = {it->bytes, it->size};
    }
    // The module copies the code; a file's bytes are copied into words first, as
    // std::vector<char> promises no 4-byte alignment.
    std::vector<uint32_t> words((code.size() + 3) / 4);
    std::memcpy(words.data(), code.data(), code.size());
    VkShaderModuleCreateInfo ci{.sType = VK_STRUCTURE_TYPE_SHADER_MODULE_CREATE_INFO,
                                .codeSize = code.size(),
                                .pCode = words.data()};
    VkShaderModule module;
    VK_CHECK(vkCreateShaderModule(ctx.device, &ci, nullptr, &module));
    return ShaderModule(ctx, module);
}

VkDescriptorSetLayout pushDescriptorLayout(Context& ctx, const std::vector<VkDescriptorType>& types,
                                           VkShaderStageFlags stages) {
    std::vector<VkDescriptorSetLayoutBinding> bindings;
    for (uint32_t i = 0; i < types.size(); ++i)
        bindings.push_back({.binding = i, .descriptorType = types[i], .descriptorCount = 1, .stageFlags = stages});
    VkDescriptorSetLayoutCreateInfo ci{.sType = VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO,
                                       .flags = VK_DESCRIPTOR_SET_LAYOUT_CREATE_PUSH_DESCRIPTOR_BIT_KHR,
                                       .bindingCount = uint32_t(bindings.size()),
                                       .pBindings = bindings.data()};
    VkDescriptorSetLayout layout;
    VK_CHECK(vkCreateDescriptorSetLayout(ctx.device, &ci, nullptr, &layout));
    return layout;
}

VkPipelineLayout pipelineLayout(Context& ctx, VkDescriptorSetLayout set, uint32_t pushConstantBytes,
                                VkShaderStageFlags pushStages) {
    VkPushConstantRange range{.stageFlags = pushStages, .offset = 0, .size = pushConstantBytes};
    VkPipelineLayoutCreateInfo ci{.sType = VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO,
                                  .setLayoutCount = 1,
                                  .pSetLayouts = &set,
                                  .pushConstantRangeCount = pushConstantBytes ? 1u : 0u,
                                  .pPushConstantRanges = &range};
    VkPipelineLayout layout;
    VK_CHECK(vkCreatePipelineLayout(ctx.device, &ci, nullptr, &layout));
    return layout;
}

VkPipeline computePipeline(Context& ctx, VkPipelineLayout layout, const std::string& shader,
                           const std::vector<uint32_t>& specialization) {
    const ShaderModule module = loadShader(ctx, shader);
    std::vector<VkSpecializationMapEntry> entries;
    for (uint32_t i = 0; i < specialization.size(); ++i) entries.push_back({i, 4 * i, 4});
    const VkSpecializationInfo spec{.mapEntryCount = uint32_t(entries.size()),
                                    .pMapEntries = entries.data(),
                                    .dataSize = 4 * specialization.size(),
                                    .pData = specialization.data()};
    VkComputePipelineCreateInfo ci{.sType = VK_STRUCTURE_TYPE_COMPUTE_PIPELINE_CREATE_INFO,
                                   .stage = {.sType = VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO,
                                             .stage = VK_SHADER_STAGE_COMPUTE_BIT,
                                             .module = module.handle(),
                                             .pName = "main",
                                             .pSpecializationInfo = specialization.empty() ? nullptr : &spec},
                                   .layout = layout};
    VkPipeline pipeline;
    VK_CHECK(vkCreateComputePipelines(ctx.device, VK_NULL_HANDLE, 1, &ci, nullptr, &pipeline));
    return pipeline;
}

Binding sampledImage(VkSampler sampler, VkImageView view, VkImageLayout layout) {
    return {.type = VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, .image = {sampler, view, layout}};
}
Binding storageImage(VkImageView view) {
    return {.type = VK_DESCRIPTOR_TYPE_STORAGE_IMAGE, .image = {VK_NULL_HANDLE, view, VK_IMAGE_LAYOUT_GENERAL}};
}
Binding uniformBuffer(VkBuffer buffer, VkDeviceSize size) {
    return {.type = VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, .buffer = {buffer, 0, size}};
}

Binding storageBuffer(VkBuffer buffer, VkDeviceSize size) {
    return {.type = VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, .buffer = {buffer, 0, size}};
}

void pushBindings(Context& ctx, VkCommandBuffer cmd, VkPipelineBindPoint point, VkPipelineLayout layout,
                  const std::vector<Binding>& bindings) {
    std::vector<VkWriteDescriptorSet> writes;
    for (uint32_t i = 0; i < bindings.size(); ++i) {
        const Binding& b = bindings[i];
        const bool image = b.type != VK_DESCRIPTOR_TYPE_STORAGE_BUFFER && b.type != VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER;
        writes.push_back({.sType = VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET,
                          .dstBinding = i,
                          .descriptorCount = 1,
                          .descriptorType = b.type,
                          .pImageInfo = image ? &b.image : nullptr,
                          .pBufferInfo = image ? nullptr : &b.buffer});
    }
    ctx.cmdPushDescriptorSet(cmd, point, layout, 0, uint32_t(writes.size()), writes.data());
}

}  // namespace grotto::vk
