// The whole frame on one screen (render): G-buffer (with occlusion culling, its
// Hi-Z and a mid-frame submit), sun shadows, then with AO the depth prefilter, the
// estimator, spatial denoise and temporal accumulation at AO resolution, then the
// composite (which upsamples the AO itself), the display image and the read-backs.
// Each pass declares what it reads and writes; the barriers follow from that.
#include "engine/renderer.h"

#include "grotto/error.h"
#include "engine/frame/object_frame.h"
#include "engine/frame/render_memory.h"
#include "engine/passes/trace_inputs.h"
#include "engine/vk/readback.h"
#include "voxel/settings_table.h"

#include <chrono>
#include <cmath>
#include <cstring>
#include <utility>

namespace grotto {

Renderer::Renderer(vk::Context& ctx, GpuScene& scene, const voxel::Lighting& lighting, const AoOptions& ao,
                   uint32_t width, uint32_t height, const SceneObjects* objects)
    : ctx_(ctx), scene_(scene), lighting_(lighting), ao_(ao), targets_(ctx), objects_(objects), timestamps_(ctx, 16) {
    if (objects_) poses_ = objects_->poses(0.0), objectScenes_ = objects_->list();
    try {
        validateAo(ao_, "AO settings");
        requireOccupancy(ao_);
        // Before any allocation can fail halfway.
        requireRenderFits(ctx, shapeFor(width, height, ao_, lighting_), "image size");
        frame_ = vk::createBuffer(ctx, sizeof(gpu::FrameUniforms), VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT, true);
        aoConstants_ = vk::createBuffer(ctx, sizeof(gpu::GtaoConstants), VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT, true);
        temporalConstants_ =
            vk::createBuffer(ctx, sizeof(gpu::TemporalConstants), VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT, true);
        traceConstants_ = vk::createBuffer(ctx, sizeof(gpu::TraceConstants), VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, true);
        // The objects' normal tables: the composite reads them whether or not there are objects.
        objectUniforms_ = vk::createBuffer(ctx, sizeof(gpu::ObjectUniforms), VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT, true);
        createPasses();
        targets_.update(shapeFor(width, height, ao_, lighting_));
        cmd_ = vk::allocateCommandBuffer(ctx);
        fence_ = vk::createFence(ctx);
    } catch (...) {  // e.g. a shader that fails to load: free what was made before it
        release();
        throw;
    }
}

void Renderer::createPasses() {
    vk::Context& ctx = ctx_;
    if (!gbufferPass_)
        gbufferPass_ = std::make_unique<GBufferPass>(
            ctx, motion() ? GBufferMode::Motion : objects_ ? GBufferMode::Objects : GBufferMode::World);
    if (!hizPass_) hizPass_ = std::make_unique<HizPass>(ctx);
    if (!compositePass_) compositePass_ = std::make_unique<CompositePass>(ctx, ao_.enabled, shadows());
    if (displayOn_ && !displayPass_) displayPass_ = std::make_unique<DisplayPass>(ctx);
    if (normalsOn_ && !normalsPass_) normalsPass_ = std::make_unique<NormalsPass>(ctx);
    if (shadows() && !shadowPass_) shadowPass_ = std::make_unique<ShadowPass>(ctx, softShadows());
    if (!ao_.enabled) return;
    if (!prefilterPass_) prefilterPass_ = std::make_unique<DepthPrefilterPass>(ctx);
    if (!estimatorPass_) estimatorPass_ = std::make_unique<EstimatorPass>(ctx, ao_);
    if (!denoisePass_) denoisePass_ = std::make_unique<DenoisePass>(ctx);
    if (!upsamplePass_) upsamplePass_ = std::make_unique<UpsamplePass>(ctx);
    if (temporal() && !temporalPass_)
        temporalPass_ = std::make_unique<TemporalPass>(ctx, ao_.chain.denoisePasses, objects_ != nullptr, motion());
}

FrameShape Renderer::shapeFor(uint32_t width, uint32_t height, const AoOptions& ao,
                             const voxel::Lighting& lighting) const {
    const bool shadows = lighting.sunShadows && scene_.occupancy;
    return {.width = width, .height = height, .ao = ao, .shadows = shadows,
            .softShadows = shadows && lighting.sunAngle > 0.0f, .movingObjects = objects_ && objects_->moving,
            .display = displayOn_, .normals = normalsOn_, .aoAov = aoAov_};
}

// Every frame waits for its fence before render() returns, so no GPU work of ours
// uses the targets here; histories in new images start afresh.
void Renderer::updateTargets(const FrameShape& shape) {
    if (!targets_.update(shape)) return;
    historyIndex_ = 0;
    shadowCamera_.reset();
}

void Renderer::setDisplayImage(bool on) { setGameImage(displayOn_, on, "display image"); }
void Renderer::setNormalsImage(bool on) { setGameImage(normalsOn_, on, "normals image"); }

void Renderer::setGameImage(bool& flag, bool on, const char* what) {
    if (on == flag) return;
    flag = on;
    if (on) {
        try {
            requireRenderFits(ctx_, wantedShape(), what);
        } catch (...) {
            flag = false;
            throw;
        }
        createPasses();
    } else {
        vkDeviceWaitIdle(ctx_.device);  // a game may still read it
        if (!displayOn_) displayPass_.reset();
        if (!normalsOn_) normalsPass_.reset();
    }
    targets_.update(wantedShape());
}

Renderer::~Renderer() { release(); }

void Renderer::release() {
    vkDeviceWaitIdle(ctx_.device);
    vkDestroyFence(ctx_.device, fence_, nullptr);
    vkFreeCommandBuffers(ctx_.device, ctx_.commandPool, 1, &cmd_);
    gbufferPass_.reset();
    prefilterPass_.reset();
    estimatorPass_.reset();
    denoisePass_.reset();
    temporalPass_.reset();
    upsamplePass_.reset();
    compositePass_.reset();
    displayPass_.reset();
    normalsPass_.reset();
    shadowPass_.reset();
    targets_.release();
    vk::destroy(ctx_, objectUniforms_);
    vk::destroy(ctx_, frame_);
    vk::destroy(ctx_, aoConstants_);
    vk::destroy(ctx_, temporalConstants_);
    vk::destroy(ctx_, traceConstants_);
}

void Renderer::resize(uint32_t width, uint32_t height) {
    const FrameShape shape = shapeFor(width, height, ao_, lighting_);
    requireRenderFits(ctx_, shape, "image size");
    updateTargets(shape);
    resetHistory();
}

void Renderer::setLighting(const voxel::Lighting& lighting) {
    const bool hadShadows = shadows(), wasSoft = softShadows();
    const voxel::Lighting old = std::exchange(lighting_, lighting);
    if (hadShadows == shadows() && wasSoft == softShadows()) {  // uniforms only
        if (old.sunDirection != lighting_.sunDirection || old.sunAngle != lighting_.sunAngle) shadowCamera_.reset();
        return;
    }
    try {  // a soft sun's history may not fit
        requireRenderFits(ctx_, wantedShape(), "lighting");
    } catch (...) {
        lighting_ = old;
        throw;
    }
    compositePass_.reset();
    shadowPass_.reset();
    createPasses();
    updateTargets(wantedShape());
    resetHistory();
}

void Renderer::requireOccupancy(const AoOptions& ao) const {
    if (ao.enabled && tracesVoxels(ao.method) && !scene_.occupancy)
        throw Error("AO settings", std::string("--ao ") + aoMethodName(ao.method) + " traces the world's voxels",
                    "upload the scene from its world (uploadScene(ctx, world)), not from a mesh alone");
}

void Renderer::setAo(const AoOptions& ao) {
    validateAo(ao, "AO settings");
    requireOccupancy(ao);
    const FrameShape shape = shapeFor(width(), height(), ao, lighting_);
    requireRenderFits(ctx_, shape, "AO settings");
    const AoOptions old = std::exchange(ao_, ao);
    const bool wasTemporal = old.enabled && old.chain.temporalHistory > 0;
    // What each pass and target is made from (its shader's specialisation, its size).
    const bool chain = old.enabled != ao_.enabled;
    const bool estimator = old.method != ao_.method || old.estimator.ssaoSamples != ao_.estimator.ssaoSamples ||
                           differIn(old, ao_, voxel::kEstimatorPipeline);  // its loop shape: the settings table's column
    const bool denoise = old.chain.denoisePasses != ao_.chain.denoisePasses;
    if (chain) compositePass_.reset();
    if (chain || estimator) estimatorPass_.reset();
    if (chain || denoise || wasTemporal != temporal()) temporalPass_.reset();
    // Moving objects get motion vectors only with the temporal pass: its G-buffer pass and target follow it.
    const bool motionChanged = objects_ && objects_->moving && wasTemporal != temporal();
    if (motionChanged) gbufferPass_.reset();
    if (!ao_.enabled) {
        prefilterPass_.reset();
        denoisePass_.reset();
        upsamplePass_.reset();
    }
    createPasses();
    updateTargets(shape);
    resetHistory();
}

TargetRef Renderer::aoOutput() const {
    if (!ao_.enabled) return TargetId::AoRaw;  // the 1x1 placeholder the composite binds
    return temporal() ? TargetRef{TargetId::AoHistory, historyIndex_} : denoisedTarget(ao_.chain.denoisePasses);
}

void Renderer::pass(VkCommandBuffer cmd, const PassDecl& decl, const std::function<void()>& record) {
    targets_.recordBarriers(cmd, decl.uses);
    if (decl.timestamp) timestamps_.begin(cmd, decl.timestamp);
    record();
    if (decl.timestamp) timestamps_.end(cmd);
}

// The frame, top to bottom; each pass's barriers follow from what it declares.
FrameStats Renderer::render(const Camera& camera, uint32_t frameIndex, FrameCopy* copy) {
    const auto start = std::chrono::steady_clock::now();
    writeConstants(camera, frameIndex);
    VkCommandBuffer cmd = beginCommands();
    timestamps_.reset(cmd);
    targets_.beginFrame();
    scene_.recordUploads(cmd);  // edits since the last frame, with their barrier to vertex input
    FrameStats stats = recordGBuffer(cmd, camera);
    if (shadows()) {
        const uint32_t history = shadowHistoryIndex_;
        if (softShadows()) shadowHistoryIndex_ = 1 - shadowHistoryIndex_;  // reads the last, writes the other
        pass(cmd, shadowPass_->declare(history), [&] {
            shadowPass_->record(cmd, targets_.gbuffer(), objectUniforms_, image(TargetId::Shadow), traceConstants_,
                                *scene_.occupancy, &image({TargetId::ShadowHistory, history}),
                                &image({TargetId::ShadowHistory, shadowHistoryIndex_}));
        });
    }
    if (ao_.enabled) recordAo(cmd);
    pass(cmd, CompositePass::declare(aoOutput()), [&] {
        compositePass_->record(cmd, targets_.gbuffer(), image(aoOutput()), image(TargetId::Color), frame_,
                               scene_.palette, aoConstants_, objectUniforms_, image(TargetId::Shadow));
    });
    if (displayOn_)
        pass(cmd, DisplayPass::declare(), [&] {
            displayPass_->record(cmd, image(TargetId::Color), image(TargetId::Display), toneMapCurve(lighting_.toneMap));
        });
    if (normalsOn_)
        pass(cmd, NormalsPass::declare(), [&] {
            normalsPass_->record(cmd, targets_.gbuffer().surface, objectUniforms_, image(TargetId::Normals));
        });
    if (copy) recordCopy(cmd, *copy, camera);
    submitAndWait(cmd);
    stats.wallMs = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    stats.passMs = timestamps_.read();
    lastCamera_ = camera;
    lastPoses_ = poses_;
    return stats;
}

// First what was visible last frame; with occlusion culling, then the rest that its
// depth does not hide (chunk_culling.h). Between the two the CPU decides, so the
// frame is submitted in two parts. The objects are drawn last.
FrameStats Renderer::recordGBuffer(VkCommandBuffer cmd, const Camera& camera) {
    const GBufferObjects drawObjects{objectScenes_, poses_, lastCamera_ ? lastPoses_ : poses_,
                                     lastCamera_ ? &*lastCamera_ : &camera};
    const GBufferObjects* drawn = objects_ ? &drawObjects : nullptr;
    const PassDecl gbuffer = gbufferPass_->declare();
    FrameStats stats;
    targets_.recordBarriers(cmd, gbuffer.uses);
    timestamps_.begin(cmd, gbuffer.timestamp);
    const std::vector<QuadDraw>& early = culling_.begin(scene_, camera, cullingOptions_);
    stats.quadsDrawn = gbufferPass_->record(cmd, targets_.gbuffer(), scene_, frame_, camera, early, true, drawn,
                                            !cullingOptions_.occlusion);
    if (cullingOptions_.occlusion) {
        pass(cmd, HizPass::declare(), [&] { hizPass_->record(cmd, image(TargetId::Depth)); });
        submitAndWait(cmd);
        const std::vector<QuadDraw>& late = culling_.late(hizPass_->tiles());
        beginCommands();
        targets_.recordBarriers(cmd, gbuffer.uses);
        stats.quadsDrawn += gbufferPass_->record(cmd, targets_.gbuffer(), scene_, frame_, camera, late, false, drawn);
    }
    stats.culling = culling_.stats();
    timestamps_.end(cmd);
    return stats;
}

void Renderer::recordAo(VkCommandBuffer cmd) {
    const AoTargets& ao = targets_.ao();
    pass(cmd, DepthPrefilterPass::declare(),
         [&] { prefilterPass_->record(cmd, image(TargetId::Depth), ao, aoConstants_); });
    pass(cmd, estimatorPass_->declare(), [&] {
        estimatorPass_->record(cmd, image(TargetId::Surface), ao, aoConstants_, traceConstants_, scene_.occupancy.get());
    });
    // With the temporal pass, the final blur is part of it.
    const uint32_t passes = ao_.chain.denoisePasses, blurs = temporal() && passes > 0 ? passes - 1 : passes;
    timestamps_.begin(cmd, DenoisePass::kTimestamp);
    for (uint32_t i = 0; i < blurs; ++i)
        pass(cmd, DenoisePass::declare(i), [&] { denoisePass_->record(cmd, ao, passes, i, aoConstants_); });
    timestamps_.end(cmd);
    if (!temporal()) return;
    // Reads the last output, writes the other image, which becomes the last.
    const uint32_t previous = historyIndex_;
    historyIndex_ = 1 - historyIndex_;
    pass(cmd, temporalPass_->declare(previous, motion()), [&] {
        temporalPass_->record(cmd, ao, image({TargetId::AoHistory, previous}), image({TargetId::AoHistory, historyIndex_}),
                              aoConstants_,
                              temporalConstants_, &objectUniforms_, &image(motion() ? TargetId::Motion : TargetId::Depth));
    });
}

void Renderer::writeConstants(const Camera& camera, uint32_t frameIndex) {
    const gpu::FrameUniforms uniforms = frameUniforms(camera, lighting_, ao_);
    std::memcpy(frame_.mapped(), &uniforms, sizeof uniforms);
    if (ao_.enabled) {
        const uint32_t scale = ao_.chain.fullResolution ? 1 : 2;
        gpu::GtaoConstants constants = gtaoConstants(camera, gpuSettings(ao_), frameIndex, scale);
        if (objects_) normalTable(constants.viewNormals, glm::transpose(camera.basis), poses_);
        std::memcpy(aoConstants_.mapped(), &constants, sizeof constants);
        if (temporal()) {
            // A frame index that does not follow the last (wrapping) starts a new
            // sequence. A zoom or new clip planes need no reset: the history is
            // reprojected through the previous projection and holds linear depth.
            if (frameIndex != previousFrame_ + 1u) previousCamera_.reset();
            gpu::TemporalConstants t = temporalConstants(camera, previousCamera_ ? &*previousCamera_ : nullptr);
            invalidated_.write(camera.position, aoReach(ao_), t);
            std::memcpy(temporalConstants_.mapped(), &t, sizeof t);
            previousCamera_ = camera;
            previousFrame_ = frameIndex;
        }
    }
    writeTraceConstants(camera, frameIndex);  // before the edits are cleared: they restart a soft sun's history
    invalidated_.clear();  // edits before this frame; later ones go to the next
    // The frame before (for motion and the temporal plane test); this one's own where there was none.
    if (objects_) {
        const gpu::ObjectUniforms o =
            objectUniforms(poses_, lastCamera_ ? *lastCamera_ : camera, lastCamera_ ? lastPoses_ : poses_);
        std::memcpy(objectUniforms_.mapped(), &o, sizeof o);
    }
}

VkCommandBuffer Renderer::beginCommands() {
    VK_CHECK(vkResetCommandBuffer(cmd_, 0));
    const VkCommandBufferBeginInfo bi{.sType = VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO,
                                      .flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT};
    VK_CHECK(vkBeginCommandBuffer(cmd_, &bi));
    return cmd_;
}

void Renderer::submitAndWait(VkCommandBuffer cmd) {
    VK_CHECK(vkEndCommandBuffer(cmd));
    VkSubmitInfo si{.sType = VK_STRUCTURE_TYPE_SUBMIT_INFO, .commandBufferCount = 1, .pCommandBuffers = &cmd};
    VK_CHECK(vkResetFences(ctx_.device, 1, &fence_));
    VK_CHECK(vkQueueSubmit(ctx_.queue, 1, &si, fence_));
    VK_CHECK(vkWaitForFences(ctx_.device, 1, &fence_, VK_TRUE, UINT64_MAX));
}

void Renderer::writeTraceConstants(const Camera& camera, uint32_t frameIndex) {
    if (!scene_.occupancy) return;
    const double radius = ao_.enabled ? ao_.estimator.radius : 1.0;
    gpu::TraceConstants t = traceConstants(camera, *scene_.occupancy, scene_.voxelSize, scene_.worldOrigin,
                                           lighting_.sunDirection, ao_.estimator.rays, radius);
    t.sunCosRadius = float(std::cos(glm::radians(0.5 * double(lighting_.sunAngle))));
    t.frameIndex = frameIndex;
    if (softShadows()) {
        // As the AO's history: consecutive frames only. An edit anywhere may move a
        // shadow anywhere along the sun's rays, so it restarts the whole history.
        if (frameIndex != shadowFrame_ + 1u || !invalidated_.boxes().empty()) shadowCamera_.reset();
        const gpu::TemporalConstants r = temporalConstants(camera, shadowCamera_ ? &*shadowCamera_ : nullptr);
        t.currentToPrevious = r.currentToPrevious;
        t.previousNdcToViewMul_Add = r.previousNdcToViewMul_Add;
        t.shadowHistory = temporal() ? ao_.chain.temporalHistory : kDefaultTemporalHistory;
        t.shadowReset = (r.reset != 0u ? 1u : 0u) | (objects_ && objects_->moving ? 2u : 0u);
        shadowCamera_ = camera;
        shadowFrame_ = frameIndex;
    }
    std::memcpy(traceConstants_.mapped(), &t, sizeof t);
}

void Renderer::setObjectPoses(std::span<const voxel::ObjectPose> poses) {
    if (!objects_ || poses.size() != objects_->scenes.size())
        throw Error::internal("Renderer::setObjectPoses", std::to_string(poses.size()) + " poses for " +
                                                              std::to_string(objects_ ? objects_->scenes.size() : 0) +
                                                              " objects");
    poses_.assign(poses.begin(), poses.end());
}

void Renderer::objectAdded(const voxel::ObjectPose& pose) {
    objectScenes_ = objects_->list();
    poses_.push_back(pose);
    if (lastCamera_) lastPoses_.push_back(pose);
}

void Renderer::objectRemoved(size_t index) {
    // render() has waited for its frame: no frame in flight draws the scene the caller frees next.
    objectScenes_.erase(objectScenes_.begin() + ptrdiff_t(index));
    poses_.erase(poses_.begin() + ptrdiff_t(index));
    if (index < lastPoses_.size()) lastPoses_.erase(lastPoses_.begin() + ptrdiff_t(index));
}

void Renderer::recordCopy(VkCommandBuffer cmd, FrameCopy& copy, const Camera& camera) {
    copy.begin({.width = width(), .height = height(), .half = targets_.ao().half,
                .scale = ao_.chain.fullResolution ? 1u : 2u, .ao = ao_.enabled, .toneMap = toneMapCurve(lighting_.toneMap),
                .camera = camera, .poses = poses_, .albedo = scene_.albedo});
    auto copyPart = [&](FrameCopy::Part part, TargetRef target, uint32_t bytesPerPixel) {
        const vk::Image& from = image(target);
        const VkDeviceSize bytes = VkDeviceSize(from.extent.width) * from.extent.height * bytesPerPixel;
        vk::recordImageCopy(cmd, from, targets_.layout(target), bytesPerPixel, copy.reserve(part, bytes), 0);
    };
    copyPart(FrameCopy::Color, TargetId::Color, 16);
    if (copy.aovs()) {
        if (shadows()) copyPart(FrameCopy::Shadow, TargetId::Shadow, 4);
        copyPart(FrameCopy::Depth, TargetId::Depth, 4);
        copyPart(FrameCopy::Surface, TargetId::Surface, 2);
        if (motion()) copyPart(FrameCopy::Motion, TargetId::Motion, 16);
    }
    if (copy.aovs() && ao_.enabled) {
        // What the frame computed on the way without storing: the full-res AO (the
        // composite upsamples for itself) and, when the temporal pass blurs for
        // itself, the spatial AO. The same shaders on the same inputs give the same values.
        if (!aoAov_) {  // its target is made on first use: frames do not store it
            aoAov_ = true;
            targets_.update(wantedShape());
        }
        const uint32_t passes = ao_.chain.denoisePasses;
        if (temporal() && passes > 0)
            pass(cmd, DenoisePass::declare(passes - 1),
                 [&] { denoisePass_->record(cmd, targets_.ao(), passes, passes - 1, aoConstants_); });
        pass(cmd, UpsamplePass::declare(aoOutput()), [&] {
            upsamplePass_->record(cmd, image(TargetId::Depth), image(TargetId::Surface), image(aoOutput()),
                                  image(TargetId::AoFull), aoConstants_);
        });
        copyPart(FrameCopy::AoFull, TargetId::AoFull, 4);
        copyPart(FrameCopy::Raw, TargetId::AoRaw, 16);
        copyPart(FrameCopy::Spatial, denoisedTarget(passes), 16);
        if (temporal()) copyPart(FrameCopy::History, aoOutput(), 16);
    }
    vk::recordHostRead(cmd);
}

FrameImages Renderer::readback(const Camera& camera, bool aovs) {
    FrameCopy copy(ctx_, aovs);
    ctx_.submitAndWait([&](VkCommandBuffer cmd) { recordCopy(cmd, copy, camera); });
    return copy.decode();
}

}  // namespace grotto
