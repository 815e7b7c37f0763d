#pragma once
// G-buffer pass. Reads: the scene's vertices, frame uniforms.
// Writes: depth (D32, reverse-Z) and a 16-bit surface id that encodes the normal
// (one of six axes) and the material (albedo from the palette). No history.
// Draws the quad runs it is given (engine/frame/chunk_culling.h decides them: levels of
// detail, frustum, faces turned away, occlusion), clearing the targets first or
// drawing over what an earlier call drew.
// With objects: each object's chunks after the world's, through its pose (object
// index in the surface id); where objects move, every chunk is drawn with this
// frame's and the last frame's transforms and a motion target is written too.
#include "engine/camera.h"
#include "engine/frame/chunk_culling.h"
#include "engine/frame/frame_plan.h"
#include "engine/frame/pass_decl.h"
#include "engine/scene/scene.h"
#include "voxel/object_pose.h"

#include <span>

#include <tuple>

namespace grotto {

inline constexpr VkFormat kSurfaceFormat = VK_FORMAT_R16_UINT;

struct GBufferTargets {
    vk::Image depth;
    vk::Image surface;  // R16_UINT, see packSurface in shaders/shared/quad.h
    vk::Image motion;   // RGBA32F where objects move (else none): previous pixel - current, previous view depth
    vk::Image atlasRecord;  // RG32UI with the face cache (a placeholder without): the pixel's quad's atlas record
};

inline constexpr VkFormat kMotionFormat = VK_FORMAT_R32G32B32A32_SFLOAT;
inline constexpr VkFormat kAtlasRecordFormat = VK_FORMAT_R32G32_UINT;

// What the pass needs to draw a scene's objects: their meshes and poses, and for
// motion the previous frame's camera and poses (the current ones where none).
struct GBufferObjects {
    std::span<const GpuScene* const> scenes;
    std::span<const voxel::ObjectPose> poses, previousPoses;
    const Camera* previousCamera = nullptr;
};

enum class GBufferMode {
    World,    // the world alone: today's pipeline
    Objects,  // objects that stand still: one more pipeline for them, no motion
    Motion,   // objects that move: every chunk through the motion pipeline
};

class GBufferPass {
public:
    // `atlas`: the world's quads write their face atlas records too (FramePlan::faceAtlas; never with Motion).
    explicit GBufferPass(vk::Context& ctx, GBufferMode mode = GBufferMode::World, bool atlas = false);
    static bool runs(const FramePlan&) { return true; }
    static auto key(const FramePlan& plan) {
        return std::tuple(plan.motion ? GBufferMode::Motion : plan.objects ? GBufferMode::Objects : GBufferMode::World,
                          plan.faceAtlas && !plan.motion);
    }
    ~GBufferPass();

    // Draws `draws` of the scene, then the objects when `drawObjects`, clearing
    // the targets first when `clear`. `objects` also gives the previous camera the
    // motion target needs. Returns the number of quads drawn.
    // Draws into depth and surface (and motion where objects move) as attachments.
    PassDecl declare() const;
    uint64_t record(VkCommandBuffer cmd, const GBufferTargets& targets, const GpuScene& scene,
                    const vk::Buffer& frame, const Camera& camera, std::span<const QuadDraw> draws, bool clear,
                    const GBufferObjects* objects = nullptr, bool drawObjects = true);

private:
    void release();  // handles not made yet are null, which Vulkan ignores

    vk::Context& ctx_;
    VkDescriptorSetLayout setLayout_ = VK_NULL_HANDLE;
    VkPipelineLayout layout_ = VK_NULL_HANDLE;
    VkPipeline pipeline_ = VK_NULL_HANDLE;
    GBufferMode mode_;
    bool atlas_;
    VkDescriptorSetLayout objectSetLayout_ = VK_NULL_HANDLE;  // the frame, seen by the fragment stage too
    VkPipelineLayout objectLayout_ = VK_NULL_HANDLE;
    VkPipeline objectPipeline_ = VK_NULL_HANDLE;  // Objects: objects only; Motion: every chunk
};

}  // namespace grotto
