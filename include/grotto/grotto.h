#pragma once
// Grotto for games: one header to load or build a voxel world, edit it, set the
// camera, lighting and AO, resize, render and get the result, either as host
// pixels or as Vulkan images on the game's own device. Grotto's Vulkan layer and
// OpenVDB stay behind it. Link Grotto::engine (find_package(Grotto)).
#include "common/error.h"
#include "engine/vk/external_device.h"
#include "voxel/edit.h"
#include "voxel/world.h"
#include "voxel/world_desc.h"

#include <glm/gtc/quaternion.hpp>
#include <vulkan/vulkan.h>

#include <cstdint>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

namespace grotto {

// A Vulkan device the game made and keeps: instance, physical device, device,
// queue and its family, with what Grotto needs of them (engine/vk/external_device.h).
using VulkanDevice = vk::ExternalDevice;

// An image Grotto rendered, owned by Grotto and valid until the next render(),
// resize(), setAo(), setLighting() or the engine's end.
struct RenderedImage {
    VkImage image = VK_NULL_HANDLE;
    VkFormat format = VK_FORMAT_UNDEFINED;
    VkExtent2D extent{0, 0};
    VkImageLayout layout = VK_IMAGE_LAYOUT_GENERAL;
};

// What render() hands back. Synchronisation: render() returns once the GPU has
// finished the frame (it waits on its own fence), so no semaphore is needed; the
// images are in VK_IMAGE_LAYOUT_GENERAL, last written by compute shaders. To read
// them in your own submission on the same queue, record first a barrier with
// srcStageMask COMPUTE_SHADER, srcAccessMask SHADER_WRITE (and the layout change
// you need, from GENERAL); give them back in GENERAL (any access) before calling
// render() again. Do not write to them.
struct RenderedFrame {
    RenderedImage color;    // scene-linear RGBA, R32G32B32A32_SFLOAT, full size: radiance x exposure, no tone
                            // map (values above 1 are normal), Rec. 709 primaries
    RenderedImage display;  // what to show: `color` through the world's tone map, display-linear in [0, 1],
                            // R16G16B16A16_SFLOAT, full size; blit or write it to an sRGB image, which encodes it
    RenderedImage ao;       // ambient visibility in the red channel (1 = open), R32G32B32A32_SFLOAT,
                            // at AO resolution: ceil(w/2) x ceil(h/2) by default; 1x1 with AO off
    uint64_t quadsDrawn = 0;
    double wallMs = 0.0;    // record + submit + wait
};

// A frame read back to host memory, row 0 on top.
struct Pixels {
    uint32_t width = 0, height = 0;
    std::vector<float> rgba;  // scene-linear, as RenderedFrame::color
    std::vector<float> ao;    // visibility per pixel at full size (1 without AO)
};

struct EngineOptions {
    uint32_t width = 1280, height = 720;
    bool validation = false;  // the Khronos validation layer (headless only; GROTTO_VALIDATION=1 too)
    std::string deviceName;   // headless: a substring of the device to use; empty = lavapipe, else the first
};

class Engine {
public:
    // Headless: Grotto makes a Vulkan instance and device of its own.
    explicit Engine(const EngineOptions& options = {});
    // On the game's device; Grotto never destroys it.
    Engine(const VulkanDevice& device, const EngineOptions& options = {});
    ~Engine();
    Engine(const Engine&) = delete;
    Engine& operator=(const Engine&) = delete;

    // The world: a world .json or .vdb, or one built in memory
    // (voxel::World::fromDense). Its lighting, AO settings and default camera
    // become the engine's (without cameras of its own: one framing its bounds in
    // the engine's image size). Throws grotto::Error (input) on bad input.
    void loadWorld(const std::filesystem::path& file);
    void setWorld(voxel::World world);
    const voxel::World& world() const;
    // Writes the world as edited with the engine's lighting and AO settings: FILE.json,
    // the world file (palette, lighting, AO, detail, cameras, paths, objects), and
    // FILE.vdb, its voxels; `file` names either. loadWorld(FILE.json) is the same world.
    void saveWorld(const std::filesystem::path& file) const;

    // Edits change the world between any two frames; only the chunks they touch
    // are re-meshed and re-uploaded, and temporal AO history near them restarts.
    voxel::EditResult edit(const voxel::Edit& edit);
    voxel::EditResult undo();

    // Objects (the world's "objects", or WorldDesc::objects of a world built in
    // memory) take the pose their keys give at `seconds`; setObjectPose moves one
    // (index in the world's order) as the game likes, until the next setTime.
    // Objects cast and receive AO; their motion feeds the temporal pass.
    void setTime(double seconds);
    void setObjectPose(size_t object, glm::dvec3 position, glm::dquat rotation = glm::dquat(1.0, 0.0, 0.0, 0.0));
    size_t objectCount() const;

    void setCamera(const voxel::CameraDesc& camera);
    void setLighting(const voxel::Lighting& lighting);
    void setAo(const voxel::AoDesc& ao);  // the world file's "ao" block; throws Error for bad values
    void resize(uint32_t width, uint32_t height);
    void cut();  // a camera cut: the next frame starts without temporal history

    // Renders a frame. Consecutive calls accumulate temporal AO.
    RenderedFrame render();
    // The last rendered frame, read back.
    Pixels readPixels();
    // Writes the last rendered frame as a PNG (tone-mapped, 8-bit sRGB: display-referred)
    // or an EXR (scene-linear colour, as `color`, with AOVs), atomically.
    void saveFrame(const std::filesystem::path& file);

    std::string deviceName() const;
    int validationMessages() const;  // headless with validation on; 0 otherwise

private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

}  // namespace grotto
