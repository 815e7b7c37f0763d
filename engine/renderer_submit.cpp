// How the renderer's frames reach the queue: the slot's command buffer begun, one
// submission per frame after the game's waits and signalling the timeline, and
// waits for a frame on the CPU.
#include "engine/renderer.h"

#include "engine/vk/check.h"

#include <vector>

namespace grotto {

VkCommandBuffer Renderer::beginCommands() {
    const VkCommandBuffer cmd = slot().cmd;
    VK_CHECK(vkResetCommandBuffer(cmd, 0));
    const VkCommandBufferBeginInfo bi{.sType = VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO,
                                      .flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT};
    VK_CHECK(vkBeginCommandBuffer(cmd, &bi));
    return cmd;
}

void Renderer::submitCommands(VkCommandBuffer cmd, std::span<const FrameWait> waits) {
    VK_CHECK(vkEndCommandBuffer(cmd));
    std::vector<VkSemaphore> semaphores;
    std::vector<uint64_t> values;
    std::vector<VkPipelineStageFlags> stages;
    for (const FrameWait& w : waits) {
        semaphores.push_back(w.semaphore);
        values.push_back(w.value);  // a binary semaphore's is ignored
        stages.push_back(w.stages);
    }
    const uint64_t signal = ++submitted_;
    const VkTimelineSemaphoreSubmitInfo timeline{.sType = VK_STRUCTURE_TYPE_TIMELINE_SEMAPHORE_SUBMIT_INFO,
                                                 .waitSemaphoreValueCount = uint32_t(values.size()),
                                                 .pWaitSemaphoreValues = values.data(),
                                                 .signalSemaphoreValueCount = 1,
                                                 .pSignalSemaphoreValues = &signal};
    const VkSubmitInfo si{.sType = VK_STRUCTURE_TYPE_SUBMIT_INFO,
                          .pNext = &timeline,
                          .waitSemaphoreCount = uint32_t(semaphores.size()),
                          .pWaitSemaphores = semaphores.data(),
                          .pWaitDstStageMask = stages.data(),
                          .commandBufferCount = 1,
                          .pCommandBuffers = &cmd,
                          .signalSemaphoreCount = 1,
                          .pSignalSemaphores = &timeline_};
    VK_CHECK(vkQueueSubmit(ctx_.queue, 1, &si, VK_NULL_HANDLE));
    slot().done = signal;
}

void Renderer::waitFor(uint64_t timelineValue) {
    if (timelineValue == 0) return;
    const VkSemaphoreWaitInfo wi{.sType = VK_STRUCTURE_TYPE_SEMAPHORE_WAIT_INFO,
                                 .semaphoreCount = 1,
                                 .pSemaphores = &timeline_,
                                 .pValues = &timelineValue};
    VK_CHECK(vkWaitSemaphores(ctx_.device, &wi, UINT64_MAX));
}

void Renderer::finishFrames() { waitFor(submitted_); }

void Renderer::submitAndWait(VkCommandBuffer cmd) {
    submitCommands(cmd);
    waitFor(submitted_);
}

}  // namespace grotto
