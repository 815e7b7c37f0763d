#include "app/viewer/path_recorder.h"

#include "common/atomic_file.h"
#include "common/error.h"
#include "voxel/json_reader.h"


namespace grotto::viewer {

bool PathRecorder::add(double time, const voxel::CameraDesc& camera) {
    if (!keys_.empty() && time <= keys_.back().time) return false;
    keys_.push_back({time, camera});
    return true;
}

void PathRecorder::save(const std::filesystem::path& file) const {
    if (keys_.size() < 2)
        throw Error(file.string(), "a path needs at least two keys, " + std::to_string(keys_.size()) + " recorded",
                    "record a key (R) at each camera the path should pass through");
    auto vec = [](const glm::dvec3& v) { return voxel::json::array({v.x, v.y, v.z}); };
    voxel::json path = voxel::json::object();
    // The lens of the first key; a key whose fov differs says so itself.
    const voxel::CameraDesc& first = keys_.front().camera;
    path["fov"] = first.fovDegrees;
    path["near"] = first.nearPlane;
    path["far"] = first.farPlane;
    path["keys"] = voxel::json::array();
    for (const Key& k : keys_) {
        voxel::json key = {{"time", k.time}, {"position", vec(k.camera.position)}, {"target", vec(k.camera.target)}};
        if (k.camera.fovDegrees != first.fovDegrees) key["fov"] = k.camera.fovDegrees;
        path["keys"].push_back(key);
    }
    requireOutputPath(file);
    writeAtomically(file, path.dump(2) + "\n");
}

}  // namespace grotto::viewer
