#include "engine/scene/path_edits.h"

#include "grotto/error.h"
#include "engine/renderer.h"

namespace grotto {

namespace {

// An error of the world's about an edit, as one about the path's field.
Error inPath(const voxel::CameraPathDesc& path, const voxel::TimedEdit& e, const Error& error) {
    return Error(path.source.string(), "field '" + e.field + "': " + error.problem(), error.hint(), error.kind());
}

}  // namespace

void checkPathEdits(const voxel::CameraPathDesc& path, const voxel::World& world) {
    for (const voxel::TimedEdit& e : path.edits) {
        try {
            world.check(e.edit);
        } catch (const Error& error) {
            throw inPath(path, e, error);
        }
    }
}

PathEdits::PathEdits(const voxel::CameraPathDesc& path, const voxel::World& world) : path_(path) {
    checkPathEdits(path, world);
}

voxel::WorldBox PathEdits::applyUpTo(double time, LiveScene& scene, Renderer* renderer) {
    voxel::WorldBox changed;
    for (; next_ < path_.edits.size() && path_.edits[next_].time <= time; ++next_) {
        const voxel::TimedEdit& e = path_.edits[next_];
        try {
            changed = changed.merged(scene.apply(e.edit).box);
        } catch (const Error& error) {
            throw inPath(path_, e, error);
        }
    }
    if (renderer && !changed.empty()) renderer->invalidateHistory(changed);
    return changed;
}

}  // namespace grotto
