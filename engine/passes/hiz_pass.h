#pragma once
// Depth tiles for occlusion culling. Reads: the G-buffer depth (shader read-only).
// Writes: the farthest depth of each tile into a host-visible buffer the CPU reads
// once the submission has finished (engine/frame/chunk_culling.h tests boxes against it).
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

class HizPass {
public:
    explicit HizPass(vk::Context& ctx);
    ~HizPass();

    // Samples the depth; timed as part of the G-buffer.
    static PassDecl declare() { return {nullptr, {{TargetId::Depth, Access::Sampled}}}; }
    // Records the reduction of `depth` (width x height) and a barrier making it
    // visible to the host; the buffer is made or remade for the size.
    void record(VkCommandBuffer cmd, const vk::Image& depth);
    // After the submission has finished.
    DepthTiles tiles() const;

private:
    vk::Context& ctx_;
    ComputePass pass_;
    vk::Buffer buffer_;
    uint32_t width_ = 0, height_ = 0;
};

}  // namespace grotto
