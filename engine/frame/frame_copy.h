#pragma once
// A frame's images in host-visible memory. The renderer records their copies into
// a command buffer of the frame (Renderer::render's own, or readback's); once that
// has completed, decode() turns them into FrameImages. Decoding reads host memory
// only, so it may run on another thread while the renderer goes on with the next
// frame: a caller reads back frame N as frame N + 1 renders, with no wait of its own.
#include "engine/camera.h"
#include "engine/frame/frame_images.h"
#include "engine/vk/resources.h"
#include "voxel/object_pose.h"

#include <glm/glm.hpp>

#include <optional>
#include <vector>

namespace grotto {

class FrameCopy {
public:
    // `aovs`: the G-buffer and AO images too, as Renderer::readback(camera, true).
    FrameCopy(vk::Context& ctx, bool aovs);
    ~FrameCopy();
    FrameCopy(const FrameCopy&) = delete;
    FrameCopy& operator=(const FrameCopy&) = delete;

    bool aovs() const { return aovs_; }
    // The copied frame's images, exactly as Renderer::readback returns them.
    FrameImages decode() const;

    // What the renderer records: each image into a buffer of its own (the largest
    // allocation stays one image's), and what decoding needs to know of the frame.
    enum Part { Color, Shadow, Depth, Surface, Motion, AoFull, Raw, Spatial, History, BentNormal, CacheLight, kParts };
    struct Layout {
        uint32_t width = 0, height = 0;
        VkExtent2D half{};   // the AO images' size
        uint32_t scale = 2;  // full size over AO size
        bool ao = false;
        bool chain = false;  // an AO chain's images (else, with AO, the face cache's full-res AO alone)
        uint32_t toneMap = GROTTO_TONE_MAP_FILMIC;  // FrameImages::toneMap
        std::optional<Camera> camera;
        std::vector<voxel::ObjectPose> poses;
        std::vector<glm::vec3> albedo;  // material k at [k - 1]
    };
    // Starts a frame's copy: no part copied yet.
    void begin(Layout layout);
    // The buffer for `part`, (re)made to hold at least `bytes`, which the frame copies.
    const vk::Buffer& reserve(Part part, VkDeviceSize bytes);

private:
    vk::Context& ctx_;
    bool aovs_;
    Layout layout_;
    vk::Buffer buffers_[kParts];
    VkDeviceSize copied_[kParts] = {};  // bytes the frame copied into each; 0: none
};

}  // namespace grotto
