#pragma once
// One world being rendered: the live world and its GPU copy, the world's objects,
// the renderer with its culling, and the camera path playing, if any. Every
// command that renders, the viewer and grotto::Engine drive one, so they all play
// a path alike: its camera, its objects' keys, its timed edits and its cuts.
#include "engine/renderer.h"
#include "engine/scene/live_scene.h"
#include "engine/scene/path_edits.h"
#include "engine/scene/scene_objects.h"
#include "voxel/reference_ao.h"

#include <filesystem>
#include <memory>
#include <optional>
#include <span>
#include <vector>

namespace grotto {

class CameraPath;

// What the renderer's frames are made with, held by the session only until the
// renderer is made (RenderSession::renderer) and then the renderer's alone.
struct FrameSettings {
    voxel::Lighting lighting;
    AoOptions ao;
    CullingOptions culling;
    uint32_t width = 0, height = 0;
    std::vector<voxel::ObjectPose> poses;  // the objects', one each
};

class RenderSession {
public:
    // Loads the world's objects and uploads the world and them. `detail`: the
    // levels of detail and occlusion culling the renderer draws with. With
    // `objectsMayMove`, every object gets motion vectors, whatever its keys say
    // (a game poses objects itself).
    RenderSession(vk::Context& ctx, voxel::World world, const AoOptions& ao, const voxel::Detail& detail,
                  uint32_t width, uint32_t height, bool objectsMayMove = false);
    ~RenderSession();
    RenderSession(const RenderSession&) = delete;
    RenderSession& operator=(const RenderSession&) = delete;

    LiveScene& scene() { return *scene_; }
    // A .vox world's estimated peak memory, the renderer's at this size included
    // (engine/scene/scene_memory.h), checked against its budget before the upload; else 0.
    uint64_t memoryEstimate() const { return scene_->memoryEstimate(); }
    const voxel::World& world() const { return scene_->world(); }
    // Made on first use (a command that renders with renderers of its own never
    // makes it). With --ao cache and no cache of the AO radius loaded, the world
    // is baked first (bakeFaceCache), as setAo does.
    Renderer& renderer();
    const SceneObjects* objects() const { return objects_.get(); }
    std::span<const voxel::World> objectWorlds() const { return objectWorlds_; }
    // Settings and size for the frames that follow: the renderer's once it is
    // made (its setters say what each restarts), held here until then.
    void setLighting(const voxel::Lighting& lighting);
    void setAo(const AoOptions& ao);
    void setCulling(const CullingOptions& culling);
    void resize(uint32_t width, uint32_t height);
    const voxel::Lighting& lighting() const { return renderer_ ? renderer_->lighting() : unmade_->lighting; }
    const AoOptions& ao() const { return renderer_ ? renderer_->ao() : unmade_->ao; }
    // --ao cache's light on the world's faces, before the first frame: a bake of
    // this world with the session's AO radius (`grotto bake`), refused with
    // grotto::Error (input) naming the file and field when it is not one; or baked
    // here on every core with grotto bake's defaults, under the session's lighting.
    void loadFaceCache(const std::filesystem::path& bake) { scene_->loadFaceCache(bake, ao().estimator.radius); }
    void bakeFaceCache() { scene_->bakeFaceCache(lightingBakeSettings(lighting(), ao().estimator.radius)); }
    // Or nothing traced yet: the renderer's GPU tracer converges the faces as they
    // come into view (engine/passes/face_cache_trace_pass.h). With `progressive`
    // set, a cache the session needs later (a new radius, cache chosen without
    // one) starts so too, instead of being baked on the CPU first.
    void startFaceCache() { scene_->progressiveFaceCache(lightingBakeSettings(lighting(), ao().estimator.radius)); }
    void setProgressiveFaceCache(bool progressive) { progressiveCache_ = progressive; }
    // Frames with no face in view left to trace: the last frame's tracer found none,
    // and the world's full light, if it was baking on its own thread, is taken
    // (true without the face cache).
    bool faceCacheConverged();
    // With full light and no bake, the world's light is baked on a thread of its
    // own (LiveFaceCache::progressive): taken here once it has finished, for the
    // frames that follow. Call between frames. True when it was taken.
    bool takeBakedLight() { return scene_->takeBakedLight(); }
    // Between frames, what the frames read brought up to date: that light, and the
    // face atlas as the GPU's tracer catches up after an edit, in view or not
    // (LiveFaceCache::catchUpAtlas). True when either changed.
    bool catchUp() {
        const bool light = takeBakedLight();
        return scene_->catchUpFaceAtlas() || light;
    }
    // Waits for that bake and takes it: for frames that must not depend on how
    // fast it ran (a viewer's script).
    void waitForLight();

    // The objects at their keys' poses `seconds` into the world's time, for the
    // frames that follow (at time 0 until then), or at poses of the caller's.
    void setTime(double seconds);
    void setPoses(std::vector<voxel::ObjectPose> poses);
    const std::vector<voxel::ObjectPose>& poses() const { return renderer_ ? renderer_->objectPoses() : unmade_->poses; }
    // The objects' worlds at those poses, for the reference to trace.
    std::vector<voxel::PosedWorld> posedObjects() const { return voxel::posedWorlds(objectWorlds_, poses()); }

    // Objects added and removed between frames (at most GROTTO_MAX_OBJECTS in all):
    // `world` holds the object's voxels; `desc` its name, pivot and keys (it stands
    // at its first key's pose until the next setTime). Indices above a removed
    // object's move down by one. Throws grotto::Error (input) past the limit or
    // for an index that does not exist.
    void addObject(voxel::World world, voxel::ObjectDesc desc);
    void removeObject(size_t index);
    // The first solid voxel along a ray (unit `direction`, world units), of the
    // world or of an object at its pose now; an object's hit is in its own voxels,
    // with `normal` turned by its pose.
    struct Hit {
        voxel::RayHit ray;
        glm::dvec3 normal{0.0};  // the outward normal of the face entered, world axes; 0 inside a voxel
        int material = 0;
        int object = -1;  // -1: the world's voxels
    };
    std::optional<Hit> raycast(glm::dvec3 origin, glm::dvec3 direction, double maxDistance) const;

    // An edit of the live world (or its undo); the renderer restarts its history
    // where it changed. Throws grotto::Error (input) for an edit the world refuses.
    voxel::EditResult apply(const voxel::Edit& edit);
    voxel::EditResult undo();

    // Plays `path` from its start: the path's edits are checked against the world
    // now (grotto::Error naming the path's file and field). `defaults`: the lens
    // of the world's default camera.
    void playPath(const voxel::CameraPathDesc& path, const voxel::CameraDesc& defaults);
    void stopPath();
    bool playing() const { return path_ != nullptr; }
    const CameraPath& path() const { return *path_; }
    // Moves the playing path to `time` seconds without rendering: the edits due by
    // then are applied (no history to restart yet), and the next frame starts afresh.
    void startPathAt(double time);
    // Are edits of the path due by `time` not applied yet? (A caller may keep the
    // world as it was before them.)
    bool pathEditsPending(double time) const { return edits_ && edits_->pending(time); }
    struct PathFrame {
        Camera camera;
        double time = 0.0;
        voxel::WorldBox edited;  // what the edits due by then changed (empty: nothing)
        bool cut = false;        // the path cut since the frame before: the history restarted
    };
    // The path at `time` seconds (after the time of the frame before): its camera,
    // the objects posed at its keys, the edits due applied (the history restarts
    // where they changed the world) and, after a cut, the history restarted.
    PathFrame pathFrame(double time, uint32_t width, uint32_t height);

private:
    void requireFaceCache(const AoOptions& ao);
    bool progressiveCache_ = false;

    vk::Context& ctx_;
    std::vector<voxel::World> objectWorlds_;
    std::unique_ptr<SceneObjects> objects_;
    std::unique_ptr<LiveScene> scene_;
    std::unique_ptr<Renderer> renderer_;
    std::optional<FrameSettings> unmade_;  // the renderer's settings while there is none: one owner at a time
    voxel::CameraPathDesc pathDesc_;
    std::unique_ptr<CameraPath> path_;
    std::unique_ptr<PathEdits> edits_;
    std::optional<double> lastPathTime_;  // the path's time at the frame before; unset: none yet
    bool objectsMayMove_;
};

}  // namespace grotto
