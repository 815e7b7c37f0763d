#pragma once
// The half-resolution AO chain's images, all kept in VK_IMAGE_LAYOUT_GENERAL.
#include "engine/vk/resources.h"

#include "shaders/shared/gtao.h"

#include <array>

namespace grotto {

struct AoTargets {
    VkExtent2D half{};                                         // ceil(full / 2)
    std::array<vk::Image, GROTTO_GTAO_DEPTH_MIPS> depthMips;   // R32F view depth, MIP k at ceil(half / 2^k)
    vk::Image raw;                                             // RG32F: visibility, packed edges
    std::array<vk::Image, 2> spatial;                          // RG32F: denoiser ping-pong
    vk::Image full;                                            // R32F: upsampled visibility

    // The denoiser's output after `passes` passes (the raw AO when there are none).
    const vk::Image& denoised(uint32_t passes) const { return passes == 0 ? raw : spatial[(passes - 1) % 2]; }
};

}  // namespace grotto
