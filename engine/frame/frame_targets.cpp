#include "engine/frame/frame_targets.h"

#include "grotto/error.h"


namespace grotto {
namespace {

constexpr VkImageUsageFlags kRead = VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT;
constexpr VkImageUsageFlags kStorage = VK_IMAGE_USAGE_STORAGE_BIT;
constexpr VkImageLayout kGeneral = VK_IMAGE_LAYOUT_GENERAL, kEachFrame = VK_IMAGE_LAYOUT_UNDEFINED;
constexpr VkFormat kRgba32f = VK_FORMAT_R32G32B32A32_SFLOAT, kR32f = VK_FORMAT_R32_SFLOAT;

bool always(const FramePlan&) { return true; }
bool chainOn(const FramePlan& s) { return s.chain; }
bool surfaceHistory(const FramePlan& s) { return s.surfaceHistory; }  // a soft sun's and objects' light advance together

// Colour, display and the G-buffer are read by a game too (include/grotto/grotto.h):
// sampled, and transfer sources for a window's blit and the read-backs. The AO
// chain's images live in GENERAL: written as storage, read as sampled images.
constexpr TargetRow kRows[] = {
    {TargetId::Depth, VK_FORMAT_D32_SFLOAT, TargetSize::Frame, VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT | kRead,
     always, false, 1, kEachFrame},
    {TargetId::Surface, kSurfaceFormat, TargetSize::Frame, VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | kRead, always, false, 1,
     kEachFrame},
    {TargetId::Motion, kMotionFormat, TargetSize::Frame, VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | kRead,
     [](const FramePlan& s) { return s.motion; }, false, 1, kEachFrame},
    {TargetId::Color, kRgba32f, TargetSize::Frame, kStorage | kRead, always, false, 1, kEachFrame},
    {TargetId::Display, VK_FORMAT_R16G16B16A16_SFLOAT, TargetSize::Frame, kStorage | kRead,
     [](const FramePlan& s) { return s.display; }, false, 1, kGeneral},
    {TargetId::Normals, VK_FORMAT_R16G16B16A16_SFLOAT, TargetSize::Frame, kStorage | kRead,
     [](const FramePlan& s) { return s.normals; }, false, 1, kGeneral},
    {TargetId::Shadow, kR32f, TargetSize::Frame, kStorage | VK_IMAGE_USAGE_TRANSFER_SRC_BIT,
     [](const FramePlan& s) { return s.shadows; }, true, 1, kGeneral},
    {TargetId::ShadowHistory, kRgba32f, TargetSize::Frame, kStorage,
     [](const FramePlan& s) { return s.shadowHistory; }, false, 2, kGeneral, surfaceHistory},
    // The composite with the face cache binds it (a placeholder) with or without objects.
    {TargetId::ObjectLight, VK_FORMAT_R16G16B16A16_SFLOAT, TargetSize::Frame, kStorage,
     [](const FramePlan& s) { return s.objectLight; }, true, 1, kGeneral},
    {TargetId::ObjectLightHistory, VK_FORMAT_R32G32B32A32_UINT, TargetSize::Frame, kStorage,
     [](const FramePlan& s) { return s.objectLight; }, false, 2, kGeneral, surfaceHistory},
    {TargetId::AoDepthAtlas, kR32f, TargetSize::DepthAtlas, kStorage | kRead, chainOn, false, 1, kGeneral},
    // VBAO binds it whatever its thickness mode; only the voxels mode fills it.
    {TargetId::AoThickness, kR32f, TargetSize::DepthAtlas, kStorage,
     [](const FramePlan& s) { return voxelThickness(s.ao); }, true, 1, kGeneral},
    // VBAO's bent normals, when the sky's ambient or a read-back wants them; the
    // composite binds it (a placeholder) with every method.
    {TargetId::AoBentNormal, VK_FORMAT_R16G16B16A16_SFLOAT, TargetSize::Ao, kStorage | VK_IMAGE_USAGE_TRANSFER_SRC_BIT,
     [](const FramePlan& s) { return s.ao.enabled && s.ao.method == AoMethod::Vbao; }, true, 1, kGeneral},
    {TargetId::AoRaw, kRgba32f, TargetSize::Ao, kStorage | kRead, chainOn, true, 1, kGeneral},
    // One denoise pass needs one target (with the temporal pass, only for the
    // AO_spatial AOV), more ping-pong between two.
    {TargetId::AoSpatial0, kRgba32f, TargetSize::Ao, kStorage | kRead,
     [](const FramePlan& s) { return s.chain && s.ao.chain.denoisePasses >= 1; }, false, 1, kGeneral},
    {TargetId::AoSpatial1, kRgba32f, TargetSize::Ao, kStorage | kRead,
     [](const FramePlan& s) { return s.chain && s.ao.chain.denoisePasses >= 2; }, false, 1, kGeneral},
    {TargetId::AoHistory, kRgba32f, TargetSize::Ao, kStorage | kRead, [](const FramePlan& s) { return s.temporal; },
     false, 2, kGeneral, [](const FramePlan& s) { return s.temporal; }},
    // Frames do not store the upsampled AO (the composite upsamples for itself) or
    // the face cache's AO: only a read-back with AOVs makes it.
    {TargetId::AoFull, kR32f, TargetSize::Frame, kStorage | VK_IMAGE_USAGE_TRANSFER_SRC_BIT,
     [](const FramePlan& s) { return s.ao.enabled && s.aoAov; }, false, 1, kGeneral},
    // The light the face cache gave each pixel: only a read-back with AOVs makes it.
    {TargetId::CacheLight, kRgba32f, TargetSize::Frame, kStorage | VK_IMAGE_USAGE_TRANSFER_SRC_BIT,
     [](const FramePlan& s) { return s.faceCache && s.aoAov; }, false, 1, kGeneral},
    // Each pixel's quad record in the face cache's atlas (engine/scene/face_atlas.h),
    // which the G-buffer writes when the composite reads the atlas; the composite
    // binds it (a placeholder) with the cache whether or not.
    {TargetId::AtlasRecord, kAtlasRecordFormat, TargetSize::Frame, VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | kRead,
     [](const FramePlan& s) { return s.faceCache; }, true, 1, kEachFrame},
};

}  // namespace

std::span<const TargetRow> targetRows() { return kRows; }

VkExtent2D targetExtent(const TargetRow& row, const FramePlan& plan) {
    if (!row.exists(plan)) return row.placeholder ? VkExtent2D{1, 1} : VkExtent2D{0, 0};
    switch (row.size) {
    case TargetSize::Frame: return plan.frame();
    case TargetSize::Ao: return plan.aoExtent();
    case TargetSize::DepthAtlas: return depthMipLayout(plan.aoExtent()).atlas;
    }
    return {0, 0};
}

vk::Image& FrameTargets::slot(TargetId id, uint32_t copy) {
    switch (id) {
    case TargetId::Depth: return gbuffer_.depth;
    case TargetId::Surface: return gbuffer_.surface;
    case TargetId::Motion: return gbuffer_.motion;
    case TargetId::Color: return color_;
    case TargetId::Display: return display_;
    case TargetId::Normals: return normals_;
    case TargetId::Shadow: return shadow_;
    case TargetId::ShadowHistory: return shadowHistory_[copy];
    case TargetId::ObjectLight: return objectLight_;
    case TargetId::ObjectLightHistory: return objectLightHistory_[copy];
    case TargetId::AoDepthAtlas: return ao_.depthAtlas;
    case TargetId::AoThickness: return ao_.thickness;
    case TargetId::AoBentNormal: return ao_.bentNormal;
    case TargetId::AoRaw: return ao_.raw;
    case TargetId::AoSpatial0: return ao_.spatial[0];
    case TargetId::AoSpatial1: return ao_.spatial[1];
    case TargetId::AoHistory: return ao_.history[copy];
    case TargetId::AoFull: return ao_.full;
    case TargetId::CacheLight: return cacheLight_;
    case TargetId::AtlasRecord: return gbuffer_.atlasRecord;
    }
    throw Error::internal("FrameTargets", "no such target");
}

const vk::Image& FrameTargets::image(TargetRef target) const {
    return const_cast<FrameTargets*>(this)->slot(target.id, index(target));
}

void FrameTargets::advanceHistories(const FramePlan& plan) {
    for (const TargetRow& row : kRows)
        if (row.advances && row.advances(plan)) current_[size_t(row.id)] ^= 1u;
}

bool FrameTargets::update(const FramePlan& plan) {
    bool changed = false;
    for (const TargetRow& row : kRows) {
        const VkExtent2D extent = targetExtent(row, plan);
        for (uint32_t c = 0; c < row.copies; ++c) {
            vk::Image& image = slot(row.id, c);
            if (image.extent.width == extent.width && image.extent.height == extent.height) continue;
            changed = true;
            current_[size_t(row.id)] = 0;
            vk::destroy(ctx_, image);
            state(row.id, c) = {};
            if (extent.width != 0) image = vk::createImage(ctx_, extent, row.format, row.usage);
        }
    }
    ao_.half = plan.chain ? plan.aoExtent() : VkExtent2D{};
    plan_ = plan;
    return changed;
}

bool FrameTargets::changes(const FramePlan& plan) const {
    for (const TargetRow& row : kRows) {
        const VkExtent2D extent = targetExtent(row, plan);
        for (uint32_t c = 0; c < row.copies; ++c) {
            const VkExtent2D now = const_cast<FrameTargets*>(this)->slot(row.id, c).extent;
            if (now.width != extent.width || now.height != extent.height) return true;
        }
    }
    return false;
}

void FrameTargets::release() {
    for (const TargetRow& row : kRows)
        for (uint32_t c = 0; c < row.copies; ++c) {
            vk::destroy(ctx_, slot(row.id, c));
            state(row.id, c) = {};
        }
    current_ = {};
    ao_.half = {};
    plan_ = {};
}

size_t FrameTargets::bytes() const {
    size_t n = 0;
    for (const TargetRow& row : kRows)
        for (uint32_t c = 0; c < row.copies; ++c) n += const_cast<FrameTargets*>(this)->slot(row.id, c).memory.size;
    return n;
}

}  // namespace grotto
