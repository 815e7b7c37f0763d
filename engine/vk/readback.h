#pragma once
// Copies a whole image to host memory (tightly packed rows) and restores its layout.
#include "engine/vk/resources.h"

#include <cstdint>
#include <vector>

namespace grotto::vk {

std::vector<uint8_t> readImage(Context& ctx, const Image& image, VkImageLayout layout, uint32_t bytesPerPixel);

}  // namespace grotto::vk
