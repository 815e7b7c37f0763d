// The read-backs: a frame's images, and with AOVs what the frame computed on the
// way without storing, copied into host memory (frame_copy.h).
#include "engine/renderer.h"

#include "engine/vk/readback.h"

namespace grotto {

void Renderer::recordCopy(VkCommandBuffer cmd, FrameCopy& copy, const Camera& camera) {
    copy.begin({.width = width(), .height = height(), .half = targets_.ao().half,
                .scale = ao_.chain.fullResolution ? 1u : 2u, .ao = ao_.enabled, .chain = plan_.chain, .toneMap = toneMapCurve(lighting_.toneMap),
                .camera = camera, .poses = poses_, .albedo = scene_.albedo});
    auto copyPart = [&](FrameCopy::Part part, TargetRef target, uint32_t bytesPerPixel) {
        const vk::Image& from = image(target);
        const VkDeviceSize bytes = VkDeviceSize(from.extent.width) * from.extent.height * bytesPerPixel;
        vk::recordImageCopy(cmd, from, targets_.layout(target), bytesPerPixel, copy.reserve(part, bytes), 0);
    };
    copyPart(FrameCopy::Color, TargetId::Color, 16);
    if (copy.aovs() && plan_.faceCache) {
        // The cache's AO and sun at each pixel, as the composite read them.
        pass(cmd, FaceCacheAovPass::declare(), [&] {
            passes_.get<FaceCacheAovPass>().record(cmd, targets_.gbuffer(), slot().frame, *scene_.faceCache(),
                                      image(TargetId::AoFull), image(TargetId::Shadow), image(TargetId::ObjectLight),
                                      image(TargetId::CacheLight));
        });
        copyPart(FrameCopy::CacheLight, TargetId::CacheLight, 16);
    }
    if (copy.aovs()) {
        if (plan_.shadows) copyPart(FrameCopy::Shadow, TargetId::Shadow, 4);
        copyPart(FrameCopy::Depth, TargetId::Depth, 4);
        copyPart(FrameCopy::Surface, TargetId::Surface, 2);
        if (plan_.motion) copyPart(FrameCopy::Motion, TargetId::Motion, 16);
    }
    if (copy.aovs() && plan_.faceCache) copyPart(FrameCopy::AoFull, TargetId::AoFull, 4);
    if (copy.aovs() && plan_.chain) {
        // What the frame computed on the way without storing: the full-res AO (the
        // composite upsamples for itself) and, when the temporal pass blurs for
        // itself, the spatial AO. The same shaders on the same inputs give the same values.
        // VBAO's bent normals, where the frame did not find them: its estimator again
        // with them (the same kernel on the same inputs and noise).
        if (BentNormalsPass* bent = passes_.find<BentNormalsPass>()) {
            PassDecl untimed = bent->declare();
            untimed.timestamp = nullptr;  // not the frame's cost
            pass(cmd, untimed, [&] {
                bent->record(cmd, image(TargetId::Surface), targets_.ao(), slot().aoConstants,
                                  slot().traceConstants, scene_.occupancy(), &objectGrids_.buffer);
            });
        }
        const uint32_t passes = ao_.chain.denoisePasses;
        if (plan_.temporal && passes > 0)
            pass(cmd, DenoisePass::declare(passes - 1),
                 [&] { passes_.get<DenoisePass>().record(cmd, targets_.ao(), passes, passes - 1, slot().aoConstants); });
        pass(cmd, UpsamplePass::declare(aoOutput()), [&] {
            passes_.get<UpsamplePass>().record(cmd, image(TargetId::Depth), image(TargetId::Surface), image(aoOutput()),
                                  image(TargetId::AoFull), slot().aoConstants);
        });
        copyPart(FrameCopy::AoFull, TargetId::AoFull, 4);
        copyPart(FrameCopy::Raw, TargetId::AoRaw, 16);
        if (ao_.method == AoMethod::Vbao) copyPart(FrameCopy::BentNormal, TargetId::AoBentNormal, 8);
        copyPart(FrameCopy::Spatial, denoisedTarget(passes), 16);
        if (plan_.temporal) copyPart(FrameCopy::History, aoOutput(), 16);
    }
    vk::recordHostRead(cmd);
}

FrameImages Renderer::readback(const Camera& camera, bool aovs) {
    finishFrames();
    if (aovs) planAovs();
    FrameCopy copy(ctx_, aovs);
    ctx_.submitAndWait([&](VkCommandBuffer cmd) { recordCopy(cmd, copy, camera); });
    return copy.decode();
}

}  // namespace grotto
