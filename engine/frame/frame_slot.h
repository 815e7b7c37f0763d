#pragma once
// What each of the two frames in flight owns alone (Renderer::submit): everything
// the CPU writes or reads while the other frame may still run on the GPU. The
// render targets are not here: frames on one queue use them one after the other,
// ordered by barriers. A slot is reused only once the frame that last used it has
// finished (its timeline value reached).
#include "engine/passes/hiz_pass.h"
#include "engine/vk/resources.h"
#include "engine/vk/timestamps.h"
#include "voxel/object_pose.h"

#include <glm/glm.hpp>

#include <cstdint>
#include <vector>

namespace grotto {

struct FrameSlot {
    explicit FrameSlot(vk::Context& ctx);  // throws as the buffers it makes
    ~FrameSlot();
    FrameSlot(const FrameSlot&) = delete;
    FrameSlot& operator=(const FrameSlot&) = delete;

    vk::Context& ctx;
    VkCommandBuffer cmd = VK_NULL_HANDLE;
    // Written by the host as the frame is recorded; bound by push descriptors.
    vk::Buffer frame, aoConstants, temporalConstants, traceConstants, objectUniforms;
    vk::Buffer staging;  // the scene's staged uploads this frame copies (GpuScene::recordUploads)
    vk::Timestamps timestamps;
    bool timesUnread = false;  // its last frame's pass times have not been handed out yet
    // The images each timed pass declares, in bytes (pass_traffic.h), by its timestamp's name.
    std::vector<std::pair<std::string, uint64_t>> passBytes;
    // The depth tiles the frame wrote for occlusion culling, and what they show:
    // the camera, the scene (GpuScene::updates) and the objects' poses as they were.
    HizReadback hiz;
    bool hizWritten = false;
    glm::dmat4 hizViewProj{0.0};
    glm::dvec3 hizPosition{0.0};
    uint64_t hizSceneUpdates = 0;
    std::vector<voxel::ObjectPose> hizPoses;
    uint64_t done = 0;  // the timeline value reached when its last frame has finished (0: none yet)

private:
    void release();
};

}  // namespace grotto
