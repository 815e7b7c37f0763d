#pragma once
// Orders the passes of a frame; the barriers between them follow from what each
// declares it reads and writes (engine/frame/pass_decl.h).
#include "engine/ao_settings.h"
#include "engine/camera.h"
#include "engine/frame/frame_constants.h"
#include "engine/frame/frame_copy.h"
#include "engine/frame/frame_slot.h"
#include "engine/frame/frame_targets.h"
#include "engine/frame/frame_images.h"
#include "engine/frame/frame_passes.h"
#include "engine/frame/frame_plan.h"
#include "engine/frame/history_boxes.h"
#include "engine/scene/scene.h"
#include "engine/scene/scene_objects.h"
#include "engine/vk/timestamps.h"
#include "shaders/shared/temporal.h"
#include "voxel/world_desc.h"

#include <array>
#include <functional>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <utility>
#include <vector>

namespace grotto {

struct FrameStats {
    // GPU time per pass: render()'s own frame; submit()'s, the frame submitted two
    // calls before (when its slot is reused), empty for the first two.
    std::vector<std::pair<std::string, double>> passMs;
    // The same frame's passes' declared images, in bytes (pass_traffic.h): the
    // least memory each can move, summed under its passMs name.
    std::vector<std::pair<std::string, uint64_t>> passBytes;
    double wallMs = 0.0;  // record + submit (+ wait, render())
    uint64_t quadsDrawn = 0;
    CullingStats culling;  // what level of detail and culling left to draw
    uint64_t timelineValue = 0;  // Renderer::timeline() reaches it once the frame has finished
};

// What a game hands a frame in flight (Renderer::submit): the semaphores of its
// own work (on other queues) that the frame must wait for (grotto/vulkan.h).
struct FrameSync {
    std::vector<FrameWait> waits;
};

class Renderer {
public:
    // The scene may change between frames (GpuScene::updateChunks): each frame
    // first records its staged uploads. `objects`: the scene's objects (kept by
    // the caller), drawn at their poses (setObjectPoses; at time 0 until then).
    Renderer(vk::Context& ctx, GpuScene& scene, const voxel::Lighting& lighting, const AoOptions& ao,
             uint32_t width, uint32_t height, const SceneObjects* objects = nullptr);
    ~Renderer();

    // Renders frame `frameIndex` (it advances the AO noise). The temporal pass
    // accumulates over consecutive frame indices (wrapping); any other index starts
    // the history afresh. With `copy`, the frame's own command buffer also copies
    // its images into it (the AOVs when copy->aovs()), for decoding later on any
    // thread: the same images readback(camera, copy->aovs()) would return.
    FrameStats render(const Camera& camera, uint32_t frameIndex = 0, FrameCopy* copy = nullptr);
    // The same frame, on a game's device with two frames in flight: records the
    // whole frame and submits it in one submission after sync's waits, and returns
    // without waiting for it. It signals timeline() with the returned
    // timelineValue once finished. First it waits (on the CPU) for the frame two
    // before, whose slot (frame_slot.h) it reuses. The images (colorImage() and
    // the others) are this frame's until the next submit() or render(): a game
    // records its reads of them into submissions on the renderer's queue before
    // that call, waiting for timelineValue (docs/embedding.md says exactly). With
    // occlusion culling, the second phase is culled against the depth tiles of a
    // frame that has finished, one or two frames before, and only while camera,
    // scene and objects stay as they were then (else it is not culled): the image
    // is the one render() draws.
    FrameStats submit(const Camera& camera, uint32_t frameIndex, const FrameSync& sync = {}, FrameCopy* copy = nullptr);
    // Signalled by every submission with the next value (FrameStats::timelineValue).
    VkSemaphore timeline() const { return timeline_; }
    // Waits until every frame submitted has finished (a no-op after render()).
    void finishFrames();
    // The objects' poses for the next frames, one per object. The poses of the
    // frame before are kept for the motion vectors.
    void setObjectPoses(std::span<const voxel::ObjectPose> poses);
    const std::vector<voxel::ObjectPose>& objectPoses() const { return poses_; }
    // The caller's objects gained one (at the end, at `pose`, still: no motion in
    // its first frame) or lost object `index` (before its scene is freed); the
    // others keep their poses and motion.
    void objectAdded(const voxel::ObjectPose& pose);
    void objectRemoved(size_t index);
    // A camera cut: the next frame starts without history.
    void resetHistory() {
        previousCamera_.reset();
        surfaceCamera_.reset();
        culling_.reset();
    }
    // Levels of detail and occlusion culling for the G-buffer (chunk_culling.h);
    // the default is a world file's (voxel::Detail).
    void setCulling(const CullingOptions& options) { cullingOptions_ = options; }
    const CullingOptions& culling() const { return cullingOptions_; }
    // Voxels in `changed` (world units) were edited: in the next frame, every pixel
    // whose surface lies within the AO's reach of it (aoReach: the radius, times
    // GTAO's multiplier) starts its temporal history afresh. Applies to the next
    // render only.
    void invalidateHistory(const voxel::WorldBox& changed) { invalidated_.add(changed); }

    // Settings changed in place, the scene untouched. A new size remakes the render
    // targets and restarts the history; lighting is uniforms only; new AO settings
    // remake only the passes and targets that depend on what changed, and restart
    // the history. Each throws grotto::Error (input) as the constructor would.
    void resize(uint32_t width, uint32_t height);
    void setLighting(const voxel::Lighting& lighting);
    void setAo(const AoOptions& ao);
    // Reads back the last frame, waiting for it and the copy; the G-buffer and AO
    // AOVs only when asked for.
    FrameImages readback(const Camera& camera, bool aovs);

    // The last frame's images, for an embedding game (include/grotto/grotto.h says
    // how to synchronise with them): scene-linear colour at full size, and the AO the
    // composite read (visibility in red) at AO resolution. Both in GENERAL.
    const vk::Image& colorImage() const { return image(TargetId::Color); }
    // With it on, every frame also tone-maps its colour into displayImage()
    // (RGBA16F, display-linear, GENERAL): what a window or a game shows. Off by
    // default: image files tone-map on the CPU and need no such pass.
    void setDisplayImage(bool on);
    const vk::Image& displayImage() const { return image(TargetId::Display); }
    // With it on, every frame also writes the world-space normal of each pixel's
    // face into normalsImage() (normals_pass.h; GENERAL). Off by default.
    void setNormalsImage(bool on);
    const vk::Image& normalsImage() const { return image(TargetId::Normals); }
    // The G-buffer's depth (D32, reverse-Z: 1 at the near plane, 0 at infinity) and
    // the layout the last frame left it in.
    const vk::Image& depthImage() const { return image(TargetId::Depth); }
    VkImageLayout layout(TargetId target) const { return targets_.layout(target); }
    const vk::Image& aoImage() const { return image(aoOutput()); }

    size_t targetBytes() const { return targets_.bytes(); }
    // What its frames do now: their passes and targets (frame_plan.h).
    const FramePlan& plan() const { return plan_; }
    const AoOptions& ao() const { return ao_; }
    const voxel::Lighting& lighting() const { return given_; }

private:
    // Turns an image only a game or a window reads on or off (`flag`: displayOn_ or normalsOn_).
    void setGameImage(bool& flag, bool on, const char* what);
    // What the scene has now: the one place the renderer looks; frames ask their plan.
    SceneFacts sceneFacts() const;
    // The frame at a size with these settings, this scene and what the caller asked for.
    FramePlan planFor(uint32_t width, uint32_t height, const AoOptions& ao, const voxel::Lighting& lighting) const;
    FramePlan wantedPlan() const { return planFor(width(), height(), ao_, given_); }  // at the current size
    // Takes `plan` as the frame's: its passes made, dropped or remade (once no
    // frame in flight uses those it frees).
    void applyPlan(const FramePlan& plan);
    // A read-back with AOVs: its target and passes made before the frame is recorded, kept from then on.
    void planAovs();
    uint32_t width() const { return plan_.width; }
    uint32_t height() const { return plan_.height; }
    void updateTargets(const FramePlan& plan);  // restarts the histories when targets change
    void restart(const FramePlan& plan);  // a plan whose frames start afresh: its passes, targets, no history
    void release();  // frees whatever exists; null handles are skipped
    // Records a pass: the barriers its declaration calls for, then `record` within its timestamp.
    void pass(VkCommandBuffer cmd, const PassDecl& decl, const std::function<void()>& record);
    // Adds a pass's declared images to this frame's FrameStats::passBytes, under
    // the timestamp open around it (its own, or a group's: the denoiser's blurs,
    // the depth tiles within the G-buffer's); untimed work counts nowhere.
    void countImageBytes(const PassDecl& decl);
    void writeConstants(const Camera& camera, uint32_t frameIndex);  // uniforms and constants of the frame
    VkCommandBuffer beginCommands();  // the slot's, reset and begun
    // Takes the next slot once its last frame has finished and records the frame
    // into its command buffer, not yet ended. `inFlight`: as submit(), else render().
    FrameStats recordFrame(const Camera& camera, uint32_t frameIndex, FrameCopy* copy, bool inFlight);
    FrameStats recordGBuffer(VkCommandBuffer cmd, const Camera& camera);
    FrameStats recordGBufferInFlight(VkCommandBuffer cmd, const Camera& camera);
    // Depth tiles of a finished frame that saw what this one sees; none (cull nothing) otherwise.
    DepthTiles reusableTiles(const Camera& camera) const;
    void recordAo(VkCommandBuffer cmd);
    // The last frame's images into `copy`, after everything recorded before.
    void recordCopy(VkCommandBuffer cmd, FrameCopy& copy, const Camera& camera);
    // The composite for this frame: while the cache has faces not converged, the
    // one that asks for the faces of the texels it reads.
    CompositePass& composite();
    void writeTraceConstants(const Camera& camera, uint32_t frameIndex, const gpu::FrameUniforms& frame);  // its day words and bits
    // Uploads the objects' grids for rays again when they changed (or were never uploaded).
    void refreshObjectGrids();
    // Ends the command buffer and submits it after `waits`, signalling the timeline's next value.
    void submitCommands(VkCommandBuffer cmd, std::span<const FrameWait> waits = {});
    void waitFor(uint64_t timelineValue);
    void submitAndWait(VkCommandBuffer cmd);  // both, for the last value
    // Throws grotto::Error (input) for AO settings out of range or that the scene
    // cannot serve: a method that traces voxels without the occupancy, the cache
    // without a face cache.
    void requireAo(const AoOptions& ao) const;
    TargetRef aoOutput() const;  // the AO chain's last output: what the composite reads
    const vk::Image& image(TargetRef target) const { return targets_.image(target); }

    vk::Context& ctx_;
    GpuScene& scene_;
    voxel::Lighting given_;     // as set: what lighting() returns
    voxel::Lighting lighting_;  // in effect: the day's sun and sky at its time (voxel/daylight.h)
    AoOptions ao_;
    FrameTargets targets_;
    bool displayOn_ = false;
    bool normalsOn_ = false;
    bool aoAov_ = false;  // a read-back asked for the AO AOVs: their full-res target is kept from then on
    // The full-res histories of a soft sun and of objects' light over the face
    // cache: the camera and frame index of their last frame (none: the next frame
    // starts afresh). Their images are the targets' (FrameTargets::advanceHistories).
    std::optional<Camera> surfaceCamera_;
    // The sun when a moved sun last restarted the surface history (setLighting).
    std::optional<glm::vec3> historySun_;
    static constexpr float kObjectLightSunDegrees = 5.0f;
    uint32_t surfaceFrame_ = 0;
    // Objects: their poses now and at the last frame rendered (with its camera),
    // and their normal tables (bound to the composite in every world).
    const SceneObjects* objects_ = nullptr;
    std::vector<voxel::ObjectPose> poses_, lastPoses_;
    std::optional<Camera> lastCamera_;
    std::vector<const GpuScene*> objectScenes_;
    GpuObjectGrids objectGrids_;      // the objects' voxels for rays, as of objectGridsVersion_
    uint64_t objectGridsVersion_ = 0;
    // Temporal state: the camera and frame index the AO history's last output was
    // rendered with (none after a cut).
    std::optional<Camera> previousCamera_;
    uint32_t previousFrame_ = 0;
    HistoryBoxes invalidated_;  // edits since the last frame
    ChunkCulling culling_;
    CullingOptions cullingOptions_ = cullingOptions(voxel::Detail{});
    FramePlan plan_;       // what the frames do now
    FramePasses passes_;   // the passes plan_ runs
    // The two frames in flight: each frame takes the other slot than the last.
    std::array<std::unique_ptr<FrameSlot>, 2> slots_;
    uint32_t slotIndex_ = 1;
    FrameSlot& slot() const { return *slots_[slotIndex_]; }  // the frame's being recorded, or the last's
    VkSemaphore timeline_ = VK_NULL_HANDLE;
    uint64_t submitted_ = 0;  // the last value a submission signals
};

}  // namespace grotto
