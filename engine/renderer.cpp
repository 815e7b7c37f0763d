// The whole frame on one screen (recordFrame): G-buffer (with occlusion culling, its
// Hi-Z and, in render(), a mid-frame submit), sun shadows, with the face cache the
// objects' light (with the face cache: first its rays for the faces in view not
// converged), then with AO the depth prefilter, the estimator, spatial denoise
// and temporal accumulation at AO resolution, then the composite (which upsamples
// the AO itself), the display image and the read-backs (renderer_copy.cpp).
// Each pass declares what it reads and writes; the barriers follow from that.
// render() waits for its frame; submit() keeps two in flight.
#include "engine/renderer.h"

#include "grotto/error.h"
#include "engine/frame/pass_traffic.h"
#include "engine/frame/render_memory.h"
#include "shaders/shared/face_trace.h"
#include "voxel/daylight.h"

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <string_view>
#include <utility>

namespace grotto {

Renderer::Renderer(vk::Context& ctx, GpuScene& scene, const voxel::Lighting& lighting, const AoOptions& ao,
                   uint32_t width, uint32_t height, const SceneObjects* objects)
    : ctx_(ctx), scene_(scene), given_(lighting), lighting_(voxel::lightingInEffect(lighting)), ao_(ao), targets_(ctx), objects_(objects), passes_(ctx) {
    if (objects_) poses_ = objects_->poses(0.0), objectScenes_ = objects_->list();
    try {
        requireAo(ao_);
        // Before any allocation can fail halfway.
        const FramePlan plan = planFor(width, height, ao_, given_);
        requireRenderFits(ctx, plan, "image size");
        for (auto& s : slots_) s = std::make_unique<FrameSlot>(ctx);
        VkSemaphoreTypeCreateInfo type{.sType = VK_STRUCTURE_TYPE_SEMAPHORE_TYPE_CREATE_INFO,
                                       .semaphoreType = VK_SEMAPHORE_TYPE_TIMELINE};
        const VkSemaphoreCreateInfo sci{.sType = VK_STRUCTURE_TYPE_SEMAPHORE_CREATE_INFO, .pNext = &type};
        VK_CHECK(vkCreateSemaphore(ctx.device, &sci, nullptr, &timeline_));
        applyPlan(plan);
        targets_.update(plan);
    } catch (...) {  // e.g. a shader that fails to load: free what was made before it
        release();
        throw;
    }
}

SceneFacts Renderer::sceneFacts() const {
    SceneFacts facts{.occupancy = scene_.occupancy() != nullptr, .objects = objects_ != nullptr,
                     .movingObjects = objects_ && objects_->moving};
    if (const GpuFaceCache* cache = scene_.faceCache()) {
        facts.faceCache = {cache->sun().direction, cache->sun().angleDegrees, cache->sun().day, cache->sky().fullLight,
                           cache->dayLightFirst() != 0};
        // GROTTO_CACHE_READ=chain: the chain of look-ups instead (A/B measurements, tests).
        const char* read = std::getenv("GROTTO_CACHE_READ");
        facts.faceAtlas = scene_.faceAtlasCurrent() && !(read && std::string_view(read) == "chain");
    }
    return facts;
}

FramePlan Renderer::planFor(uint32_t width, uint32_t height, const AoOptions& ao,
                            const voxel::Lighting& lighting) const {
    return planFrame(width, height, ao, lighting, sceneFacts(),
                     {.display = displayOn_, .normals = normalsOn_, .aoAov = aoAov_});
}

void Renderer::applyPlan(const FramePlan& plan) {
    if (passes_.changes(plan)) finishFrames();  // no frame in flight may use a pass freed
    passes_.update(plan);
    plan_ = plan;
}

void Renderer::planAovs() {
    if (aoAov_ || !(plan_.faceCache || plan_.chain)) return;
    aoAov_ = true;
    const FramePlan plan = wantedPlan();
    targets_.update(plan);  // the AO AOV's target, no history: the histories go on
    applyPlan(plan);
}

CompositePass& Renderer::composite() {
    // The header's count, as the last frame to finish left it: faces never traced
    // since their edit, whose taps the asking composite drops and asks for. Faces
    // whose sky light alone is left to refresh are the request pass's and the
    // backlog's, and the frame may read through the atlas meanwhile.
    if (plan_.cacheTracing && scene_.faceCache()->lastHeader()[GROTTO_FACE_ROUGH] != 0)
        return passes_.get<AskingCompositePass>();
    return passes_.get<CompositePass>();
}

// Histories in new images start afresh.
void Renderer::updateTargets(const FramePlan& plan) {
    finishFrames();  // no GPU work of ours may use the targets freed
    if (!targets_.update(plan)) return;
    surfaceCamera_.reset();
}

void Renderer::setDisplayImage(bool on) { setGameImage(displayOn_, on, "display image"); }
void Renderer::setNormalsImage(bool on) { setGameImage(normalsOn_, on, "normals image"); }

void Renderer::setGameImage(bool& flag, bool on, const char* what) {
    if (on == flag) return;
    finishFrames();
    flag = on;
    if (on) {
        try {
            requireRenderFits(ctx_, wantedPlan(), what);
        } catch (...) {
            flag = false;
            throw;
        }
    } else {
        vkDeviceWaitIdle(ctx_.device);  // a game may still read it
    }
    applyPlan(wantedPlan());
    targets_.update(plan_);
}

Renderer::~Renderer() { release(); }

void Renderer::release() {
    if (timeline_) finishFrames();
    vkDeviceWaitIdle(ctx_.device);
    vkDestroySemaphore(ctx_.device, timeline_, nullptr);
    timeline_ = VK_NULL_HANDLE;
    for (auto& s : slots_) s.reset();
    passes_.release();
    targets_.release();
    vk::destroy(ctx_, objectGrids_.buffer);
}

void Renderer::resize(uint32_t width, uint32_t height) {
    const FramePlan plan = planFor(width, height, ao_, given_);
    requireRenderFits(ctx_, plan, "image size");
    restart(plan);
}

void Renderer::restart(const FramePlan& plan) {
    applyPlan(plan);
    updateTargets(plan);
    resetHistory();
}

void Renderer::setLighting(const voxel::Lighting& given) {
    const voxel::Lighting lighting = voxel::lightingInEffect(given);
    const FramePlan plan = planFor(width(), height(), ao_, given);
    // Uniforms only, unless passes or targets change or the ambient's source (its light everywhere).
    const bool restarts = passes_.changes(plan) || targets_.changes(plan) || lighting.ambientFrom != lighting_.ambientFrom;
    if (restarts) requireRenderFits(ctx_, plan, "lighting");  // a soft sun's history may not fit
    // A moved sun stales the histories that hold it: a soft sun's shadow at once;
    // the light objects take with full light (what the faces they see send back,
    // the sun's bounce) once the sun has moved kObjectLightSunDegrees since the
    // history began, so a day's sun, a quarter of a degree a frame along houses'
    // day, does not restart it every frame. Objects' AO and sky weights hold no
    // sun: a day's moving sun keeps them.
    const bool sunMoved = lighting.sunDirection != lighting_.sunDirection || lighting.sunAngle != lighting_.sunAngle;
    const bool objectLightHoldsSun = plan.objectLight && ambientSource(lighting, ao_) == voxel::AmbientSource::Full;
    const bool objectLightStale =
        objectLightHoldsSun && (!historySun_ || glm::dot(glm::normalize(lighting.sunDirection), *historySun_) <
                                                    std::cos(glm::radians(kObjectLightSunDegrees)));
    if ((plan.softShadows && sunMoved) || (sunMoved && objectLightStale)) {
        surfaceCamera_.reset();
        historySun_ = glm::normalize(lighting.sunDirection);
    }
    given_ = given, lighting_ = lighting;
    if (restarts) restart(plan);
    else plan_ = plan;
}

void Renderer::requireAo(const AoOptions& ao) const {
    validateAo(ao, "AO settings");
    const SceneFacts scene = sceneFacts();
    if ((ao.enabled && tracesVoxels(ao.method) || voxelThickness(ao) || faceCached(ao)) && !scene.occupancy)
        throw Error("AO settings", std::string("AO method '") + aoMethodName(ao.method) + "' traces the world's voxels",
                    "upload the scene from its world (uploadScene(ctx, world)), not from a mesh alone");
    if (faceCached(ao) && !scene.faceCache)
        throw Error("AO settings", "AO method 'cache' reads the light cached on the world's faces, and no face cache is loaded",
                    "load a bake of the world (made by grotto bake) or bake it first");
}

void Renderer::setAo(const AoOptions& ao) {
    requireAo(ao);
    const FramePlan plan = planFor(width(), height(), ao, given_);
    requireRenderFits(ctx_, plan, "AO settings");
    ao_ = ao;
    restart(plan);
}

TargetRef Renderer::aoOutput() const {
    if (!plan_.chain) return TargetId::AoRaw;  // the 1x1 placeholder the composite binds
    return plan_.temporal ? TargetId::AoHistory : denoisedTarget(ao_.chain.denoisePasses);
}

void Renderer::countImageBytes(const PassDecl& decl) {
    const std::string* timed = slot().timestamps.open();
    if (!timed) return;
    std::vector<std::pair<std::string, uint64_t>>& bytes = slot().passBytes;
    auto at = std::find_if(bytes.begin(), bytes.end(), [&](const auto& p) { return p.first == *timed; });
    if (at == bytes.end()) at = bytes.insert(bytes.end(), {*timed, 0});
    at->second += declaredImageBytes(decl, targets_);
}

void Renderer::pass(VkCommandBuffer cmd, const PassDecl& decl, const std::function<void()>& record) {
    targets_.recordBarriers(cmd, decl.uses);
    if (decl.timestamp) slot().timestamps.begin(cmd, decl.timestamp);
    countImageBytes(decl);
    record();
    if (decl.timestamp) slot().timestamps.end(cmd);
}

FrameStats Renderer::render(const Camera& camera, uint32_t frameIndex, FrameCopy* copy) {
    const auto start = std::chrono::steady_clock::now();
    finishFrames();  // frames submitted in flight before: this one starts on an idle queue
    if (copy && copy->aovs()) planAovs();
    FrameStats stats = recordFrame(camera, frameIndex, copy, false);
    submitAndWait(slot().cmd);
    stats.wallMs = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    stats.passMs = slot().timestamps.read();
    stats.passBytes = slot().passBytes;
    slot().timesUnread = false;
    stats.timelineValue = submitted_;
    lastCamera_ = camera;
    lastPoses_ = poses_;
    return stats;
}

FrameStats Renderer::submit(const Camera& camera, uint32_t frameIndex, const FrameSync& sync, FrameCopy* copy) {
    const auto start = std::chrono::steady_clock::now();
    if (copy && copy->aovs()) planAovs();
    FrameStats stats = recordFrame(camera, frameIndex, copy, true);
    submitCommands(slot().cmd, sync.waits);
    slot().timesUnread = true;
    stats.wallMs = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    stats.timelineValue = submitted_;
    lastCamera_ = camera;
    lastPoses_ = poses_;
    return stats;
}

// The frame, top to bottom; each pass's barriers follow from what it declares.
FrameStats Renderer::recordFrame(const Camera& camera, uint32_t frameIndex, FrameCopy* copy, bool inFlight) {
    applyPlan(wantedPlan());  // the scene's face cache may have come or changed its sun
    if (plan_.objectRays) refreshObjectGrids();
    slotIndex_ = 1 - slotIndex_;
    FrameSlot& s = slot();
    waitFor(s.done);  // the frame two before: its slot's buffers are the CPU's again
    std::vector<std::pair<std::string, double>> unread;
    std::vector<std::pair<std::string, uint64_t>> unreadBytes;
    if (s.timesUnread) unread = s.timestamps.read(), unreadBytes = std::move(s.passBytes);
    s.timesUnread = false;
    s.passBytes.clear();
    writeConstants(camera, frameIndex);
    VkCommandBuffer cmd = beginCommands();
    s.timestamps.reset(cmd);
    if (inFlight) {
        // Everything before on the queue (the last frame, a game's reads of it) ends
        // and its writes are visible before this frame's first command.
        const VkMemoryBarrier before{.sType = VK_STRUCTURE_TYPE_MEMORY_BARRIER,
                                     .srcAccessMask = VK_ACCESS_MEMORY_WRITE_BIT,
                                     .dstAccessMask = VK_ACCESS_MEMORY_READ_BIT | VK_ACCESS_MEMORY_WRITE_BIT};
        vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_ALL_COMMANDS_BIT, VK_PIPELINE_STAGE_ALL_COMMANDS_BIT, 0, 1, &before,
                             0, nullptr, 0, nullptr);
    }
    targets_.beginFrame(!inFlight);
    targets_.advanceHistories(plan_);
    scene_.recordUploads(cmd, s.staging);  // edits since the last frame, with their barrier to vertex input
    FrameStats stats = inFlight ? recordGBufferInFlight(cmd, camera) : recordGBuffer(cmd, camera);
    stats.passMs = std::move(unread);
    stats.passBytes = std::move(unreadBytes);
    if (plan_.cacheTracing)
        pass(cmd, FaceCacheTracePass::declare(), [&] {
            passes_.get<FaceCacheTracePass>().record(cmd, targets_.gbuffer(), {width(), height()}, s.frame, s.traceConstants,
                                    *scene_.occupancy(), *scene_.faceCache(),
                                    ao_.chain.cacheRays ? ao_.chain.cacheRays : defaultCacheRays(ctx_));
        });
    if (plan_.tracedShadows)
        pass(cmd, passes_.get<ShadowPass>().declare(), [&] {
            passes_.get<ShadowPass>().record(cmd, targets_.gbuffer(), s.objectUniforms, image(TargetId::Shadow), s.traceConstants,
                                *scene_.occupancy(), objectGrids_.buffer, &image({TargetId::ShadowHistory, Copy::Previous}),
                                &image(TargetId::ShadowHistory));
        });
    if (plan_.objectLight)
        pass(cmd, ObjectLightPass::declare(), [&] {
            passes_.get<ObjectLightPass>().record(cmd, targets_.gbuffer(), s.objectUniforms, image(TargetId::ObjectLight),
                                     image({TargetId::ObjectLightHistory, Copy::Previous}),
                                     image(TargetId::ObjectLightHistory), s.traceConstants,
                                     *scene_.occupancy(), objectGrids_.buffer, scene_.palette, *scene_.faceCache());
        });
    if (plan_.chain) recordAo(cmd);
    pass(cmd, CompositePass::declare(aoOutput()), [&] {
        composite().record(cmd, targets_.gbuffer(), image(TargetId::Color),
                               {.aoHalf = image(aoOutput()), .frame = s.frame, .palette = scene_.palette,
                                .gtaoConstants = s.aoConstants, .objectUniforms = s.objectUniforms,
                                .shadow = image(TargetId::Shadow), .bentNormals = image(TargetId::AoBentNormal),
                                .faceCache = scene_.faceCache(), .objectLight = &image(TargetId::ObjectLight),
                                .shadowEdges = plan_.shadowEdges ? &passes_.get<ShadowEdgePass>().edges() : nullptr,
                                .atlasRecord = &targets_.gbuffer().atlasRecord, .atlasCells = &scene_.faceAtlasCells()});
    });
    if (plan_.shadowEdges)
        pass(cmd, ShadowEdgePass::declare(), [&] {
            passes_.get<ShadowEdgePass>().record(cmd, targets_.gbuffer(), image(TargetId::Color), s.traceConstants, *scene_.occupancy());
        });
    if (plan_.display)
        pass(cmd, DisplayPass::declare(), [&] {
            passes_.get<DisplayPass>().record(cmd, image(TargetId::Color), image(TargetId::Display), toneMapCurve(lighting_.toneMap));
        });
    if (plan_.normals)
        pass(cmd, NormalsPass::declare(), [&] {
            passes_.get<NormalsPass>().record(cmd, targets_.gbuffer().surface, s.objectUniforms, image(TargetId::Normals));
        });
    if (copy) recordCopy(cmd, *copy, camera);
    return stats;
}

// First what was visible last frame; with occlusion culling, then the rest that its
// depth does not hide (chunk_culling.h). Between the two the CPU decides, so the
// frame is submitted in two parts. The objects are drawn last.
FrameStats Renderer::recordGBuffer(VkCommandBuffer cmd, const Camera& camera) {
    const GBufferObjects drawObjects{objectScenes_, poses_, lastCamera_ ? lastPoses_ : poses_,
                                     lastCamera_ ? &*lastCamera_ : &camera};
    const GBufferObjects* drawn = objects_ ? &drawObjects : nullptr;
    GBufferPass& gbufferPass = passes_.get<GBufferPass>();
    const PassDecl gbuffer = gbufferPass.declare();
    FrameStats stats;
    FrameSlot& s = slot();
    targets_.recordBarriers(cmd, gbuffer.uses);
    s.timestamps.begin(cmd, gbuffer.timestamp);
    countImageBytes(gbuffer);
    const std::vector<QuadDraw>& early = culling_.begin(scene_, camera, cullingOptions_);
    stats.quadsDrawn = gbufferPass.record(cmd, targets_.gbuffer(), scene_, s.frame, camera, early, true, drawn,
                                            !cullingOptions_.occlusion);
    s.hizWritten = false;  // these tiles hold the first phase only
    if (cullingOptions_.occlusion) {
        pass(cmd, HizPass::declare(), [&] { passes_.get<HizPass>().record(cmd, image(TargetId::Depth), s.hiz); });
        submitAndWait(cmd);
        const std::vector<QuadDraw>& late = culling_.late(s.hiz.tiles());
        beginCommands();
        targets_.recordBarriers(cmd, gbuffer.uses);
        stats.quadsDrawn += gbufferPass.record(cmd, targets_.gbuffer(), scene_, s.frame, camera, late, false, drawn);
    }
    stats.culling = culling_.stats();
    s.timestamps.end(cmd);
    return stats;
}

// Frames in flight: no wait in the middle. The second phase is culled against the
// tiles of a finished frame that saw the same (reusableTiles), and both phases are
// drawn in one pass; this frame's tiles, of its whole depth, serve the frames after.
FrameStats Renderer::recordGBufferInFlight(VkCommandBuffer cmd, const Camera& camera) {
    const GBufferObjects drawObjects{objectScenes_, poses_, lastCamera_ ? lastPoses_ : poses_,
                                     lastCamera_ ? &*lastCamera_ : &camera};
    GBufferPass& gbufferPass = passes_.get<GBufferPass>();
    const PassDecl gbuffer = gbufferPass.declare();
    FrameStats stats;
    FrameSlot& s = slot();
    targets_.recordBarriers(cmd, gbuffer.uses);
    s.timestamps.begin(cmd, gbuffer.timestamp);
    countImageBytes(gbuffer);
    std::vector<QuadDraw> draws = culling_.begin(scene_, camera, cullingOptions_);
    if (cullingOptions_.occlusion) {
        const std::vector<QuadDraw>& late = culling_.late(reusableTiles(camera));
        draws.insert(draws.end(), late.begin(), late.end());
    }
    stats.quadsDrawn = gbufferPass.record(cmd, targets_.gbuffer(), scene_, s.frame, camera, draws, true,
                                            objects_ ? &drawObjects : nullptr);
    s.hizWritten = cullingOptions_.occlusion;
    if (s.hizWritten) {
        pass(cmd, HizPass::declare(), [&] { passes_.get<HizPass>().record(cmd, image(TargetId::Depth), s.hiz); });
        s.hizViewProj = camera.viewProjRelativeDouble();
        s.hizPosition = camera.position;
        s.hizSceneUpdates = scene_.updates;
        s.hizPoses = poses_;
    }
    stats.culling = culling_.stats();
    s.timestamps.end(cmd);
    return stats;
}

// Tiles hold the depth of a whole frame: for the same camera, scene and poses, a
// box behind them is hidden in this frame too. The most recent finished frame's
// first: the other slot's if it has finished, else this slot's last (waited for).
DepthTiles Renderer::reusableTiles(const Camera& camera) const {
    uint64_t reached = 0;
    VK_CHECK(vkGetSemaphoreCounterValue(ctx_.device, timeline_, &reached));
    const FrameSlot& other = *slots_[1 - slotIndex_];
    for (const FrameSlot* s : {&other, static_cast<const FrameSlot*>(&slot())}) {
        const bool finished = s != &other || other.done <= reached;
        if (finished && s->hizWritten && s->hizViewProj == camera.viewProjRelativeDouble() &&
            s->hizPosition == camera.position && s->hiz.width == camera.width && s->hiz.height == camera.height &&
            s->hizSceneUpdates == scene_.updates && s->hizPoses == poses_)
            return s->hiz.tiles();
    }
    return {};
}

void Renderer::recordAo(VkCommandBuffer cmd) {
    const AoTargets& ao = targets_.ao();
    DepthPrefilterPass& prefilter = passes_.get<DepthPrefilterPass>();
    EstimatorPass& estimator = passes_.get<EstimatorPass>();
    pass(cmd, prefilter.declare(), [&] {
        prefilter.record(cmd, image(TargetId::Depth), image(TargetId::Surface), ao, slot().aoConstants,
                               slot().traceConstants, scene_.occupancy());
    });
    pass(cmd, estimator.declare(), [&] {
        estimator.record(cmd, image(TargetId::Surface), ao, slot().aoConstants, slot().traceConstants,
                               scene_.occupancy(), &objectGrids_.buffer);
    });
    // With the temporal pass, the final blur is part of it.
    const uint32_t passes = ao_.chain.denoisePasses, blurs = plan_.temporal && passes > 0 ? passes - 1 : passes;
    slot().timestamps.begin(cmd, DenoisePass::kTimestamp);
    for (uint32_t i = 0; i < blurs; ++i)
        pass(cmd, DenoisePass::declare(i), [&] { passes_.get<DenoisePass>().record(cmd, ao, passes, i, slot().aoConstants); });
    slot().timestamps.end(cmd);
    if (!plan_.temporal) return;
    // Reads the last output, writes this frame's.
    TemporalPass& temporal = passes_.get<TemporalPass>();
    pass(cmd, temporal.declare(plan_.motion), [&] {
        temporal.record(cmd, ao, image({TargetId::AoHistory, Copy::Previous}), image(TargetId::AoHistory),
                        slot().aoConstants, slot().temporalConstants, &slot().objectUniforms,
                        &image(plan_.motion ? TargetId::Motion : TargetId::Depth));
    });
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
    finishFrames();  // no frame in flight may draw the scene the caller frees next
    objectScenes_.erase(objectScenes_.begin() + ptrdiff_t(index));
    poses_.erase(poses_.begin() + ptrdiff_t(index));
    if (index < lastPoses_.size()) lastPoses_.erase(lastPoses_.begin() + ptrdiff_t(index));
}

}  // namespace grotto
