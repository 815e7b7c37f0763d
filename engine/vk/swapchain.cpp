#include "engine/vk/swapchain.h"

#include <algorithm>

namespace grotto::vk {

Swapchain::Swapchain(Context& ctx, bool vsync) : ctx_(ctx), vsync_(vsync) {
    if (!ctx.surface) throw Error::internal("Swapchain", "the context was made without a window surface");
}

Swapchain::~Swapchain() {
    vkDeviceWaitIdle(ctx_.device);
    releaseViews();
    if (handle) vkDestroySwapchainKHR(ctx_.device, handle, nullptr);
}

void Swapchain::releaseViews() {
    for (VkImageView v : views) vkDestroyImageView(ctx_.device, v, nullptr);
    views.clear();
    images.clear();
}

bool Swapchain::recreate(VkExtent2D wanted) {
    vkDeviceWaitIdle(ctx_.device);
    VkSurfaceCapabilitiesKHR caps;
    VK_CHECK(vkGetPhysicalDeviceSurfaceCapabilitiesKHR(ctx_.physical, ctx_.surface, &caps));
    VkExtent2D e = caps.currentExtent.width != UINT32_MAX ? caps.currentExtent : wanted;
    e.width = std::clamp(e.width, caps.minImageExtent.width, caps.maxImageExtent.width);
    e.height = std::clamp(e.height, caps.minImageExtent.height, caps.maxImageExtent.height);
    if (wanted.width == 0 || wanted.height == 0 || e.width == 0 || e.height == 0) return false;

    uint32_t n = 0;
    vkGetPhysicalDeviceSurfaceFormatsKHR(ctx_.physical, ctx_.surface, &n, nullptr);
    std::vector<VkSurfaceFormatKHR> formats(n);
    vkGetPhysicalDeviceSurfaceFormatsKHR(ctx_.physical, ctx_.surface, &n, formats.data());
    VkSurfaceFormatKHR chosen{VK_FORMAT_UNDEFINED, VK_COLOR_SPACE_SRGB_NONLINEAR_KHR};
    for (const VkSurfaceFormatKHR& f : formats)
        if ((f.format == VK_FORMAT_B8G8R8A8_SRGB || f.format == VK_FORMAT_R8G8B8A8_SRGB) &&
            f.colorSpace == VK_COLOR_SPACE_SRGB_NONLINEAR_KHR)
            chosen = f;
    if (chosen.format == VK_FORMAT_UNDEFINED)
        throw Error("window", "the window's surface offers no 8-bit sRGB format", "try another GROTTO_DEVICE");

    VkPresentModeKHR mode = VK_PRESENT_MODE_FIFO_KHR;  // always available
    if (!vsync_) {
        vkGetPhysicalDeviceSurfacePresentModesKHR(ctx_.physical, ctx_.surface, &n, nullptr);
        std::vector<VkPresentModeKHR> modes(n);
        vkGetPhysicalDeviceSurfacePresentModesKHR(ctx_.physical, ctx_.surface, &n, modes.data());
        for (VkPresentModeKHR m : {VK_PRESENT_MODE_IMMEDIATE_KHR, VK_PRESENT_MODE_MAILBOX_KHR})
            if (std::find(modes.begin(), modes.end(), m) != modes.end()) mode = m;
    }
    uint32_t count = caps.minImageCount + 1;
    if (caps.maxImageCount > 0) count = std::min(count, caps.maxImageCount);
    // Transfer dst: the frame is blitted in; transfer src: the window can be captured.
    const VkImageUsageFlags usage = VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT |
                                    (caps.supportedUsageFlags & VK_IMAGE_USAGE_TRANSFER_SRC_BIT);
    VkSwapchainKHR old = handle;
    VkSwapchainCreateInfoKHR ci{.sType = VK_STRUCTURE_TYPE_SWAPCHAIN_CREATE_INFO_KHR,
                                .surface = ctx_.surface,
                                .minImageCount = count,
                                .imageFormat = chosen.format,
                                .imageColorSpace = chosen.colorSpace,
                                .imageExtent = e,
                                .imageArrayLayers = 1,
                                .imageUsage = usage,
                                .imageSharingMode = VK_SHARING_MODE_EXCLUSIVE,
                                .preTransform = caps.currentTransform,
                                .compositeAlpha = VK_COMPOSITE_ALPHA_OPAQUE_BIT_KHR,
                                .presentMode = mode,
                                .clipped = VK_TRUE,
                                .oldSwapchain = old};
    releaseViews();
    VK_CHECK(vkCreateSwapchainKHR(ctx_.device, &ci, nullptr, &handle));
    if (old) vkDestroySwapchainKHR(ctx_.device, old, nullptr);
    format = chosen.format;
    extent = e;
    vkGetSwapchainImagesKHR(ctx_.device, handle, &n, nullptr);
    images.resize(n);
    vkGetSwapchainImagesKHR(ctx_.device, handle, &n, images.data());
    for (VkImage image : images) {
        VkImageViewCreateInfo vi{.sType = VK_STRUCTURE_TYPE_IMAGE_VIEW_CREATE_INFO,
                                 .image = image,
                                 .viewType = VK_IMAGE_VIEW_TYPE_2D,
                                 .format = format,
                                 .subresourceRange = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1}};
        VkImageView view;
        VK_CHECK(vkCreateImageView(ctx_.device, &vi, nullptr, &view));
        views.push_back(view);
    }
    return true;
}

bool Swapchain::acquire(VkSemaphore ready, uint32_t& index) {
    const VkResult r = vkAcquireNextImageKHR(ctx_.device, handle, UINT64_MAX, ready, VK_NULL_HANDLE, &index);
    if (r == VK_ERROR_OUT_OF_DATE_KHR) return false;
    if (r != VK_SUBOPTIMAL_KHR) VK_CHECK(r);
    return true;
}

bool Swapchain::present(VkSemaphore done, uint32_t index) {
    VkPresentInfoKHR pi{.sType = VK_STRUCTURE_TYPE_PRESENT_INFO_KHR,
                        .waitSemaphoreCount = 1,
                        .pWaitSemaphores = &done,
                        .swapchainCount = 1,
                        .pSwapchains = &handle,
                        .pImageIndices = &index};
    const VkResult r = vkQueuePresentKHR(ctx_.queue, &pi);
    if (r == VK_ERROR_OUT_OF_DATE_KHR || r == VK_SUBOPTIMAL_KHR) return false;
    VK_CHECK(r);
    return true;
}

}  // namespace grotto::vk
