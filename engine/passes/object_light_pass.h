#pragma once
// Objects' part in the face cache's light (object_light.comp), for --ao cache with
// objects: at full resolution, only where an object is in view of a surface, the
// AO and sky light objects take from world surfaces, and objects' own. Reads: the
// G-buffer's depth and surface ids, the objects' normal tables, the trace constants,
// the occupancy and the objects' grids, the palette and the face cache (with full
// light: the light world faces send), and the last frame's RGBA32UI history.
// Writes: RGBA16F light (AO, horizon and zenith sky weights; with full light, rgb
// light) and the next history.
#include "engine/frame/frame_plan.h"
#include "engine/frame/pass_decl.h"
#include "engine/passes/compute_pass.h"
#include "engine/passes/gbuffer_pass.h"
#include "engine/scene/face_cache_gpu.h"
#include "engine/scene/occupancy.h"

namespace grotto {

class ObjectLightPass {
public:
    static constexpr uint32_t kRays = 8;  // per pixel in view of an object, per frame
    explicit ObjectLightPass(vk::Context& ctx);
    static bool runs(const FramePlan& plan) { return plan.objectLight; }
    // Reads history image `history`, writes the other.
    static PassDecl declare();
    void record(VkCommandBuffer cmd, const GBufferTargets& gbuffer, const vk::Buffer& objectUniforms,
                const vk::Image& light, const vk::Image& history, const vk::Image& nextHistory,
                const vk::Buffer& traceConstants, const GpuOccupancy& occupancy, const vk::Buffer& objectGrids,
                const vk::Buffer& palette, const GpuFaceCache& faceCache);

private:
    vk::Context& ctx_;
    ComputePass pass_;
};

}  // namespace grotto
