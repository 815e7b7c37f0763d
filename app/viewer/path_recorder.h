#pragma once
// Camera keys recorded in the viewer, saved as a path file that `flythrough` and
// `stability` load as they load any other (docs/paths.md): one key per record,
// its time the viewer's play clock, positions and targets in full double
// precision so the path passes exactly through the recorded cameras.
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
    // Writes the path atomically; throws grotto::Error (input) with fewer than two keys.
    void save(const std::filesystem::path& file) const;

private:
    struct Key {
        double time;
        voxel::CameraDesc camera;
    };
    std::vector<Key> keys_;
};

}  // namespace grotto::viewer
