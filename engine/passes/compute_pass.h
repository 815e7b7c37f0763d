#pragma once
// A compute shader with a push-descriptor set layout and optional push constants:
// what every full-screen compute pass needs, so each pass file holds only its own
// inputs, outputs and dispatch.
#include "engine/vk/pipeline.h"

#include <string>
#include <vector>

namespace grotto {

class ComputePass {
public:
    ComputePass(vk::Context& ctx, const std::string& shader, const std::vector<VkDescriptorType>& bindings,
                uint32_t pushBytes = 0, const std::vector<uint32_t>& specialization = {});
    ~ComputePass();
    ComputePass(const ComputePass&) = delete;
    ComputePass& operator=(const ComputePass&) = delete;

    // One thread per pixel of `size`, in groups of `group` x `group`.
    void dispatch(VkCommandBuffer cmd, const std::vector<vk::Binding>& bindings, VkExtent2D size, uint32_t group,
                  const void* push = nullptr) const;

    // Groups as `args` holds them at `offset` (VkDispatchIndirectCommand), written on the GPU.
    void dispatchIndirect(VkCommandBuffer cmd, const std::vector<vk::Binding>& bindings, VkBuffer args,
                          VkDeviceSize offset, const void* push = nullptr) const;

private:
    void bind(VkCommandBuffer cmd, const std::vector<vk::Binding>& bindings, const void* push) const;
    void release();  // handles not made yet are null, which Vulkan ignores

    vk::Context& ctx_;
    uint32_t pushBytes_;
    VkDescriptorSetLayout setLayout_ = VK_NULL_HANDLE;
    VkPipelineLayout layout_ = VK_NULL_HANDLE;
    VkPipeline pipeline_ = VK_NULL_HANDLE;
};

// A global barrier: compute writes so far are visible to later compute reads.
void computeToCompute(VkCommandBuffer cmd);
// Compute writes so far are visible to the host once the command buffer completes.
void computeToHost(VkCommandBuffer cmd);

}  // namespace grotto
