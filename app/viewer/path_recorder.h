#pragma once
// Camera keys and edits recorded in the viewer, saved as a path file that
// `flythrough` and `stability` load as they load any other (docs/paths.md): one
// key per record, its time the viewer's play clock, positions and targets in full
// double precision so the path passes exactly through the recorded cameras; the
// edits made while recording as its "edits" track, at the times they were made.
#include "voxel/camera_path_desc.h"
#include "voxel/world_desc.h"

#include <filesystem>
#include <vector>

namespace grotto::viewer {

class PathRecorder {
public:
    // A key at `time` seconds (play clock). Times must increase: a key at or
    // before the last is dropped (returns false).
    bool add(double time, const voxel::CameraDesc& camera);
    size_t size() const { return keys_.size(); }
    // An edit made at `time` seconds (play clock, from the first key), and the
    // undo of the last one recorded.
    void addEdit(double time, const voxel::Edit& edit);
    void dropLastEdit();
    size_t edits() const { return edits_.size(); }
    // The recording as a path: the lens of the first key; a key whose fov differs says so itself.
    voxel::CameraPathDesc path() const;
    // Writes the path atomically; throws grotto::Error (input) with fewer than two keys.
    void save(const std::filesystem::path& file) const;

private:
    struct Key {
        double time;
        voxel::CameraDesc camera;
    };
    std::vector<Key> keys_;
    std::vector<voxel::TimedEdit> edits_;
};

}  // namespace grotto::viewer
