#pragma once
// Puts frames in the window: the renderer's display image (the colour through the
// tone map) or an AOV view, display-linear, is blitted into the swapchain's sRGB
// image (the blit encodes it, as the PNG writer does), Dear
// ImGui's panel is drawn over it, and the image is presented. Handles the
// swapchain going out of date (resize) and a minimised window (nothing to draw).
#include "engine/vk/resources.h"
#include "engine/vk/swapchain.h"

#include <cstdint>
#include <filesystem>
#include <optional>
#include <vector>

struct ImDrawData;

namespace grotto::viewer {

class Presenter {
public:
    // `framebuffer`: the window's size in pixels. Initialises ImGui's Vulkan backend
    // (ImGui's context and its GLFW backend must exist already).
    Presenter(vk::Context& ctx, VkExtent2D framebuffer, bool vsync);
    ~Presenter();
    Presenter(const Presenter&) = delete;
    Presenter& operator=(const Presenter&) = delete;

    // The window's framebuffer changed size (0 x 0 while minimised).
    void resize(VkExtent2D framebuffer);
    // Shows `color` (display-linear float RGBA, GENERAL, written by compute or transfers in earlier submissions), scaled to the
    // window, with `ui` on top. With `capture`, the presented image is also read back
    // as 8-bit sRGB RGB. False when nothing was presented (minimised, out of date).
    bool present(const vk::Image& color, ImDrawData* ui, std::vector<uint8_t>* capture = nullptr);
    VkExtent2D extent() const { return swapchain_.extent; }

private:
    void createTargets();   // render pass framebuffers and per-image semaphores
    void releaseTargets();

    vk::Context& ctx_;
    vk::Swapchain swapchain_;
    bool hasImages_ = false;
    VkExtent2D wanted_{};
    VkRenderPass uiPass_ = VK_NULL_HANDLE;
    VkDescriptorPool uiPool_ = VK_NULL_HANDLE;
    std::vector<VkFramebuffer> framebuffers_;
    std::vector<VkSemaphore> done_;  // per swapchain image: its commands finished, present may start
    VkSemaphore acquired_ = VK_NULL_HANDLE;
    VkCommandBuffer cmd_ = VK_NULL_HANDLE;
    VkFence fence_ = VK_NULL_HANDLE;
};

}  // namespace grotto::viewer
