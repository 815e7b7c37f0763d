#include "app/viewer/presenter.h"

#include <imgui.h>
#include <imgui_impl_vulkan.h>

#include <cstring>

namespace grotto::viewer {
namespace {

void checkImgui(VkResult r) { VK_CHECK(r); }

}  // namespace

Presenter::Presenter(vk::Context& ctx, VkExtent2D framebuffer, bool vsync)
    : ctx_(ctx), swapchain_(ctx, vsync), wanted_(framebuffer) {
    hasImages_ = swapchain_.recreate(framebuffer);
    if (!hasImages_) throw Error("window", "the window has no size", "give --size a positive width and height");

    // The panel's pass draws over the blitted frame and leaves the image ready to present.
    VkAttachmentDescription attachment{.format = swapchain_.format,
                                       .samples = VK_SAMPLE_COUNT_1_BIT,
                                       .loadOp = VK_ATTACHMENT_LOAD_OP_LOAD,
                                       .storeOp = VK_ATTACHMENT_STORE_OP_STORE,
                                       .stencilLoadOp = VK_ATTACHMENT_LOAD_OP_DONT_CARE,
                                       .stencilStoreOp = VK_ATTACHMENT_STORE_OP_DONT_CARE,
                                       .initialLayout = VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
                                       .finalLayout = VK_IMAGE_LAYOUT_PRESENT_SRC_KHR};
    VkAttachmentReference ref{0, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL};
    VkSubpassDescription subpass{.pipelineBindPoint = VK_PIPELINE_BIND_POINT_GRAPHICS,
                                 .colorAttachmentCount = 1,
                                 .pColorAttachments = &ref};
    VkSubpassDependency afterBlit{.srcSubpass = VK_SUBPASS_EXTERNAL,
                                  .dstSubpass = 0,
                                  .srcStageMask = VK_PIPELINE_STAGE_TRANSFER_BIT,
                                  .dstStageMask = VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT,
                                  .srcAccessMask = VK_ACCESS_TRANSFER_WRITE_BIT,
                                  .dstAccessMask = VK_ACCESS_COLOR_ATTACHMENT_READ_BIT |
                                                   VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT};
    VkRenderPassCreateInfo rp{.sType = VK_STRUCTURE_TYPE_RENDER_PASS_CREATE_INFO,
                              .attachmentCount = 1,
                              .pAttachments = &attachment,
                              .subpassCount = 1,
                              .pSubpasses = &subpass,
                              .dependencyCount = 1,
                              .pDependencies = &afterBlit};
    VK_CHECK(vkCreateRenderPass(ctx.device, &rp, nullptr, &uiPass_));
    VkDescriptorPoolSize size{VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 8};
    VkDescriptorPoolCreateInfo dp{.sType = VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO,
                                  .flags = VK_DESCRIPTOR_POOL_CREATE_FREE_DESCRIPTOR_SET_BIT,
                                  .maxSets = 8,
                                  .poolSizeCount = 1,
                                  .pPoolSizes = &size};
    VK_CHECK(vkCreateDescriptorPool(ctx.device, &dp, nullptr, &uiPool_));
    cmd_ = vk::allocateCommandBuffer(ctx);
    fence_ = vk::createFence(ctx);
    VkSemaphoreCreateInfo sci{.sType = VK_STRUCTURE_TYPE_SEMAPHORE_CREATE_INFO};
    VK_CHECK(vkCreateSemaphore(ctx.device, &sci, nullptr, &acquired_));
    createTargets();

    ImGui_ImplVulkan_InitInfo init{};
    init.Instance = ctx.instance;
    init.PhysicalDevice = ctx.physical;
    init.Device = ctx.device;
    init.QueueFamily = ctx.queueFamily;
    init.Queue = ctx.queue;
    init.DescriptorPool = uiPool_;
    init.MinImageCount = 2;
    init.ImageCount = uint32_t(std::max<size_t>(swapchain_.images.size(), 2));
    init.MSAASamples = VK_SAMPLE_COUNT_1_BIT;
    init.CheckVkResultFn = checkImgui;
    ImGui_ImplVulkan_Init(&init, uiPass_);
    ctx.submitAndWait([](VkCommandBuffer cmd) { ImGui_ImplVulkan_CreateFontsTexture(cmd); });
    ImGui_ImplVulkan_DestroyFontUploadObjects();
}

Presenter::~Presenter() {
    vkDeviceWaitIdle(ctx_.device);
    ImGui_ImplVulkan_Shutdown();
    releaseTargets();
    vkDestroySemaphore(ctx_.device, acquired_, nullptr);
    vkDestroyFence(ctx_.device, fence_, nullptr);
    vkFreeCommandBuffers(ctx_.device, ctx_.commandPool, 1, &cmd_);
    vkDestroyDescriptorPool(ctx_.device, uiPool_, nullptr);
    vkDestroyRenderPass(ctx_.device, uiPass_, nullptr);
}

void Presenter::createTargets() {
    VkSemaphoreCreateInfo sci{.sType = VK_STRUCTURE_TYPE_SEMAPHORE_CREATE_INFO};
    for (VkImageView view : swapchain_.views) {
        VkFramebufferCreateInfo fb{.sType = VK_STRUCTURE_TYPE_FRAMEBUFFER_CREATE_INFO,
                                   .renderPass = uiPass_,
                                   .attachmentCount = 1,
                                   .pAttachments = &view,
                                   .width = swapchain_.extent.width,
                                   .height = swapchain_.extent.height,
                                   .layers = 1};
        VK_CHECK(vkCreateFramebuffer(ctx_.device, &fb, nullptr, &framebuffers_.emplace_back()));
        VK_CHECK(vkCreateSemaphore(ctx_.device, &sci, nullptr, &done_.emplace_back()));
    }
}

void Presenter::releaseTargets() {
    vkDeviceWaitIdle(ctx_.device);
    for (VkFramebuffer f : framebuffers_) vkDestroyFramebuffer(ctx_.device, f, nullptr);
    for (VkSemaphore s : done_) vkDestroySemaphore(ctx_.device, s, nullptr);
    framebuffers_.clear();
    done_.clear();
}

void Presenter::resize(VkExtent2D framebuffer) {
    wanted_ = framebuffer;
    releaseTargets();
    hasImages_ = swapchain_.recreate(framebuffer);
    if (hasImages_) createTargets();
}

bool Presenter::present(const vk::Image& color, ImDrawData* ui, std::vector<uint8_t>* capture) {
    if (!hasImages_) return false;
    uint32_t index = 0;
    if (!swapchain_.acquire(acquired_, index)) {
        resize(wanted_);
        return false;
    }
    const VkImage target = swapchain_.images[index];
    const VkExtent2D e = swapchain_.extent;
    vk::Buffer readback;
    if (capture) readback = vk::createBuffer(ctx_, VkDeviceSize(e.width) * e.height * 4, VK_BUFFER_USAGE_TRANSFER_DST_BIT, true);

    VK_CHECK(vkResetCommandBuffer(cmd_, 0));
    VkCommandBufferBeginInfo bi{.sType = VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO,
                                .flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT};
    VK_CHECK(vkBeginCommandBuffer(cmd_, &bi));
    auto barrier = [&](VkImage image, VkImageLayout from, VkImageLayout to, VkPipelineStageFlags srcStage,
                       VkAccessFlags srcAccess, VkPipelineStageFlags dstStage, VkAccessFlags dstAccess) {
        vk::transition(cmd_, image, VK_IMAGE_ASPECT_COLOR_BIT, from, to, srcStage, srcAccess, dstStage, dstAccess);
    };
    const auto transfer = VK_PIPELINE_STAGE_TRANSFER_BIT;
    // The frame's image, written by compute or a transfer in an earlier submission.
    const auto compute = VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT;
    barrier(color.image, VK_IMAGE_LAYOUT_GENERAL, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, compute | transfer,
            VK_ACCESS_SHADER_WRITE_BIT | VK_ACCESS_TRANSFER_WRITE_BIT, transfer, VK_ACCESS_TRANSFER_READ_BIT);
    barrier(target, VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, transfer, 0, transfer,
            VK_ACCESS_TRANSFER_WRITE_BIT);
    VkImageBlit blit{.srcSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1},
                     .srcOffsets = {{0, 0, 0}, {int32_t(color.extent.width), int32_t(color.extent.height), 1}},
                     .dstSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1},
                     .dstOffsets = {{0, 0, 0}, {int32_t(e.width), int32_t(e.height), 1}}};
    const bool sameSize = color.extent.width == e.width && color.extent.height == e.height;
    vkCmdBlitImage(cmd_, color.image, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, target, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
                   1, &blit, sameSize ? VK_FILTER_NEAREST : VK_FILTER_LINEAR);
    barrier(color.image, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, VK_IMAGE_LAYOUT_GENERAL, transfer, 0, compute | transfer,
            0);  // back in GENERAL, as the renderer keeps it
    VkRenderPassBeginInfo rb{.sType = VK_STRUCTURE_TYPE_RENDER_PASS_BEGIN_INFO,
                             .renderPass = uiPass_,
                             .framebuffer = framebuffers_[index],
                             .renderArea = {{0, 0}, e}};
    vkCmdBeginRenderPass(cmd_, &rb, VK_SUBPASS_CONTENTS_INLINE);
    if (ui) ImGui_ImplVulkan_RenderDrawData(ui, cmd_);
    vkCmdEndRenderPass(cmd_);
    if (capture) {
        barrier(target, VK_IMAGE_LAYOUT_PRESENT_SRC_KHR, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL,
                VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT, VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT, transfer,
                VK_ACCESS_TRANSFER_READ_BIT);
        VkBufferImageCopy region{.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1},
                                 .imageExtent = {e.width, e.height, 1}};
        vkCmdCopyImageToBuffer(cmd_, target, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, readback.buffer, 1, &region);
        barrier(target, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, VK_IMAGE_LAYOUT_PRESENT_SRC_KHR, transfer,
                VK_ACCESS_TRANSFER_READ_BIT, VK_PIPELINE_STAGE_BOTTOM_OF_PIPE_BIT, 0);
    }
    VK_CHECK(vkEndCommandBuffer(cmd_));
    const VkPipelineStageFlags waitStage = VK_PIPELINE_STAGE_TRANSFER_BIT;
    VkSubmitInfo si{.sType = VK_STRUCTURE_TYPE_SUBMIT_INFO,
                    .waitSemaphoreCount = 1,
                    .pWaitSemaphores = &acquired_,
                    .pWaitDstStageMask = &waitStage,
                    .commandBufferCount = 1,
                    .pCommandBuffers = &cmd_,
                    .signalSemaphoreCount = 1,
                    .pSignalSemaphores = &done_[index]};
    VK_CHECK(vkResetFences(ctx_.device, 1, &fence_));
    VK_CHECK(vkQueueSubmit(ctx_.queue, 1, &si, fence_));
    VK_CHECK(vkWaitForFences(ctx_.device, 1, &fence_, VK_TRUE, UINT64_MAX));
    if (capture) {
        // 8-bit sRGB in the swapchain's channel order; RGB out.
        const bool bgra = swapchain_.format == VK_FORMAT_B8G8R8A8_SRGB;
        const auto* px = static_cast<const uint8_t*>(readback.mapped());
        const size_t n = size_t(e.width) * e.height;
        capture->resize(3 * n);
        for (size_t i = 0; i < n; ++i)
            for (int c = 0; c < 3; ++c) (*capture)[3 * i + c] = px[4 * i + (bgra ? 2 - c : c)];
        vk::destroy(ctx_, readback);
    }
    if (!swapchain_.present(done_[index], index)) resize(wanted_);
    return true;
}

}  // namespace grotto::viewer
