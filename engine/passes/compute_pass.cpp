#include "engine/passes/compute_pass.h"

#include "engine/vk/readback.h"

namespace grotto {

ComputePass::ComputePass(vk::Context& ctx, const std::string& shader, const std::vector<VkDescriptorType>& bindings,
                         uint32_t pushBytes, const std::vector<uint32_t>& specialization)
    : ctx_(ctx), pushBytes_(pushBytes) {
    setLayout_ = vk::pushDescriptorLayout(ctx, bindings, VK_SHADER_STAGE_COMPUTE_BIT);
    try {  // a shader that fails to load must not leak the layouts
        layout_ = vk::pipelineLayout(ctx, setLayout_, pushBytes, VK_SHADER_STAGE_COMPUTE_BIT);
        pipeline_ = vk::computePipeline(ctx, layout_, shader, specialization);
    } catch (...) {
        release();
        throw;
    }
}

ComputePass::~ComputePass() { release(); }

void ComputePass::release() {
    vkDestroyPipeline(ctx_.device, pipeline_, nullptr);
    vkDestroyPipelineLayout(ctx_.device, layout_, nullptr);
    vkDestroyDescriptorSetLayout(ctx_.device, setLayout_, nullptr);
}

void ComputePass::bind(VkCommandBuffer cmd, const std::vector<vk::Binding>& bindings, const void* push) const {
    vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, pipeline_);
    vk::pushBindings(ctx_, cmd, VK_PIPELINE_BIND_POINT_COMPUTE, layout_, bindings);
    if (pushBytes_ && push) vkCmdPushConstants(cmd, layout_, VK_SHADER_STAGE_COMPUTE_BIT, 0, pushBytes_, push);
}

void ComputePass::dispatchIndirect(VkCommandBuffer cmd, const std::vector<vk::Binding>& bindings, VkBuffer args,
                                   VkDeviceSize offset, const void* push) const {
    bind(cmd, bindings, push);
    vkCmdDispatchIndirect(cmd, args, offset);
}

void ComputePass::dispatch(VkCommandBuffer cmd, const std::vector<vk::Binding>& bindings, VkExtent2D size,
                           uint32_t group, const void* push) const {
    bind(cmd, bindings, push);
    vkCmdDispatch(cmd, (size.width + group - 1) / group, (size.height + group - 1) / group, 1);
}

void computeToCompute(VkCommandBuffer cmd) {
    VkMemoryBarrier b{.sType = VK_STRUCTURE_TYPE_MEMORY_BARRIER,
                      .srcAccessMask = VK_ACCESS_SHADER_WRITE_BIT,
                      .dstAccessMask = VK_ACCESS_SHADER_READ_BIT | VK_ACCESS_SHADER_WRITE_BIT};
    vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT, 0, 1, &b, 0,
                         nullptr, 0, nullptr);
}

void computeToHost(VkCommandBuffer cmd) {
    vk::recordHostRead(cmd, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT, VK_ACCESS_SHADER_WRITE_BIT);
}

}  // namespace grotto
