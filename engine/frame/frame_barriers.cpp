// The barriers between passes, derived from what each declares it uses: an image
// gets one where its layout must change, where a write before is not yet visible
// to the stage that reads it, or where it is written after being read or written.
#include "engine/frame/frame_targets.h"

namespace grotto {
namespace {

struct Need {
    VkPipelineStageFlags stage;
    VkAccessFlags access;
    VkImageLayout layout;
    bool write;
};

Need need(Access access) {
    constexpr VkPipelineStageFlags compute = VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT;
    switch (access) {
    case Access::Read: return {compute, VK_ACCESS_SHADER_READ_BIT, VK_IMAGE_LAYOUT_GENERAL, false};
    case Access::Sampled: return {compute, VK_ACCESS_SHADER_READ_BIT, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL, false};
    case Access::Write: return {compute, VK_ACCESS_SHADER_WRITE_BIT, VK_IMAGE_LAYOUT_GENERAL, true};
    case Access::DepthAttachment:
        return {VK_PIPELINE_STAGE_EARLY_FRAGMENT_TESTS_BIT | VK_PIPELINE_STAGE_LATE_FRAGMENT_TESTS_BIT,
                VK_ACCESS_DEPTH_STENCIL_ATTACHMENT_READ_BIT | VK_ACCESS_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT,
                VK_IMAGE_LAYOUT_DEPTH_STENCIL_ATTACHMENT_OPTIMAL, true};
    case Access::ColorAttachment:
        return {VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT, VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT,
                VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL, true};
    }
    return {};
}

constexpr VkAccessFlags kWrites =
    VK_ACCESS_SHADER_WRITE_BIT | VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT | VK_ACCESS_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT;

}  // namespace

// A frame that starts once the last has finished needs no barrier against what
// came before. One that may start while the last still runs (frames in flight,
// after a memory barrier from every earlier command) orders its first use of each
// image after every earlier command, the game's reads included. The targets a
// frame lays out afresh drop their contents either way.
void FrameTargets::beginFrame(bool lastFinished) {
    for (const TargetRow& row : targetRows())
        for (uint32_t c = 0; c < row.copies; ++c) {
            ImageState& s = state(row.id, c);
            s.writeStage = 0;
            s.readStages = lastFinished ? 0 : VK_PIPELINE_STAGE_ALL_COMMANDS_BIT;
            s.writeAccess = 0;
            if (row.initial == VK_IMAGE_LAYOUT_UNDEFINED) s.dropped = true;
        }
}

void FrameTargets::recordBarriers(VkCommandBuffer cmd, const std::vector<TargetUse>& uses) {
    std::vector<VkImageMemoryBarrier> barriers;
    VkPipelineStageFlags src = 0, dst = 0;
    for (const TargetUse& use : uses) {
        ImageState& s = state(use.target);
        const Need n = need(use.access);
        const bool unseenWrite = s.writeStage != 0 && (s.visibleTo & n.stage) != n.stage;
        const bool hazard = n.write ? s.writeStage != 0 || s.readStages != 0 : unseenWrite;
        if (s.layout != n.layout || s.dropped || hazard) {
            const vk::Image& img = image(use.target);
            barriers.push_back({.sType = VK_STRUCTURE_TYPE_IMAGE_MEMORY_BARRIER,
                                .srcAccessMask = s.dropped ? 0 : s.writeAccess,
                                .dstAccessMask = n.access,
                                .oldLayout = s.dropped ? VK_IMAGE_LAYOUT_UNDEFINED : s.layout,
                                .newLayout = n.layout,
                                .srcQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED,
                                .dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED,
                                .image = img.image,
                                .subresourceRange = {img.aspect, 0, 1, 0, 1}});
            src |= s.writeStage | s.readStages;  // a dropped image's are those of a frame that may still run
            dst |= n.stage;
            s.layout = n.layout;
            s.dropped = false;
            s.visibleTo = n.write ? 0 : n.stage;
            s.readStages = 0;
        }
        if (n.write) {
            s.writeStage = n.stage;
            s.writeAccess = n.access & kWrites;
            s.readStages = 0;
            s.visibleTo = 0;
        } else {
            s.readStages |= n.stage;
        }
    }
    if (barriers.empty()) return;
    vkCmdPipelineBarrier(cmd, src ? src : VK_PIPELINE_STAGE_TOP_OF_PIPE_BIT, dst, 0, 0, nullptr, 0, nullptr,
                         uint32_t(barriers.size()), barriers.data());
}

VkImageLayout FrameTargets::layout(TargetRef target) const {
    return states_[size_t(target.id)][index(target)].layout;
}

}  // namespace grotto
