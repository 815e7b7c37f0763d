#pragma once
// Depth tiles for occlusion culling. Reads: the G-buffer depth (shader read-only).
// Writes: the farthest depth of each tile into a host-visible buffer (a frame
// slot's, HizReadback) the CPU reads once the submission has finished
// (engine/frame/chunk_culling.h tests boxes against it).
#include "engine/frame/frame_plan.h"
#include "engine/frame/pass_decl.h"
#include "engine/passes/compute_pass.h"
#include "engine/vk/resources.h"

#include <span>

namespace grotto {

inline constexpr uint32_t kHizTile = 8;  // pixels per tile side

// The tiles as the CPU sees them: row 0 on top, as the image.
struct DepthTiles {
    uint32_t width = 0, height = 0;  // of the image, pixels
    uint32_t tilesX = 0, tilesY = 0;
    std::span<const float> farthest;  // reverse-Z depth per tile, 0 where sky shows
};

// Where a frame's tiles land: a host-visible buffer, made for the depth's size.
struct HizReadback {
    vk::Buffer buffer;
    uint32_t width = 0, height = 0;  // of the depth it was made for
    DepthTiles tiles() const;        // after the submission that wrote them has finished
};

class HizPass {
public:
    explicit HizPass(vk::Context& ctx);
    static bool runs(const FramePlan&) { return true; }

    // Samples the depth; timed as part of the G-buffer.
    static PassDecl declare() { return {nullptr, {{TargetId::Depth, Access::Sampled}}}; }
    // Records the reduction of `depth` (width x height) into `into` and a barrier
    // making it visible to the host; its buffer is made or remade for the size (no
    // frame in flight may use it).
    void record(VkCommandBuffer cmd, const vk::Image& depth, HizReadback& into);

private:
    vk::Context& ctx_;
    ComputePass pass_;
};

}  // namespace grotto
