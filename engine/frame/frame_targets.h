#pragma once
// Every render target of a frame, declared once: one row each (format, size, usage,
// when it exists, how many copies a history keeps, its first layout). Making,
// freeing, the bytes they hold and the memory estimate (render_memory.h) all read
// these rows, so a target added here is counted everywhere.
#include "engine/ao_settings.h"
#include "engine/passes/ao_targets.h"
#include "engine/passes/gbuffer_pass.h"
#include "engine/vk/resources.h"

#include <array>
#include <cstdint>
#include <span>

namespace grotto {

// What decides which targets a frame has, and their sizes.
struct FrameShape {
    uint32_t width = 0, height = 0;
    AoOptions ao;
    bool shadows = false;        // sun shadows (the lighting asks for them and the scene has occupancy)
    bool softShadows = false;    // a sun of finite size: its shadow keeps a history
    bool movingObjects = false;  // with the temporal pass: motion vectors
    bool display = false;        // the tone-mapped display image (Renderer::setDisplayImage)
    bool aoAov = false;          // the full-resolution AO a read-back with AOVs upsamples into

    bool temporal() const { return ao.enabled && ao.chain.temporalHistory > 0; }
    bool motion() const { return movingObjects && temporal(); }
    VkExtent2D frame() const { return {width, height}; }
    VkExtent2D aoExtent() const;  // the AO chain's resolution: the frame's, or half of it rounded up
};

// The shape of a world's frames at a size, as the commands render them: from a
// scene uploaded from the world (so with occupancy, and sun shadows where the
// lighting has them), with its objects when `objects`.
FrameShape worldFrameShape(const voxel::WorldDesc& desc, uint32_t width, uint32_t height, const AoOptions& ao,
                           bool objects = true);

enum class TargetId {
    Depth, Surface, Motion, Color, Display, Shadow, ShadowHistory,
    AoDepthAtlas, AoRaw, AoSpatial0, AoSpatial1, AoHistory, AoFull,
};

enum class TargetSize {
    Frame,       // the frame's pixels
    Ao,          // the AO chain's resolution (FrameShape::aoExtent)
    DepthAtlas,  // every depth MIP of the AO resolution side by side (depthMipLayout)
};

struct TargetRow {
    TargetId id;
    VkFormat format;
    TargetSize size;
    VkImageUsageFlags usage;
    bool (*exists)(const FrameShape&);
    bool placeholder;       // where it does not exist, a 1x1 image stands in: its pass binds it regardless
    uint32_t copies;        // 2: a history, this frame's and the last, ping-ponged
    VkImageLayout initial;  // GENERAL: laid out once when made; UNDEFINED: every frame lays it out
};

std::span<const TargetRow> targetRows();
// The row's image size in `shape`: 1x1 for a placeholder, {0, 0} where it has none.
VkExtent2D targetExtent(const TargetRow& row, const FrameShape& shape);

// The images themselves, made and freed by the rows, kept under the names the
// passes take them by.
class FrameTargets {
public:
    explicit FrameTargets(vk::Context& ctx) : ctx_(ctx) {}
    ~FrameTargets() { release(); }
    FrameTargets(const FrameTargets&) = delete;
    FrameTargets& operator=(const FrameTargets&) = delete;

    // Makes the images `shape` has and frees those it lacks, keeping those whose
    // size stays; the first transitions of new GENERAL images go into `cmd`. The
    // caller sees that the GPU uses none of the freed ones. Returns whether
    // anything was made or freed.
    bool update(const FrameShape& shape, VkCommandBuffer cmd);
    bool update(const FrameShape& shape);  // in a submission of its own, waited for
    void release();

    const FrameShape& shape() const { return shape_; }
    size_t bytes() const;  // the device memory of every image
    const vk::Image& image(TargetId id, uint32_t copy = 0) const;
    const GBufferTargets& gbuffer() const { return gbuffer_; }
    const AoTargets& ao() const { return ao_; }

private:
    vk::Image& slot(TargetId id, uint32_t copy);

    vk::Context& ctx_;
    FrameShape shape_;
    GBufferTargets gbuffer_;
    AoTargets ao_;
    vk::Image color_, display_, shadow_;
    std::array<vk::Image, 2> shadowHistory_;
};

}  // namespace grotto
