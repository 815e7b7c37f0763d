#pragma once
// Sun shadows at full resolution (shadow.comp): one exact ray per pixel toward the
// sun through the world's voxels. Reads: the G-buffer's depth and surface ids, the
// objects' normal tables, the trace constants and the occupancy. Writes: R32F
// shadow, 1 = sunlit, 0 = blocked or facing away. Objects cast no shadow.
#include "engine/occupancy.h"
#include "engine/passes/compute_pass.h"
#include "engine/passes/gbuffer_pass.h"

namespace grotto {

class ShadowPass {
public:
    explicit ShadowPass(vk::Context& ctx);
    void record(VkCommandBuffer cmd, const GBufferTargets& gbuffer, const vk::Buffer& objectUniforms,
                const vk::Image& shadow, const vk::Buffer& traceConstants, const GpuOccupancy& occupancy);

private:
    vk::Context& ctx_;
    ComputePass pass_;
};

}  // namespace grotto
