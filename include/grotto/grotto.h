#pragma once
// Grotto for games: load or build a voxel world, edit it, add and move objects,
// pick what a pixel sees, set the camera, lighting and AO, resize, render and get
// the result, as host pixels or as Vulkan images on the game's own device.
// Everything here is Grotto's public surface: this header and the few beside it
// (error.h, edit.h, settings.h, vulkan.h), which need only Vulkan's and GLM's
// headers. Link Grotto::engine (find_package(Grotto)).
//
// Threads: an Engine is used from one thread at a time; every call may block on
// the GPU. Engines on different devices are independent. On a game's device,
// render() submits to the game's queue: the game must not submit to that queue
// from another thread during the call.
#include "grotto/edit.h"
#include "grotto/error.h"
#include "grotto/settings.h"
#include "grotto/vulkan.h"

#include <glm/gtc/quaternion.hpp>
#include <glm/vec3.hpp>

#include <cmath>
#include <cstdint>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace grotto {

// A block of voxels made in memory: a material id per voxel, x fastest, then y,
// then z; 0 is empty, k is entry k of the palette (1..255).
struct VoxelGrid {
    glm::ivec3 size{0};
    std::vector<uint8_t> materials;  // size.x * size.y * size.z ids
    double voxelSize = 1.0;          // world units per voxel
    glm::dvec3 origin{0.0};          // world position of voxel (0, 0, 0)'s low corner
};

// A voxel model the game places and moves: its own voxels (their origin is the
// model's own space) with the world's palette, the point rotations turn about (in
// the model's space, world units) and its pose: where that point stands, and the
// rotation from the model's space to the world's.
struct Object {
    std::string name;
    VoxelGrid voxels;
    glm::dvec3 pivot{0.0};
    glm::dvec3 position{0.0};
    glm::dquat rotation{1.0, 0.0, 0.0, 0.0};
};

// What a ray or a pixel meets first: a solid voxel of the world or of an object.
struct Hit {
    double distance = 0.0;         // along the ray, world units
    glm::dvec3 position{0.0};      // the point hit, world units
    glm::ivec3 voxel{0};           // the voxel hit: the world's index, or the object's own
    glm::dvec3 normal{0.0};        // outward normal of the face entered, world axes (0: the ray started inside)
    int material = 0;              // its palette id
    std::optional<size_t> object;  // the object's index (objectCount()'s order); empty: the world's voxels
};

// What render() hands back: images on the Vulkan device Grotto renders with.
// Synchronisation: render() returns once the GPU has finished the frame (it waits
// on its own fence), so no semaphore is needed. To read an image in your own
// submission on the same queue, record first a barrier from the stage and access
// named below (and the layout change you need, from `layout`); give colour,
// display, normals and AO back in GENERAL before calling render() again (depth in
// any layout: the next frame discards it). Do not write to them.
struct RenderedFrame {
    // Written by compute shaders (srcStageMask COMPUTE_SHADER, srcAccessMask SHADER_WRITE), in GENERAL:
    RenderedImage color;    // scene-linear RGBA, R32G32B32A32_SFLOAT, full size: radiance x exposure, no tone
                            // map (values above 1 are normal), Rec. 709 primaries
    RenderedImage display;  // what to show: `color` through the world's tone map, display-linear in [0, 1],
                            // R16G16B16A16_SFLOAT, full size; blit or write it to an sRGB image, which encodes it
    RenderedImage normals;  // world-space unit normal of each pixel's face in xyz, w 1 on a surface and 0 on
                            // the sky; R16G16B16A16_SFLOAT, full size
    RenderedImage ao;       // ambient visibility in the red channel (1 = open), R32G32B32A32_SFLOAT,
                            // at AO resolution: ceil(w/2) x ceil(h/2) by default; 1x1 with AO off
    // Written by the G-buffer's depth test (LATE_FRAGMENT_TESTS, DEPTH_STENCIL_ATTACHMENT_WRITE), read after:
    RenderedImage depth;    // D32_SFLOAT, full size, reverse-Z with an infinite far plane: depth =
                            // nearPlane / (view distance along the camera's axis); 1 at the near plane, 0 = sky
    uint64_t quadsDrawn = 0;
    double wallMs = 0.0;    // record + submit (+ wait, render())
    // The frame has finished on the GPU once `timeline` (a timeline semaphore of
    // Grotto's) reaches `timelineValue`: already so when render() returns; after
    // submit(), wait for it before reading the images (docs/embedding.md).
    VkSemaphore timeline = VK_NULL_HANDLE;
    uint64_t timelineValue = 0;
};

// A frame read back to host memory, row 0 on top.
struct Pixels {
    uint32_t width = 0, height = 0;
    std::vector<float> rgba;  // scene-linear, as RenderedFrame::color
    std::vector<float> ao;       // visibility per pixel at full size (1 without AO)
    std::vector<float> depth;    // distance along the view axis, world units; +inf on the sky
    std::vector<float> normals;  // world-space normal, xyz per pixel (3 floats); 0 on the sky
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

    // The world: a world .json, .vdb (docs/worlds.md) or MagicaVoxel .vox
    // (docs/formats.md), or one built in memory with a palette (empty: Grotto's
    // default palette: stone, grass, wood, brick, ...).
    // Its lighting, AO settings and default camera become the engine's (without
    // cameras of its own: one framing its bounds in the engine's image size).
    // Throws grotto::Error (input) on bad input, leaving the engine as it was.
    void loadWorld(const std::filesystem::path& file);
    void setWorld(const VoxelGrid& voxels, const std::vector<Material>& palette = {});
    // The world's bounds, world units (voxel corners), as edited.
    WorldBox bounds() const;
    // The palette id of a voxel of the world (0: empty).
    int material(glm::ivec3 voxel) const;
    // Writes the world as edited with the engine's lighting and AO settings: FILE.json,
    // the world file (palette, lighting, AO, detail, cameras, paths, objects at
    // their poses now), and FILE.vdb, its voxels (an object added by the game, its
    // voxels as FILE.object-K.vdb); `file` names either. loadWorld(FILE.json) is
    // the same world.
    void saveWorld(const std::filesystem::path& file) const;

    // Edits change the world between any two frames; only the chunks they touch
    // are re-meshed and re-uploaded, and temporal AO history near them restarts.
    EditResult edit(const Edit& edit);
    EditResult undo();

    // Objects: the world file's, then those added, by index in that order (at most
    // 31 in all). Removing one moves the indices above it down by one. Objects
    // cast and receive AO; their motion feeds the temporal pass.
    size_t addObject(const Object& object);
    void removeObject(size_t object);
    size_t objectCount() const;
    // A world file's objects take the pose their keys give at `seconds` (added
    // objects the pose they were added with); setObjectPose moves one as the game
    // likes, until the next setTime.
    void setTime(double seconds);
    void setObjectPose(size_t object, glm::dvec3 position, glm::dquat rotation = glm::dquat(1.0, 0.0, 0.0, 0.0));

    // The first solid voxel, of the world or of an object at its pose now, along a
    // ray (`direction` need not be unit length) or through the centre of pixel
    // (x, y) of the camera set (row 0 on top), within `maxDistance` world units.
    std::optional<Hit> raycast(glm::dvec3 origin, glm::dvec3 direction, double maxDistance = INFINITY) const;
    std::optional<Hit> pick(uint32_t x, uint32_t y, double maxDistance = INFINITY) const;

    void setCamera(const CameraDesc& camera);
    const CameraDesc& camera() const;
    void setLighting(const Lighting& lighting);  // throws Error for values out of range
    Lighting lighting() const;
    void setAo(const AoDesc& ao);  // the world file's "ao" block; throws Error for bad values
    // The light cached on the world's faces for ao.method "cache" (docs/face-cache.md):
    // a bake of this world from `grotto bake`, at the AO radius set now. Throws
    // Error naming the file and the field when it is not this world's bake or
    // not these settings'. Without one, "cache" starts with nothing traced and
    // the GPU traces the faces as they come into view, within ao.cache_rays a frame.
    // With "cache" the AO lives on the faces: readPixels() has it per pixel, and
    // RenderedFrame::ao is a 1x1 placeholder.
    void loadBake(const std::filesystem::path& file);
    // With lighting.ambient.from "full" and no bake loaded, the GPU traces the
    // sky's light alone: the world's full light (lamps, bounces) is baked on a
    // thread of the engine's meanwhile, and the first render() after it has
    // finished takes it. How far it is, 0 to 1 (1 when there is none to wait for),
    // and a wait for it, for frames that must have it (a test, a capture).
    double lightBaked() const;
    void waitForLight();
    AoDesc ao() const;
    void resize(uint32_t width, uint32_t height);
    void cut();  // a camera cut: the next frame starts without temporal history

    // Renders a frame and waits for it. Consecutive calls accumulate temporal AO.
    RenderedFrame render();
    // The same frame with two frames in flight, for a game's device: recorded and
    // submitted in one submission after the game's `waits`, returning without
    // waiting for the GPU (it waits on the CPU only for the frame two before, whose
    // resources it reuses). The frame has finished when `timeline` reaches
    // `timelineValue`. The images are single: submit your reads of this frame's
    // images to the queue (waiting for that value) before the next submit() or
    // render(). readPixels() and saveFrame() wait for the frame themselves.
    RenderedFrame submit(const std::vector<FrameWait>& waits = {});
    // A camera path of the world file (docs/paths.md), by name: renderPath(seconds)
    // renders the frame `seconds` into it, as `grotto flythrough` does: the path's
    // camera, its objects at their keys, its edits due by then applied and its cuts
    // taken. Times must increase from one call to the next; playPath starts over.
    void playPath(const std::string& name);
    double pathDuration() const;  // seconds, of the path playing
    RenderedFrame renderPath(double seconds);
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
