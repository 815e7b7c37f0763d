#pragma once
// Every render target of a frame, declared once: one row each (format, size, usage,
// when it exists, how many copies a history keeps, whether it outlives a frame).
// Making, freeing, the bytes they hold and the memory estimate (render_memory.h)
// all read these rows, so a target added here is counted everywhere; the barriers
// and layout transitions between passes follow from what each pass declares it
// uses (pass_decl.h).
#include "engine/frame/frame_plan.h"
#include "engine/frame/pass_decl.h"
#include "engine/passes/ao_targets.h"
#include "engine/passes/gbuffer_pass.h"
#include "engine/vk/resources.h"

#include <array>
#include <cstdint>
#include <span>

namespace grotto {

enum class TargetSize {
    Frame,       // the frame's pixels
    Ao,          // the AO chain's resolution (FramePlan::aoExtent)
    DepthAtlas,  // every depth MIP of the AO resolution side by side (depthMipLayout)
};

struct TargetRow {
    TargetId id;
    VkFormat format;
    TargetSize size;
    VkImageUsageFlags usage;
    bool (*exists)(const FramePlan&);
    bool placeholder;  // where it does not exist, a 1x1 image stands in: its pass binds it regardless
    uint32_t copies;   // 2: a history, this frame's and the last, ping-ponged
    // The layout a frame finds it in: GENERAL, kept from the frame before (histories,
    // the AO chain's images, what a game may read between frames); UNDEFINED, its
    // contents are dropped at each frame's start (the G-buffer, the colour).
    VkImageLayout initial;
    bool (*advances)(const FramePlan&) = nullptr;  // a history: whether a frame of the plan writes it (flips its copies)
};

std::span<const TargetRow> targetRows();
// The row's image size in `plan`: 1x1 for a placeholder, {0, 0} where it has none.
VkExtent2D targetExtent(const TargetRow& row, const FramePlan& plan);

// The images themselves, made and freed by the rows, kept under the names the
// passes take them by.
class FrameTargets {
public:
    explicit FrameTargets(vk::Context& ctx) : ctx_(ctx) {}
    ~FrameTargets() { release(); }
    FrameTargets(const FrameTargets&) = delete;
    FrameTargets& operator=(const FrameTargets&) = delete;

    // Makes the images `plan` has and frees those it lacks, keeping those whose
    // size stays (new ones are laid out by the first pass that uses them). The
    // caller sees that the GPU uses none of the freed ones. Returns whether
    // anything was made or freed.
    bool update(const FramePlan& plan);
    bool changes(const FramePlan& plan) const;  // whether update(plan) would make or free any
    void release();

    const FramePlan& plan() const { return plan_; }
    size_t bytes() const;  // the device memory of every image
    const vk::Image& image(TargetRef target) const;
    const GBufferTargets& gbuffer() const { return gbuffer_; }
    const AoTargets& ao() const { return ao_; }

    // frame_barriers.cpp: what each image went through since its last barrier.
    // At a frame's start the targets it lays out afresh hold nothing worth keeping;
    // when the last frame has finished (`lastFinished`) nothing before needs a
    // barrier, else each image's first use waits for every command before.
    void beginFrame(bool lastFinished);
    // At a frame's start: the histories the plan writes flip, this frame's copy
    // becoming the last. A history whose images are made afresh starts at copy 0.
    void advanceHistories(const FramePlan& plan);
    // Records the layout transitions and barriers a pass using `uses` needs after
    // everything recorded before, in one vkCmdPipelineBarrier (none when nothing is needed).
    void recordBarriers(VkCommandBuffer cmd, const std::vector<TargetUse>& uses);
    VkImageLayout layout(TargetRef target) const;  // after what is recorded so far

private:
    struct ImageState {
        VkImageLayout layout = VK_IMAGE_LAYOUT_UNDEFINED;
        bool dropped = true;  // contents not needed: the next transition starts from UNDEFINED
        VkPipelineStageFlags writeStage = 0, readStages = 0, visibleTo = 0;  // the last write; reads since; where it is visible
        VkAccessFlags writeAccess = 0;
    };
    uint32_t index(TargetRef target) const {  // the copy's image
        const uint32_t current = current_[size_t(target.id)];
        return target.copy == Copy::Previous ? 1 - current : current;
    }
    vk::Image& slot(TargetId id, uint32_t index);
    ImageState& state(TargetId id, uint32_t index) { return states_[size_t(id)][index]; }
    ImageState& state(TargetRef target) { return state(target.id, index(target)); }

    vk::Context& ctx_;
    FramePlan plan_;
    std::array<std::array<ImageState, 2>, kTargetCount> states_{};
    std::array<uint32_t, kTargetCount> current_{};  // each history's image this frame writes
    GBufferTargets gbuffer_;
    AoTargets ao_;
    vk::Image color_, display_, normals_, shadow_, objectLight_, cacheLight_;
    std::array<vk::Image, 2> shadowHistory_, objectLightHistory_;
};

}  // namespace grotto
