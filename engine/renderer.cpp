// The whole frame on one screen: G-buffer, then (with AO) depth prefilter, GTAO,
// spatial denoise and temporal accumulation at half resolution, then the composite
// (which upsamples the AO itself), with the barriers between them.
#include "engine/renderer.h"

#include "common/error.h"
#include "engine/frame/object_frame.h"
#include "engine/passes/trace_inputs.h"
#include "engine/frame/render_memory.h"
#include "engine/vk/readback.h"
#include "shaders/shared/frame.h"
#include "shaders/shared/quad.h"
#include "shaders/shared/tone_map.h"
#include "voxel/settings_table.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstring>
#include <limits>
#include <utility>

namespace grotto {
namespace {

constexpr VkFormat kColorFormat = VK_FORMAT_R32G32B32A32_SFLOAT;

gpu::FrameUniforms frameUniforms(const Camera& camera, const voxel::Lighting& l, const AoOptions& ao) {
    gpu::FrameUniforms u{};
    u.viewProj = camera.viewProjRelative();
    u.sunDirection = glm::vec4(l.sunDirection, 0.0f);
    u.sunRadiance = glm::vec4(l.sunColor * l.sunIntensity, 0.0f);
    u.ambient = glm::vec4(l.ambientColor * l.ambientIntensity, 0.0f);
    u.skyZenith = glm::vec4(l.skyZenith, 0.0f);
    u.skyHorizon = glm::vec4(l.skyHorizon, 0.0f);
    // rayDirection() is linear in the pixel position before normalising.
    const double t = std::tan(camera.fovY * 0.5);
    const glm::dvec3 right = camera.basis[0] * (2.0 * t * camera.aspect() / camera.width);
    const glm::dvec3 down = -camera.basis[1] * (2.0 * t / camera.height);
    const glm::dvec3 corner = -camera.basis[2] - camera.basis[0] * (t * camera.aspect()) + camera.basis[1] * t;
    u.rayOrigin = glm::vec4(glm::vec3(corner), 0.0f);
    u.rayStepX = glm::vec4(glm::vec3(right), 0.0f);
    u.rayStepY = glm::vec4(glm::vec3(down), 0.0f);
    u.aoStrength = glm::vec4(ao.enabled ? ao.chain.strength : 0.0f, 0.0f, 0.0f, 0.0f);
    u.exposure = glm::vec4(l.exposure, 0.0f, 0.0f, 0.0f);
    u.size = {camera.width, camera.height};
    return u;
}

VkExtent2D halfOf(VkExtent2D e) { return {(e.width + 1) / 2, (e.height + 1) / 2}; }

// The world's tone map setting as the shared curve (shaders/shared/tone_map.h).
uint32_t toneMapCurve(voxel::ToneMap t) { return t == voxel::ToneMap::Filmic ? GROTTO_TONE_MAP_FILMIC : GROTTO_TONE_MAP_CLAMP; }

}  // namespace

gpu::GtaoConstants gtaoConstants(const Camera& camera, const gpu::GtaoSettings& settings, uint32_t frameIndex,
                                 uint32_t scale) {
    gpu::GtaoConstants c{};
    c.settings = settings;
    const double tanY = std::tan(camera.fovY * 0.5), tanX = tanY * camera.aspect();
    c.ndcToViewMul_Add = glm::vec4(float(2.0 * tanX / camera.width), float(-2.0 * tanY / camera.height),
                                   float(-tanX), float(tanY));
    for (int f = 0; f < 6; ++f) {
        glm::dvec3 n(0.0);
        n[f / 2] = f % 2 == 0 ? 1.0 : -1.0;
        // World to view is the transpose of the camera basis.
        c.viewNormals[f] = glm::vec4(glm::vec3(glm::transpose(camera.basis) * n), 0.0f);
    }
    c.fullSize = {camera.width, camera.height};
    c.scale = scale;
    c.halfSize = {(camera.width + scale - 1) / scale, (camera.height + scale - 1) / scale};
    c.frameIndex = frameIndex;
    c.pixelViewSize = float(scale * 2.0 * tanX / camera.width);  // an AO pixel spans `scale`
    const glm::dmat4 p = camera.projection();
    c.depthA = float(p[2][2]);
    c.depthB = float(p[3][2]);
    return c;
}

gpu::TemporalConstants temporalConstants(const Camera& current, const Camera* previous) {
    gpu::TemporalConstants t{};
    t.reset = previous ? 0u : 1u;
    const Camera& prev = previous ? *previous : current;
    // Rotation and the camera's step, never an absolute position: exact far from the origin.
    const glm::dmat3 rotation = glm::transpose(prev.basis) * current.basis;
    glm::dmat4 m(rotation);
    m[3] = glm::dvec4(glm::transpose(prev.basis) * (current.position - prev.position), 1.0);
    t.currentToPrevious = glm::mat4(m);
    const gpu::GtaoConstants g = gtaoConstants(prev, {}, 0);
    t.previousNdcToViewMul_Add = g.ndcToViewMul_Add;
    for (int f = 0; f < 6; ++f) t.previousViewNormals[f] = g.viewNormals[f];
    for (int k = 0; k < 3; ++k) t.viewToWorld[k] = glm::vec4(glm::vec3(current.basis[k]), 0.0f);
    return t;
}

Renderer::Renderer(vk::Context& ctx, GpuScene& scene, const voxel::Lighting& lighting, const AoOptions& ao,
                   uint32_t width, uint32_t height, const SceneObjects* objects)
    : ctx_(ctx), scene_(scene), lighting_(lighting), ao_(ao), targets_(ctx), objects_(objects), timestamps_(ctx, 16) {
    if (objects_) poses_ = objects_->poses(0.0), objectScenes_ = objects_->list();
    try {
        validateAo(ao_, "AO settings");
        requireOccupancy(ao_);
        requireRenderFits(ctx, shapeFor(width, height, ao_, lighting_), "image size");  // before any allocation can fail halfway
        frame_ = vk::createBuffer(ctx, sizeof(gpu::FrameUniforms), VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT, true);
        gtaoConstants_ = vk::createBuffer(ctx, sizeof(gpu::GtaoConstants), VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT, true);
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
    if (shadows() && !shadowPass_) shadowPass_ = std::make_unique<ShadowPass>(ctx, softShadows());
    if (!ao_.enabled) return;
    if (!prefilterPass_) prefilterPass_ = std::make_unique<DepthPrefilterPass>(ctx);
    if (!gtaoPass_) gtaoPass_ = std::make_unique<GtaoPass>(ctx, ao_);
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
            .display = displayOn_, .aoAov = aoAov_};
}

// Every frame waits for its fence before render() returns, so no GPU work of ours
// uses the targets here; histories in new images start afresh.
void Renderer::updateTargets(const FrameShape& shape) {
    if (!targets_.update(shape)) return;
    historyIndex_ = 0;
    shadowCamera_.reset();
}

void Renderer::setDisplayImage(bool on) {
    if (on == displayOn_) return;
    displayOn_ = on;
    if (on) {
        try {
            requireRenderFits(ctx_, wantedShape(), "display image");
        } catch (...) {
            displayOn_ = false;
            throw;
        }
        createPasses();
    } else {
        vkDeviceWaitIdle(ctx_.device);  // a game may still read it
        displayPass_.reset();
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
    gtaoPass_.reset();
    denoisePass_.reset();
    temporalPass_.reset();
    upsamplePass_.reset();
    compositePass_.reset();
    displayPass_.reset();
    shadowPass_.reset();
    targets_.release();
    vk::destroy(ctx_, objectUniforms_);
    vk::destroy(ctx_, frame_);
    vk::destroy(ctx_, gtaoConstants_);
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
    if (chain || estimator) gtaoPass_.reset();
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

const vk::Image& Renderer::aoHalfOutput() const {
    return temporal() ? targets_.image(TargetId::AoHistory, historyIndex_) : targets_.ao().denoised(ao_.chain.denoisePasses);
}

void Renderer::recordAo(VkCommandBuffer cmd) {
    timestamps_.begin(cmd, "prefilter");
    prefilterPass_->record(cmd, targets_.image(TargetId::Depth), targets_.ao(), gtaoConstants_);
    timestamps_.end(cmd);
    timestamps_.begin(cmd, aoMethodName(ao_.method));  // the estimator: gtao, or a baseline
    gtaoPass_->record(cmd, targets_.image(TargetId::Surface), targets_.ao(), gtaoConstants_, traceConstants_, scene_.occupancy.get());
    timestamps_.end(cmd);
    computeToCompute(cmd);
    // With the temporal pass, the final blur is part of it.
    const uint32_t passes = ao_.chain.denoisePasses;
    timestamps_.begin(cmd, "denoise");
    denoisePass_->record(cmd, targets_.ao(), passes, temporal() && passes > 0 ? passes - 1 : passes, gtaoConstants_);
    timestamps_.end(cmd);
    if (temporal()) {
        // Reads the last output, writes the other image, which becomes the last.
        const vk::Image& previous = targets_.image(TargetId::AoHistory, historyIndex_);
        historyIndex_ = 1 - historyIndex_;
        timestamps_.begin(cmd, "temporal");
        temporalPass_->record(cmd, targets_.ao(), previous, targets_.image(TargetId::AoHistory, historyIndex_), gtaoConstants_,
                              temporalConstants_, &objectUniforms_, motion() ? &targets_.image(TargetId::Motion) : &targets_.image(TargetId::Depth));
        timestamps_.end(cmd);
        computeToCompute(cmd);
    }
}

FrameStats Renderer::render(const Camera& camera, uint32_t frameIndex, FrameCopy* copy) {
    const auto start = std::chrono::steady_clock::now();
    const gpu::FrameUniforms uniforms = frameUniforms(camera, lighting_, ao_);
    std::memcpy(frame_.mapped(), &uniforms, sizeof uniforms);
    if (ao_.enabled) {
        const uint32_t scale = ao_.chain.fullResolution ? 1 : 2;
        gpu::GtaoConstants constants = gtaoConstants(camera, gpuSettings(ao_), frameIndex, scale);
        if (objects_) normalTable(constants.viewNormals, glm::transpose(camera.basis), poses_);
        std::memcpy(gtaoConstants_.mapped(), &constants, sizeof constants);
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
    const Camera& lastCamera = lastCamera_ ? *lastCamera_ : camera;
    const std::vector<voxel::ObjectPose>& lastPoses = lastCamera_ ? lastPoses_ : poses_;
    if (objects_) {
        const gpu::ObjectUniforms o = objectUniforms(poses_, lastCamera, lastPoses);
        std::memcpy(objectUniforms_.mapped(), &o, sizeof o);
    }
    const GBufferObjects drawObjects{objectScenes_, poses_, lastPoses, &lastCamera};

    VkCommandBuffer cmd = cmd_;
    VK_CHECK(vkResetCommandBuffer(cmd, 0));
    VkCommandBufferBeginInfo bi{.sType = VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO,
                                .flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT};
    VK_CHECK(vkBeginCommandBuffer(cmd, &bi));
    timestamps_.reset(cmd);
    // Scene edits since the last frame: copies into the vertex and index buffers,
    // with their barrier to vertex input.
    scene_.recordUploads(cmd);

    const auto top = VK_PIPELINE_STAGE_TOP_OF_PIPE_BIT;
    const auto fragmentTests = VK_PIPELINE_STAGE_EARLY_FRAGMENT_TESTS_BIT | VK_PIPELINE_STAGE_LATE_FRAGMENT_TESTS_BIT;
    const auto colorOut = VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT;
    const auto compute = VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT;
    const auto readOnly = VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL;
    const auto depthAttachment = VK_IMAGE_LAYOUT_DEPTH_STENCIL_ATTACHMENT_OPTIMAL;
    const auto depthWrite = VK_ACCESS_DEPTH_STENCIL_ATTACHMENT_READ_BIT | VK_ACCESS_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT;

    // G-buffer: previous contents are not needed (cleared), so start from UNDEFINED.
    vk::transition(cmd, targets_.image(TargetId::Depth), VK_IMAGE_LAYOUT_UNDEFINED, depthAttachment, top, 0, fragmentTests, depthWrite);
    vk::transition(cmd, targets_.image(TargetId::Surface), VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL, top, 0,
                   colorOut, VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT);
    if (motion())
        vk::transition(cmd, targets_.image(TargetId::Motion), VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL, top, 0,
                       colorOut, VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT);
    timestamps_.begin(cmd, "gbuffer");
    FrameStats stats;
    // First what was visible last frame; with occlusion culling, then the rest that
    // its depth does not hide (chunk_culling.h). Between the two the CPU decides,
    // so the frame is submitted in two parts. The objects are drawn last.
    const std::vector<QuadDraw>& early = culling_.begin(scene_, camera, cullingOptions_);
    const GBufferObjects* drawn = objects_ ? &drawObjects : nullptr;
    stats.quadsDrawn = gbufferPass_->record(cmd, targets_.gbuffer(), scene_, frame_, camera, early, true, drawn,
                                            !cullingOptions_.occlusion);
    if (cullingOptions_.occlusion) {
        vk::transition(cmd, targets_.image(TargetId::Depth), depthAttachment, readOnly, fragmentTests,
                       VK_ACCESS_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT, compute, VK_ACCESS_SHADER_READ_BIT);
        hizPass_->record(cmd, targets_.image(TargetId::Depth));
        submitAndWait(cmd);
        const std::vector<QuadDraw>& late = culling_.late(hizPass_->tiles());
        VK_CHECK(vkResetCommandBuffer(cmd, 0));
        VK_CHECK(vkBeginCommandBuffer(cmd, &bi));
        vk::transition(cmd, targets_.image(TargetId::Depth), readOnly, depthAttachment, compute, VK_ACCESS_SHADER_READ_BIT,
                       fragmentTests, depthWrite);
        stats.quadsDrawn += gbufferPass_->record(cmd, targets_.gbuffer(), scene_, frame_, camera, late, false, drawn);
    }
    stats.culling = culling_.stats();
    timestamps_.end(cmd);

    // Everything after reads the G-buffer from compute shaders.
    vk::transition(cmd, targets_.image(TargetId::Depth), depthAttachment, readOnly, fragmentTests,
                   VK_ACCESS_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT, compute, VK_ACCESS_SHADER_READ_BIT);
    vk::transition(cmd, targets_.image(TargetId::Surface), VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL, readOnly, colorOut,
                   VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT, compute, VK_ACCESS_SHADER_READ_BIT);
    if (motion())
        vk::transition(cmd, targets_.image(TargetId::Motion), VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL, readOnly, colorOut,
                       VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT, compute, VK_ACCESS_SHADER_READ_BIT);
    if (shadows()) {
        timestamps_.begin(cmd, "shadow");
        const vk::Image& history = targets_.image(TargetId::ShadowHistory, shadowHistoryIndex_);
        if (softShadows()) shadowHistoryIndex_ = 1 - shadowHistoryIndex_;  // reads the last, writes the other
        shadowPass_->record(cmd, targets_.gbuffer(), objectUniforms_, targets_.image(TargetId::Shadow), traceConstants_, *scene_.occupancy, &history,
                            &targets_.image(TargetId::ShadowHistory, shadowHistoryIndex_));
        timestamps_.end(cmd);
    }
    if (ao_.enabled) recordAo(cmd);
    computeToCompute(cmd);  // the shadow and the AO, before the composite reads them
    vk::transition(cmd, targets_.image(TargetId::Color), VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_GENERAL, top, 0, compute,
                   VK_ACCESS_SHADER_WRITE_BIT);
    timestamps_.begin(cmd, "composite");
    compositePass_->record(cmd, targets_.gbuffer(), ao_.enabled ? aoHalfOutput() : targets_.image(TargetId::AoRaw), targets_.image(TargetId::Color), frame_,
                           scene_.palette, gtaoConstants_, objectUniforms_, targets_.image(TargetId::Shadow));
    timestamps_.end(cmd);
    if (displayOn_) {
        computeToCompute(cmd);
        timestamps_.begin(cmd, "display");
        displayPass_->record(cmd, targets_.image(TargetId::Color), targets_.image(TargetId::Display), toneMapCurve(lighting_.toneMap));
        timestamps_.end(cmd);
    }
    if (copy) recordCopy(cmd, *copy, camera);

    submitAndWait(cmd);
    stats.wallMs = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    stats.passMs = timestamps_.read();
    lastCamera_ = camera;
    lastPoses_ = poses_;
    return stats;
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

void Renderer::recordCopy(VkCommandBuffer cmd, FrameCopy& copy, const Camera& camera) {
    copy.begin({.width = width(), .height = height(), .half = targets_.ao().half,
                .scale = ao_.chain.fullResolution ? 1u : 2u, .ao = ao_.enabled, .toneMap = toneMapCurve(lighting_.toneMap),
                .camera = camera, .poses = poses_, .albedo = scene_.albedo});
    const auto ro = VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL, general = VK_IMAGE_LAYOUT_GENERAL;
    auto copyPart = [&](FrameCopy::Part part, const vk::Image& image, VkImageLayout layout, uint32_t bytesPerPixel) {
        const VkDeviceSize bytes = VkDeviceSize(image.extent.width) * image.extent.height * bytesPerPixel;
        vk::recordImageCopy(cmd, image, layout, bytesPerPixel, copy.reserve(part, bytes), 0);
    };
    copyPart(FrameCopy::Color, targets_.image(TargetId::Color), general, 16);
    if (copy.aovs()) {
        if (shadows()) copyPart(FrameCopy::Shadow, targets_.image(TargetId::Shadow), general, 4);
        copyPart(FrameCopy::Depth, targets_.image(TargetId::Depth), ro, 4);
        copyPart(FrameCopy::Surface, targets_.image(TargetId::Surface), ro, 2);
        if (motion()) copyPart(FrameCopy::Motion, targets_.image(TargetId::Motion), ro, 16);
    }
    if (copy.aovs() && ao_.enabled) {
        // What the frame computed on the way without storing: the full-res AO (the
        // composite upsamples for itself) and, when the temporal pass blurs for
        // itself, the spatial AO. The same shaders on the same inputs give the same values.
        if (!aoAov_) {  // made on first use: frames do not store it
            aoAov_ = true;
            targets_.update(wantedShape(), cmd);
        }
        computeToCompute(cmd);  // after the frame's own writes
        if (temporal() && ao_.chain.denoisePasses > 0)
            denoisePass_->recordFinal(cmd, targets_.ao(), ao_.chain.denoisePasses, gtaoConstants_);
        upsamplePass_->record(cmd, targets_.image(TargetId::Depth), targets_.image(TargetId::Surface), aoHalfOutput(), targets_.image(TargetId::AoFull),
                              gtaoConstants_);
        computeToCompute(cmd);
        copyPart(FrameCopy::AoFull, targets_.image(TargetId::AoFull), general, 4);
        copyPart(FrameCopy::Raw, targets_.image(TargetId::AoRaw), general, 16);
        copyPart(FrameCopy::Spatial, targets_.ao().denoised(ao_.chain.denoisePasses), general, 16);
        if (temporal()) copyPart(FrameCopy::History, aoHalfOutput(), general, 16);
    }
    vk::recordHostRead(cmd);
}

FrameImages Renderer::readback(const Camera& camera, bool aovs) {
    FrameCopy copy(ctx_, aovs);
    ctx_.submitAndWait([&](VkCommandBuffer cmd) { recordCopy(cmd, copy, camera); });
    return copy.decode();
}

}  // namespace grotto
