#pragma once
// A window's swapchain (the viewer): its images, and their acquire and present.
// Recreated whole when the window's size changes or the surface reports it out of
// date; a minimised window (zero size) has none until restored.
#include "engine/vk/context.h"

#include <vector>

namespace grotto::vk {

class Swapchain {
public:
    // `vsync`: FIFO; otherwise MAILBOX or IMMEDIATE where the surface offers one.
    Swapchain(Context& ctx, bool vsync);
    ~Swapchain();
    Swapchain(const Swapchain&) = delete;
    Swapchain& operator=(const Swapchain&) = delete;

    // (Re)creates the images for a framebuffer of `extent` (the surface's own
    // extent wins where it dictates one). False for a zero size: nothing to present.
    bool recreate(VkExtent2D extent);
    // The next image, signalling `ready` when it may be written; false when the
    // swapchain is out of date (recreate, then try again).
    bool acquire(VkSemaphore ready, uint32_t& index);
    // Presents image `index` after `done`; false when out of date or suboptimal.
    bool present(VkSemaphore done, uint32_t index);

    VkSwapchainKHR handle = VK_NULL_HANDLE;
    VkFormat format = VK_FORMAT_UNDEFINED;  // an sRGB format: writes encode linear colour
    VkExtent2D extent{};
    std::vector<VkImage> images;
    std::vector<VkImageView> views;

private:
    void releaseViews();
    Context& ctx_;
    bool vsync_;
};

}  // namespace grotto::vk
