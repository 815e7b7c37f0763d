// The game-facing engine (include/grotto/grotto.h) over the live scene and the renderer.
#include "grotto/grotto.h"

#include "common/error.h"
#include "engine/ao_settings.h"
#include "engine/camera.h"
#include "engine/image_output.h"
#include "engine/scene/live_scene.h"
#include "engine/renderer.h"
#include "engine/scene/scene_objects.h"
#include "voxel/object_worlds.h"

#include <cmath>
#include <optional>

namespace grotto {

struct Engine::Impl {
    std::unique_ptr<vk::Context> ctx;
    std::optional<LiveScene> scene;
    std::vector<voxel::World> objectWorlds;
    std::unique_ptr<SceneObjects> objects;
    std::vector<voxel::ObjectPose> poses;
    std::unique_ptr<Renderer> renderer;  // made on the first frame, kept across settings changes
    voxel::CameraDesc camera;
    voxel::Lighting lighting;
    voxel::Detail detail;  // levels of detail and occlusion culling, from the world file
    voxel::AoDesc aoDesc;  // as set, for saveWorld
    AoOptions ao;
    uint32_t width = 0, height = 0, frame = 0;
    std::optional<Camera> last;  // the camera of the last frame rendered

    void requireWorld(const char* call) const {
        if (!scene) throw Error(call, "no world is loaded", "call loadWorld() or setWorld() first");
    }
};

namespace {

void requireSize(uint32_t width, uint32_t height) {
    if (width == 0 || height == 0 || width > 16384 || height > 16384)
        throw Error("resize", std::to_string(width) + "x" + std::to_string(height) + " is not an image size",
                    "accepted: 1 to 16384 pixels a side");
}

}  // namespace

Engine::Engine(const EngineOptions& options) : impl_(std::make_unique<Impl>()) {
    requireSize(options.width, options.height);
    impl_->ctx = std::make_unique<vk::Context>(
        vk::ContextOptions{.validation = options.validation, .deviceName = options.deviceName});
    impl_->width = options.width;
    impl_->height = options.height;
}

Engine::Engine(const VulkanDevice& device, const EngineOptions& options) : impl_(std::make_unique<Impl>()) {
    requireSize(options.width, options.height);
    impl_->ctx = std::make_unique<vk::Context>(device);
    impl_->width = options.width;
    impl_->height = options.height;
}

Engine::~Engine() {
    // The renderer and the scene's buffers go before the device they were made on.
    impl_->renderer.reset();
    impl_->objects.reset();
    impl_->scene.reset();
}

void Engine::loadWorld(const std::filesystem::path& file) { setWorld(voxel::World::load(file)); }

void Engine::setWorld(voxel::World world) {
    Impl& m = *impl_;
    // Settings first: a world whose AO block is bad is refused before anything changes.
    AoOptions ao = aoOptionsFor(world.desc().ao, world.voxelSize(), world.desc().source.string());
    std::vector<voxel::World> objectWorlds = voxel::loadObjectWorlds(world.desc());
    m.renderer.reset();  // it draws the old scene
    m.objects.reset();
    m.scene.reset();
    m.objectWorlds = std::move(objectWorlds);
    if (!m.objectWorlds.empty()) {
        m.objects = uploadObjects(*m.ctx, m.objectWorlds, world.desc());
        m.objects->moving = true;  // a game may move any object (setObjectPose): motion vectors for all
        m.poses = m.objects->poses(0.0);
    }
    m.camera = world.camera("", double(m.width) / double(m.height));
    m.lighting = world.desc().lighting;
    m.detail = world.desc().detail;
    m.aoDesc = world.desc().ao;
    m.ao = std::move(ao);
    m.scene.emplace(*m.ctx, std::move(world));
    m.last.reset();
}

const voxel::World& Engine::world() const {
    impl_->requireWorld("world");
    return impl_->scene->world();
}

void Engine::saveWorld(const std::filesystem::path& file) const {
    const Impl& m = *impl_;
    m.requireWorld("saveWorld");
    voxel::WorldDesc settings = m.scene->world().desc();
    settings.lighting = m.lighting;
    settings.ao = m.aoDesc;
    m.scene->world().save(file, settings);
}

voxel::EditResult Engine::edit(const voxel::Edit& edit) {
    Impl& m = *impl_;
    m.requireWorld("edit");
    const voxel::EditResult r = m.scene->apply(edit);
    if (m.renderer && !r.voxels.empty()) m.renderer->invalidateHistory(r.box);
    return r;
}

voxel::EditResult Engine::undo() {
    Impl& m = *impl_;
    m.requireWorld("undo");
    const voxel::EditResult r = m.scene->undo();
    if (m.renderer && !r.voxels.empty()) m.renderer->invalidateHistory(r.box);
    return r;
}

void Engine::setTime(double seconds) {
    Impl& m = *impl_;
    if (!std::isfinite(seconds)) throw Error("setTime", "the time is not finite");
    if (m.objects) m.poses = m.objects->poses(seconds);
}

void Engine::setObjectPose(size_t object, glm::dvec3 position, glm::dquat rotation) {
    Impl& m = *impl_;
    if (object >= m.poses.size())
        throw Error("setObjectPose", "object " + std::to_string(object) + " does not exist",
                    "the world has " + std::to_string(m.poses.size()) + " objects");
    const double length = glm::length(rotation);
    if (!std::isfinite(position.x + position.y + position.z) || !(length > 1e-9) || !std::isfinite(length))
        throw Error("setObjectPose", "the position is not finite or the rotation is zero");
    m.poses[object].position = position;
    m.poses[object].rotation = rotation / length;
}

size_t Engine::objectCount() const { return impl_->poses.size(); }

void Engine::setCamera(const voxel::CameraDesc& camera) { impl_->camera = camera; }

void Engine::setLighting(const voxel::Lighting& lighting) {
    impl_->lighting = lighting;
    if (impl_->renderer) impl_->renderer->setLighting(lighting);
}

void Engine::setAo(const voxel::AoDesc& desc) {
    Impl& m = *impl_;
    m.requireWorld("setAo");  // the default radius is in voxels of the world
    m.ao = aoOptionsFor(desc, m.scene->world().voxelSize(), "AO settings");
    m.aoDesc = desc;
    if (m.renderer) m.renderer->setAo(m.ao);
}

void Engine::resize(uint32_t width, uint32_t height) {
    requireSize(width, height);
    impl_->width = width;
    impl_->height = height;
    if (impl_->renderer) impl_->renderer->resize(width, height);
}

void Engine::cut() {
    if (impl_->renderer) impl_->renderer->resetHistory();
}

RenderedFrame Engine::render() {
    Impl& m = *impl_;
    m.requireWorld("render");
    if (!m.renderer)
        m.renderer =
            std::make_unique<Renderer>(*m.ctx, m.scene->gpu(), m.lighting, m.ao, m.width, m.height, m.objects.get());
    m.renderer->setDisplayImage(true);  // what the game shows
    m.renderer->setCulling(cullingOptions(m.detail));
    if (m.objects) m.renderer->setObjectPoses(m.poses);
    const Camera camera = makeCamera(m.camera, m.width, m.height);
    const FrameStats stats = m.renderer->render(camera, ++m.frame);  // consecutive indices: history accumulates
    m.last = camera;
    auto image = [](const vk::Image& i) {
        return RenderedImage{.image = i.image, .format = i.format, .extent = i.extent, .layout = VK_IMAGE_LAYOUT_GENERAL};
    };
    return {.color = image(m.renderer->colorImage()), .display = image(m.renderer->displayImage()),
            .ao = image(m.renderer->aoImage()), .quadsDrawn = stats.quadsDrawn, .wallMs = stats.wallMs};
}

Pixels Engine::readPixels() {
    Impl& m = *impl_;
    if (!m.renderer || !m.last) throw Error("readPixels", "no frame has been rendered", "call render() first");
    FrameImages f = m.renderer->readback(*m.last, true);
    return {.width = f.width, .height = f.height, .rgba = std::move(f.color), .ao = std::move(f.ao)};
}

void Engine::saveFrame(const std::filesystem::path& file) {
    Impl& m = *impl_;
    if (!m.renderer || !m.last) throw Error("saveFrame", "no frame has been rendered", "call render() first");
    const bool exr = file.extension() == ".exr";
    writeFrame(file, m.renderer->readback(*m.last, exr), *m.last, exr);
}

std::string Engine::deviceName() const { return impl_->ctx->deviceName(); }
int Engine::validationMessages() const { return impl_->ctx->validationMessages(); }

}  // namespace grotto
