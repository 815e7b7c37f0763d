// The game-facing engine (include/grotto/grotto.h) over a render session: the
// public plain types turned into the session's, and back.
#include "grotto/grotto.h"

#include "engine/ao_settings.h"
#include "engine/camera.h"
#include "engine/camera_path.h"
#include "engine/image_output.h"
#include "engine/session_setup.h"
#include "voxel/world_json.h"

#include <optional>

namespace grotto {

struct Engine::Impl {
    std::unique_ptr<vk::Context> ctx;
    std::unique_ptr<RenderSession> session;  // its renderer is made on the first frame, kept across settings changes
    std::vector<voxel::ObjectPose> poses;
    std::vector<bool> added;  // per object: added by the game (saved as a grid of its own)
    CameraDesc camera;
    AoDesc aoDesc;  // as set, for saveWorld
    uint32_t width = 0, height = 0, frame = 0;
    std::optional<Camera> last;  // the camera of the last frame rendered

    void requireWorld(const char* call) const {
        if (!session) throw Error(call, "no world is loaded", "call loadWorld() or setWorld() first");
    }
    void requireFrame(const char* call) const {
        if (!session || !last) throw Error(call, "no frame has been rendered", "call render() first");
    }
    void requireObject(const char* call, size_t object) const {
        if (object >= poses.size())
            throw Error(call, "object " + std::to_string(object) + " does not exist",
                        "the world has " + std::to_string(poses.size()) + " objects");
    }
    void setWorld(voxel::World world);
    // `sync`: submitted in flight after its waits; none: rendered and waited for.
    RenderedFrame render(const Camera& camera, const FrameSync* sync = nullptr);
};

namespace {

void requireSize(uint32_t width, uint32_t height) {
    if (width == 0 || height == 0 || width > 16384 || height > 16384)
        throw Error("resize", std::to_string(width) + "x" + std::to_string(height) + " is not an image size",
                    "accepted: 1 to 16384 pixels a side");
}

voxel::World worldFrom(const VoxelGrid& grid, const std::vector<Material>& palette, const char* call) {
    const glm::ivec3 s = grid.size;
    if (s.x < 1 || s.y < 1 || s.z < 1 || size_t(s.x) * size_t(s.y) * size_t(s.z) != grid.materials.size())
        throw Error(call, "the voxel grid's size does not match its " + std::to_string(grid.materials.size()) +
                              " material ids", "size.x * size.y * size.z ids, each axis at least 1");
    voxel::WorldDesc desc;
    desc.materials = palette;
    return voxel::World::fromDense(s, grid.materials.data(), grid.voxelSize, grid.origin, std::move(desc));
}

voxel::ObjectPose requirePose(const char* call, glm::dvec3 position, glm::dquat rotation) {
    const double length = glm::length(rotation);
    if (!std::isfinite(position.x + position.y + position.z) || !(length > 1e-9) || !std::isfinite(length))
        throw Error(call, "the position is not finite or the rotation is zero");
    return {.position = position, .rotation = rotation / length};
}

// Lighting checked as a world file's "lighting" block is, against the settings' ranges.
void requireLighting(const Lighting& lighting) {
    voxel::WorldDesc probe, checked;
    probe.lighting = lighting;
    const nlohmann::ordered_json block = voxel::worldFileJson(probe, {})["lighting"];
    voxel::applySettingsPatch(checked, {{"lighting", block}}, "setLighting", "lighting");
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

void Engine::loadWorld(const std::filesystem::path& file) { impl_->setWorld(voxel::World::load(file)); }

void Engine::setWorld(const VoxelGrid& voxels, const std::vector<Material>& palette) {
    impl_->setWorld(worldFrom(voxels, palette, "setWorld"));
}

void Engine::Impl::setWorld(voxel::World world) {
    // Settings first: a world whose AO block is bad is refused before anything changes.
    const AoOptions ao = aoOptionsFor(world.desc().ao, world.voxelSize(), world.desc().source.string());
    session.reset();  // it draws the old scene
    camera = world.camera("", double(width) / double(height));
    aoDesc = world.desc().ao;
    const voxel::Detail detail = world.desc().detail;
    // A game may move, add and remove any object: motion vectors for all.
    session = openSession(*ctx, std::move(world),
                          {.ao = ao, .detail = detail, .width = width, .height = height, .objectsMayMove = true},
                          "image size");
    readyFaceCache(*session, {.progressive = true});  // a game never waits for a bake: the GPU traces what comes into view
    poses = session->poses();
    added.assign(poses.size(), false);
    last.reset();
}

WorldBox Engine::bounds() const {
    impl_->requireWorld("bounds");
    const voxel::World& w = impl_->session->world();
    const IndexBox b = w.bounds();
    if (b.empty()) return {};
    return {w.origin() + glm::dvec3(b.min) * w.voxelSize(), w.origin() + glm::dvec3(b.max + 1) * w.voxelSize()};
}

int Engine::material(glm::ivec3 voxel) const {
    impl_->requireWorld("material");
    return impl_->session->world().material(voxel);
}

void Engine::saveWorld(const std::filesystem::path& file) const {
    const Impl& m = *impl_;
    m.requireWorld("saveWorld");
    const RenderSession& s = *m.session;
    voxel::WorldDesc settings = s.world().desc();
    settings.lighting = s.lighting();
    settings.ao = m.aoDesc;
    settings.objects = s.objects()->descs;
    std::filesystem::path stem = file;
    stem.replace_extension();
    for (size_t k = 0; k < settings.objects.size(); ++k) {
        voxel::ObjectDesc& o = settings.objects[k];
        o.keys = {{.position = m.poses[k].position, .rotation = m.poses[k].rotation}};
        if (!m.added[k]) continue;
        // A game's object has no file: its voxels go beside the world's.
        const auto saved = s.objectWorlds()[k].save(stem.string() + ".object-" + std::to_string(k) + ".vdb");
        o.gridFile = saved.grid;
        o.gridName.clear();
        o.rule = voxel::SolidRule::Int32;
    }
    s.world().save(file, settings);
}

EditResult Engine::edit(const Edit& edit) {
    impl_->requireWorld("edit");
    return impl_->session->apply(edit);
}

EditResult Engine::undo() {
    impl_->requireWorld("undo");
    return impl_->session->undo();
}

size_t Engine::addObject(const Object& object) {
    Impl& m = *impl_;
    m.requireWorld("addObject");
    const voxel::ObjectPose pose = requirePose("addObject", object.position, object.rotation);
    if (!std::isfinite(object.pivot.x + object.pivot.y + object.pivot.z))
        throw Error("addObject", "the pivot is not finite");
    // The object's voxels take the world's palette, as a world file's objects do.
    voxel::World world = worldFrom(object.voxels, m.session->world().desc().materials, "addObject");
    voxel::ObjectDesc desc{.name = object.name, .pivot = object.pivot,
                           .keys = {{.position = pose.position, .rotation = pose.rotation}}};
    m.session->addObject(std::move(world), std::move(desc));
    m.poses.push_back(m.session->poses().back());
    m.added.push_back(true);
    return m.poses.size() - 1;
}

void Engine::removeObject(size_t object) {
    Impl& m = *impl_;
    m.requireObject("removeObject", object);
    m.session->removeObject(object);
    m.poses.erase(m.poses.begin() + ptrdiff_t(object));
    m.added.erase(m.added.begin() + ptrdiff_t(object));
}

size_t Engine::objectCount() const { return impl_->poses.size(); }

void Engine::setTime(double seconds) {
    Impl& m = *impl_;
    if (!std::isfinite(seconds)) throw Error("setTime", "the time is not finite");
    if (!m.session) return;
    m.session->setTime(seconds);
    m.poses = m.session->poses();
}

void Engine::setObjectPose(size_t object, glm::dvec3 position, glm::dquat rotation) {
    Impl& m = *impl_;
    m.requireObject("setObjectPose", object);
    const voxel::ObjectPose pose = requirePose("setObjectPose", position, rotation);
    m.poses[object].position = pose.position;
    m.poses[object].rotation = pose.rotation;
}

std::optional<Hit> Engine::raycast(glm::dvec3 origin, glm::dvec3 direction, double maxDistance) const {
    Impl& m = *impl_;
    m.requireWorld("raycast");
    const double length = glm::length(direction);
    if (!std::isfinite(origin.x + origin.y + origin.z) || !(length > 0.0) || !std::isfinite(length) ||
        std::isnan(maxDistance))
        throw Error("raycast", "the origin is not finite or the direction is zero");
    direction /= length;
    m.session->setPoses(m.poses);  // as the game set them, rendered or not
    const auto h = m.session->raycast(origin, direction, std::min(maxDistance, 1e12));
    if (!h) return std::nullopt;
    Hit hit{.distance = h->ray.distance, .position = origin + direction * h->ray.distance, .voxel = h->ray.voxel,
            .normal = h->normal, .material = h->material};
    if (h->object >= 0) hit.object = size_t(h->object);
    return hit;
}

std::optional<Hit> Engine::pick(uint32_t x, uint32_t y, double maxDistance) const {
    const Impl& m = *impl_;
    if (x >= m.width || y >= m.height)
        throw Error("pick", "pixel (" + std::to_string(x) + ", " + std::to_string(y) + ") is outside the " +
                                std::to_string(m.width) + "x" + std::to_string(m.height) + " image");
    const Camera camera = makeCamera(m.camera, m.width, m.height);
    return raycast(camera.position, camera.rayDirection(x + 0.5, y + 0.5), maxDistance);
}

void Engine::setCamera(const CameraDesc& camera) { impl_->camera = camera; }
const CameraDesc& Engine::camera() const { return impl_->camera; }

void Engine::setLighting(const Lighting& lighting) {
    impl_->requireWorld("setLighting");
    requireLighting(lighting);
    impl_->session->setLighting(lighting);
}

Lighting Engine::lighting() const {
    impl_->requireWorld("lighting");
    return impl_->session->lighting();
}

void Engine::setAo(const AoDesc& desc) {
    Impl& m = *impl_;
    m.requireWorld("setAo");  // the default radius is in voxels of the world
    m.session->setAo(aoOptionsFor(desc, m.session->world().voxelSize(), "AO settings"));
    m.aoDesc = desc;
}

AoDesc Engine::ao() const { return impl_->aoDesc; }

void Engine::loadBake(const std::filesystem::path& file) {
    impl_->requireWorld("loadBake");
    impl_->session->loadFaceCache(file);
}

double Engine::lightBaked() const {
    const LiveFaceCache* cache = impl_->session ? impl_->session->scene().faceCache() : nullptr;
    return cache ? cache->lightBaked() : 1.0;
}

void Engine::waitForLight() {
    if (impl_->session) impl_->session->waitForLight();
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
    m.session->setPoses(m.poses);
    return m.render(makeCamera(m.camera, m.width, m.height));
}

RenderedFrame Engine::submit(const std::vector<FrameWait>& waits) {
    Impl& m = *impl_;
    m.requireWorld("submit");
    for (const FrameWait& w : waits)
        if (w.semaphore == VK_NULL_HANDLE) throw Error("submit", "a wait names no semaphore");
    m.session->setPoses(m.poses);
    const FrameSync sync{.waits = waits};
    return m.render(makeCamera(m.camera, m.width, m.height), &sync);
}

void Engine::playPath(const std::string& name) {
    Impl& m = *impl_;
    m.requireWorld("playPath");
    const auto& paths = m.session->world().desc().paths;
    const auto path = paths.find(name);
    if (path == paths.end()) {
        std::string names;
        for (const auto& [n, p] : paths) names += (names.empty() ? "" : ", ") + n;
        throw Error("playPath", "the world has no path named '" + name + "'",
                    names.empty() ? "it has no paths" : "its paths: " + names);
    }
    m.session->playPath(path->second, m.session->world().camera("", double(m.width) / double(m.height)));
}

double Engine::pathDuration() const {
    if (!impl_->session || !impl_->session->playing()) throw Error("pathDuration", "no path is playing");
    return impl_->session->path().duration();
}

RenderedFrame Engine::renderPath(double seconds) {
    Impl& m = *impl_;
    if (!m.session || !m.session->playing()) throw Error("renderPath", "no path is playing", "call playPath() first");
    if (!std::isfinite(seconds)) throw Error("renderPath", "the time is not finite");
    const RenderSession::PathFrame f = m.session->pathFrame(seconds, m.width, m.height);
    m.poses = m.session->poses();
    return m.render(f.camera);
}

RenderedFrame Engine::Impl::render(const Camera& camera, const FrameSync* sync) {
    Renderer& renderer = session->renderer();
    session->catchUp();  // the world's full light, once its thread has baked it; the face atlas, once traced
    renderer.setDisplayImage(true);  // what the game shows
    renderer.setNormalsImage(true);  // what it composites with
    // Consecutive indices: the history accumulates.
    const FrameStats stats = sync ? renderer.submit(camera, ++frame, *sync) : renderer.render(camera, ++frame);
    last = camera;
    auto image = [](const vk::Image& i, VkImageLayout layout) {
        return RenderedImage{.image = i.image, .format = i.format, .extent = i.extent, .layout = layout};
    };
    const VkImageLayout general = VK_IMAGE_LAYOUT_GENERAL;
    return {.color = image(renderer.colorImage(), general), .display = image(renderer.displayImage(), general),
            .normals = image(renderer.normalsImage(), general), .ao = image(renderer.aoImage(), general),
            .depth = image(renderer.depthImage(), renderer.layout(TargetId::Depth)),
            .quadsDrawn = stats.quadsDrawn, .wallMs = stats.wallMs, .timeline = renderer.timeline(),
            .timelineValue = stats.timelineValue};
}

Pixels Engine::readPixels() {
    Impl& m = *impl_;
    m.requireFrame("readPixels");
    FrameImages f = m.session->renderer().readback(*m.last, true);
    return {.width = f.width, .height = f.height, .rgba = std::move(f.color), .ao = std::move(f.ao),
            .depth = std::move(f.depth), .normals = std::move(f.normal)};
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
