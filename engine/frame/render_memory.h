#pragma once
// The memory a Renderer of a given size needs, estimated before anything is
// allocated, and the check that refuses a size the device cannot hold: a bare
// out-of-memory from the driver, halfway through, names nothing the user set.
#include "engine/frame/frame_targets.h"
#include "engine/vk/context.h"

#include <cstdint>
#include <string>

namespace grotto {

struct RenderMemory {
    uint64_t targetBytes = 0;   // the render targets the plan has (frame_targets.h)
    uint64_t stagingBytes = 0;  // the largest read-back buffer (the colour image's)
    uint64_t largestBytes = 0;  // the largest single allocation among both
    uint64_t hostBytes = 0;     // a read-back with every AOV (FrameImages), in host memory
};

// The targets from the same rows the renderer makes them by, each at the size the
// device asks for it where it says beforehand (Vulkan 1.3: then exact), else at
// texels x texel size (short of the driver's padding, 2 % at 333x177 on lavapipe).
RenderMemory estimateRenderMemory(const vk::Context& ctx, const FramePlan& plan);
// A CPU device (lavapipe): its memory is the host's.
bool cpuDevice(const vk::Context& ctx);
// What a renderer of this shape holds in host memory: a read-back with every AOV
// and its staging, and on a CPU device the targets too.
uint64_t rendererHostBytes(const vk::Context& ctx, const FramePlan& plan);
// Host memory for a read-back with every AOV (FrameImages); needs no device.
uint64_t readbackHostBytes(const FramePlan& plan);

// Throws grotto::Error (input), naming `where` with the size and the estimate,
// when rendering at that size cannot fit the device: an allocation larger than
// its maxMemoryAllocationSize, or targets and staging larger than its largest
// device-local heap and read-back larger than the machine's physical memory. On
// a CPU device (lavapipe) the targets live in host memory too, so there all of
// it is held against the physical memory. A read-back with AOVs may come at any
// frame, so its AO target counts whatever plan.aoAov says.
void requireRenderFits(const vk::Context& ctx, const FramePlan& plan, const std::string& where);

}  // namespace grotto
