#include "app/viewer/path_recorder.h"

#include "common/atomic_file.h"
#include "grotto/error.h"
#include "voxel/world_json.h"

namespace grotto::viewer {

bool PathRecorder::add(double time, const voxel::CameraDesc& camera) {
    if (!keys_.empty() && time <= keys_.back().time) return false;
    keys_.push_back({time, camera});
    return true;
}

void PathRecorder::addEdit(double time, const voxel::Edit& edit) {
    edits_.push_back({.time = time, .edit = edit, .field = "edits[" + std::to_string(edits_.size()) + "]"});
}

void PathRecorder::dropLastEdit() {
    if (!edits_.empty()) edits_.pop_back();
}

voxel::CameraPathDesc PathRecorder::path() const {
    voxel::CameraPathDesc p;
    const voxel::CameraDesc& first = keys_.front().camera;
    p.fovDegrees = first.fovDegrees;
    p.nearPlane = first.nearPlane;
    p.farPlane = first.farPlane;
    for (const Key& k : keys_) {
        voxel::PathKey key{.time = k.time, .position = k.camera.position, .target = k.camera.target};
        if (k.camera.fovDegrees != first.fovDegrees) key.fovDegrees = k.camera.fovDegrees;
        p.keys.push_back(key);
    }
    p.edits = edits_;
    return p;
}

void PathRecorder::save(const std::filesystem::path& file) const {
    if (keys_.size() < 2)
        throw Error(file.string(), "a path needs at least two keys, " + std::to_string(keys_.size()) + " recorded",
                    "record a key (R) at each camera the path should pass through");
    requireOutputPath(file);
    writeAtomically(file, voxel::cameraPathJson(path()).dump(2) + "\n");
}

}  // namespace grotto::viewer
