#pragma once
// The memory a Renderer of a given size needs, estimated before anything is
// allocated, and the check that refuses a size the device cannot hold: a bare
// out-of-memory from the driver, halfway through, names nothing the user set.
#include "engine/ao_settings.h"
#include "engine/vk/context.h"

#include <cstdint>
#include <string>

namespace grotto {

struct RenderMemory {
    uint64_t targetBytes = 0;   // the render targets: G-buffer, colour, the AO chain's (and its AOV)
    uint64_t stagingBytes = 0;  // the largest read-back buffer (the colour image's)
    uint64_t largestBytes = 0;  // the largest single allocation among both
    uint64_t hostBytes = 0;     // a read-back with every AOV (FrameImages), in host memory
};

// Exact for the targets up to the driver's padding of each image (2 % at 333x177 on lavapipe).
RenderMemory estimateRenderMemory(uint32_t width, uint32_t height, const AoOptions& ao);

// Throws grotto::Error (input), naming `where` with the size and the estimate,
// when rendering at that size cannot fit the device: an allocation larger than
// its maxMemoryAllocationSize, or targets and staging larger than its largest
// device-local heap and read-back larger than the machine's physical memory. On
// a CPU device (lavapipe) the targets live in host memory too, so there all of
// it is held against the physical memory.
void requireRenderFits(const vk::Context& ctx, uint32_t width, uint32_t height, const AoOptions& ao,
                       const std::string& where);

}  // namespace grotto
