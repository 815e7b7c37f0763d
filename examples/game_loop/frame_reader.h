#pragma once
// The game's own reads of Grotto's images, as a game compositing them would: each
// frame's display image copied into host memory by the game's command buffer on
// Grotto's queue, waiting on the GPU for the frame's timeline value. Two slots, so
// the copy of frame N runs while Grotto renders frame N + 1.
#include "vulkan_device.h"

#include <grotto/grotto.h>

#include <vector>

class FrameReader {
public:
    FrameReader(const GameDevice& game, VkExtent2D extent);
    ~FrameReader();
    FrameReader(const FrameReader&) = delete;
    FrameReader& operator=(const FrameReader&) = delete;

    // Submits the copy of `frame`'s display image (RGBA16F) into slot `slot`'s
    // buffer, after the frame's timeline value; first waits for the slot's last copy.
    void read(const grotto::RenderedFrame& frame, int slot);
    // Waits for slot `slot`'s copy and returns the pixels, four halves each.
    std::vector<uint16_t> pixels(int slot);

    // Copies `color` (RGBA32F, after a finished frame) to host memory at once.
    std::vector<float> copyNow(const grotto::RenderedImage& color);

private:
    struct Slot {
        VkBuffer buffer = VK_NULL_HANDLE;
        VkDeviceMemory memory = VK_NULL_HANDLE;
        VkCommandBuffer cmd = VK_NULL_HANDLE;
        VkFence fence = VK_NULL_HANDLE;
        bool pending = false;
    };
    void makeBuffer(VkDeviceSize bytes, VkBuffer& buffer, VkDeviceMemory& memory) const;
    // Records image -> buffer with the barriers grotto.h asks for, image back in GENERAL.
    void recordCopy(VkCommandBuffer cmd, const grotto::RenderedImage& image, VkBuffer buffer) const;

    const GameDevice& game_;
    VkExtent2D extent_;
    VkCommandPool pool_ = VK_NULL_HANDLE;
    Slot slots_[2];
};
