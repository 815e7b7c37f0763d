#pragma once
// The AO chain's images at AO resolution (half the frame's, or all of it with
// --ao-full-res), as the passes take them; FrameTargets makes them.
#include "engine/vk/resources.h"

#include "shaders/shared/gtao.h"

#include <array>

namespace grotto {

struct AoTargets {
    VkExtent2D half{};                                         // the AO resolution; none without AO
    vk::Image depthAtlas;                                      // R32F view depth, every MIP (see depthMipLayout)
    vk::Image thickness;                                       // R32F: VBAO's voxel thickness, the same layout
                                                               // (1x1 unless voxelThickness)
    vk::Image bentNormal;                                      // RGBA16F: VBAO's bent normal, world space, zero
                                                               // for the sky (1x1 but with VBAO)
    vk::Image raw;                                             // RGBA32F: visibility, packed edges, depth, face + 1
    std::array<vk::Image, 2> spatial;                          // RGBA32F: denoiser ping-pong, same layout (as many
                                                               // as the passes need: none, one, or two)
    std::array<vk::Image, 2> history;                          // RGBA32F: temporal output, this frame's and the last
                                                               // (visibility, history length, depth, face + 1)
    vk::Image full;                                            // R32F: upsampled visibility, for the AO AOV
                                                               // (made at the first read-back that wants it)

    // The denoiser's output after `passes` passes (the raw AO when there are none).
    const vk::Image& denoised(uint32_t passes) const { return passes == 0 ? raw : spatial[(passes - 1) % 2]; }
};

// Where each depth MIP sits in the atlas (xy offset, zw size): MIP 0 at the origin,
// MIPs 1-4 in a column of equal slots to its right; MIP k is ceil(half / 2^k).
struct DepthMipLayout {
    std::array<glm::ivec4, GROTTO_GTAO_DEPTH_MIPS> mips;
    VkExtent2D atlas;
};
DepthMipLayout depthMipLayout(VkExtent2D half);

}  // namespace grotto
