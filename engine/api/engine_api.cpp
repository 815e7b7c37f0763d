// The game-facing engine (include/grotto/grotto.h) over a render session.
#include "grotto/grotto.h"

#include "common/error.h"
#include "engine/ao_settings.h"
#include "engine/camera.h"
#include "engine/image_output.h"
#include "engine/session.h"

#include <cmath>
#include <optional>

namespace grotto {

struct Engine::Impl {
    std::unique_ptr<vk::Context> ctx;
    std::optional<RenderSession> session;  // its renderer is made on the first frame, kept across settings changes
    std::vector<voxel::ObjectPose> poses;
    voxel::CameraDesc camera;
    voxel::AoDesc aoDesc;  // as set, for saveWorld
    uint32_t width = 0, height = 0, frame = 0;
    std::optional<Camera> last;  // the camera of the last frame rendered

    void requireWorld(const char* call) const {
        if (!session) throw Error(call, "no world is loaded", "call loadWorld() or setWorld() first");
    }
    void requireFrame(const char* call) const {
        if (!session || !last) throw Error(call, "no frame has been rendered", "call render() first");
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
    impl_->session.reset();  // the renderer and the scene's buffers go before the device they were made on
}

void Engine::loadWorld(const std::filesystem::path& file) { setWorld(voxel::World::load(file)); }

void Engine::setWorld(voxel::World world) {
    Impl& m = *impl_;
    // Settings first: a world whose AO block is bad is refused before anything changes.
    const AoOptions ao = aoOptionsFor(world.desc().ao, world.voxelSize(), world.desc().source.string());
    m.session.reset();  // it draws the old scene
    m.camera = world.camera("", double(m.width) / double(m.height));
    m.aoDesc = world.desc().ao;
    const voxel::Detail detail = world.desc().detail;
    // A game may move any object (setObjectPose): motion vectors for all.
    m.session.emplace(*m.ctx, std::move(world), ao, detail, m.width, m.height, true);
    m.poses = m.session->poses();
    m.last.reset();
}

const voxel::World& Engine::world() const {
    impl_->requireWorld("world");
    return impl_->session->world();
}

void Engine::saveWorld(const std::filesystem::path& file) const {
    const Impl& m = *impl_;
    m.requireWorld("saveWorld");
    voxel::WorldDesc settings = m.session->world().desc();
    settings.lighting = m.session->lighting();
    settings.ao = m.aoDesc;
    m.session->world().save(file, settings);
}

voxel::EditResult Engine::edit(const voxel::Edit& edit) {
    Impl& m = *impl_;
    m.requireWorld("edit");
    return m.session->apply(edit);
}

voxel::EditResult Engine::undo() {
    Impl& m = *impl_;
    m.requireWorld("undo");
    return m.session->undo();
}

void Engine::setTime(double seconds) {
    Impl& m = *impl_;
    if (!std::isfinite(seconds)) throw Error("setTime", "the time is not finite");
    if (!m.session) return;
    m.session->setTime(seconds);
    m.poses = m.session->poses();
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
    impl_->requireWorld("setLighting");
    impl_->session->setLighting(lighting);
}

void Engine::setAo(const voxel::AoDesc& desc) {
    Impl& m = *impl_;
    m.requireWorld("setAo");  // the default radius is in voxels of the world
    m.session->setAo(aoOptionsFor(desc, m.session->world().voxelSize(), "AO settings"));
    m.aoDesc = desc;
}

void Engine::resize(uint32_t width, uint32_t height) {
    requireSize(width, height);
    impl_->width = width;
    impl_->height = height;
    if (impl_->session) impl_->session->resize(width, height);
}

void Engine::cut() {
    if (impl_->session) impl_->session->renderer().resetHistory();
}

RenderedFrame Engine::render() {
    Impl& m = *impl_;
    m.requireWorld("render");
    Renderer& renderer = m.session->renderer();
    renderer.setDisplayImage(true);  // what the game shows
    m.session->setPoses(m.poses);
    const Camera camera = makeCamera(m.camera, m.width, m.height);
    const FrameStats stats = renderer.render(camera, ++m.frame);  // consecutive indices: history accumulates
    m.last = camera;
    auto image = [](const vk::Image& i) {
        return RenderedImage{.image = i.image, .format = i.format, .extent = i.extent, .layout = VK_IMAGE_LAYOUT_GENERAL};
    };
    return {.color = image(renderer.colorImage()), .display = image(renderer.displayImage()),
            .ao = image(renderer.aoImage()), .quadsDrawn = stats.quadsDrawn, .wallMs = stats.wallMs};
}

Pixels Engine::readPixels() {
    Impl& m = *impl_;
    m.requireFrame("readPixels");
    FrameImages f = m.session->renderer().readback(*m.last, true);
    return {.width = f.width, .height = f.height, .rgba = std::move(f.color), .ao = std::move(f.ao)};
}

void Engine::saveFrame(const std::filesystem::path& file) {
    Impl& m = *impl_;
    m.requireFrame("saveFrame");
    const bool exr = file.extension() == ".exr";
    writeFrame(file, m.session->renderer().readback(*m.last, exr), *m.last, exr);
}

std::string Engine::deviceName() const { return impl_->ctx->deviceName(); }
int Engine::validationMessages() const { return impl_->ctx->validationMessages(); }

}  // namespace grotto
