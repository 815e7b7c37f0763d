#include "engine/session.h"

#include "engine/camera_path.h"
#include "engine/frame/render_memory.h"
#include "shaders/shared/face_trace.h"
#include "voxel/object_worlds.h"

namespace grotto {

RenderSession::RenderSession(vk::Context& ctx, voxel::World world, const AoOptions& ao, const voxel::Detail& detail,
                             uint32_t width, uint32_t height, bool objectsMayMove)
    : ctx_(ctx), objectWorlds_(voxel::loadObjectWorlds(world.desc())),
      unmade_(FrameSettings{.lighting = world.desc().lighting, .ao = ao, .culling = cullingOptions(detail),
                            .width = width, .height = height}),
      objectsMayMove_(objectsMayMove) {
    // Objects that may move may also come and go: the renderer draws a list, empty or not.
    if (!objectWorlds_.empty() || objectsMayMove) objects_ = uploadObjects(ctx, objectWorlds_, world.desc());
    if (objectsMayMove) objects_->moving = true;
    // The estimate counts the first frame as from the world's own camera.
    const SceneFrames frames{.rendererBytes = rendererHostBytes(ctx, planWorldFrame(world.desc(), width, height, ao)),
                             .firstView = worldCamera(world, "", width, height),
                             .lodBias = detail.lodBias};
    scene_ = std::make_unique<LiveScene>(ctx, std::move(world), frames);
    setTime(0.0);
}

// --ao cache without a cache of the session's radius, or without the full light
// the lighting asks for: baked here first, or left to the GPU's tracer (and with
// full light, a thread of its own). A full-light cache serves the sky's light too.
void RenderSession::requireFaceCache(const AoOptions& ao) {
    const LiveFaceCache* cache = scene_->faceCache();
    const bool full = lighting().ambientFrom == voxel::AmbientSource::Full;
    if (!faceCached(ao) ||
        (cache && cache->settings().radius == double(ao.estimator.radius) && (cache->settings().fullLight || !full)))
        return;
    if (progressiveCache_) startFaceCache();
    else bakeFaceCache();
}

void RenderSession::waitForLight() {
    if (LiveFaceCache* cache = scene_->faceCache()) cache->waitForLight();
    takeBakedLight();
}

bool RenderSession::faceCacheConverged() {
    if (!renderer_ || !renderer_->plan().faceCache) return true;
    takeBakedLight();
    if (scene_->faceCache()->lightPending()) return false;
    renderer_->finishFrames();
    const std::vector<uint32_t> header = scene_->gpu().faceCache()->lastHeader();
    // Neither the frame's tracer nor its composite (asking for the next) found one.
    return header[GROTTO_FACE_ASKED] + header[GROTTO_FACE_QUEUE_EMPTY] + header[GROTTO_FACE_QUEUE_PARTIAL] == 0;
}

Renderer& RenderSession::renderer() {
    if (!renderer_) {
        const FrameSettings& s = *unmade_;
        requireFaceCache(s.ao);
        auto made = std::make_unique<Renderer>(ctx_, scene_->gpu(), s.lighting, s.ao, s.width, s.height, objects_.get());
        made->setCulling(s.culling);
        if (objects_) made->setObjectPoses(s.poses);
        renderer_ = std::move(made);
        unmade_.reset();  // the renderer's from now on
    }
    return *renderer_;
}

// The renderer draws the scenes: it goes first, the scenes before the device.
RenderSession::~RenderSession() {
    renderer_.reset();
    scene_.reset();
    objects_.reset();
}

void RenderSession::setLighting(const voxel::Lighting& lighting) {
    if (!renderer_) {
        unmade_->lighting = lighting;
        return;
    }
    renderer_->setLighting(lighting);
    requireFaceCache(renderer_->ao());  // full light asked of a cache without it
}

void RenderSession::setAo(const AoOptions& ao) {
    if (!renderer_) {
        unmade_->ao = ao;
        return;
    }
    requireFaceCache(ao);
    renderer_->setAo(ao);
}

void RenderSession::setCulling(const CullingOptions& culling) {
    if (renderer_) renderer_->setCulling(culling);
    else unmade_->culling = culling;
}

void RenderSession::resize(uint32_t width, uint32_t height) {
    if (renderer_) {
        renderer_->resize(width, height);
        return;
    }
    unmade_->width = width;
    unmade_->height = height;
}

void RenderSession::setTime(double seconds) {
    if (objects_) setPoses(objects_->poses(seconds));
}

void RenderSession::setPoses(std::vector<voxel::ObjectPose> poses) {
    if (!renderer_) unmade_->poses = std::move(poses);
    else if (objects_) renderer_->setObjectPoses(poses);
}

voxel::EditResult RenderSession::apply(const voxel::Edit& edit) {
    const voxel::EditResult r = scene_->apply(edit);
    if (renderer_ && !r.voxels.empty()) renderer_->invalidateHistory(r.box);
    return r;
}

voxel::EditResult RenderSession::undo() {
    const voxel::EditResult r = scene_->undo();
    if (renderer_ && !r.voxels.empty()) renderer_->invalidateHistory(r.box);
    return r;
}

void RenderSession::playPath(const voxel::CameraPathDesc& path, const voxel::CameraDesc& defaults) {
    stopPath();
    pathDesc_ = path;  // PathEdits keeps a reference to it
    edits_ = std::make_unique<PathEdits>(pathDesc_, scene_->world());
    path_ = std::make_unique<CameraPath>(pathDesc_, defaults);
}

void RenderSession::stopPath() {
    path_.reset();
    edits_.reset();
    lastPathTime_.reset();
}

void RenderSession::startPathAt(double time) {
    edits_->applyUpTo(time, *scene_);
    lastPathTime_.reset();
}

RenderSession::PathFrame RenderSession::pathFrame(double time, uint32_t width, uint32_t height) {
    PathFrame f{.camera = path_->camera(time, width, height), .time = time};
    f.cut = lastPathTime_ && path_->cutBetween(*lastPathTime_, time);
    if (f.cut) renderer().resetHistory();
    f.edited = edits_->applyUpTo(time, *scene_, &renderer());
    if (!pathDesc_.day.empty()) {  // the path's hour: the day's sun and sky then
        voxel::Lighting l = lighting();
        l.sunFrom = voxel::SunSource::Day, l.timeOfDay = float(voxel::hourAt(pathDesc_.day, time));
        setLighting(l);
    }
    setTime(time);
    lastPathTime_ = time;
    return f;
}

}  // namespace grotto
