#pragma once
// Replays a camera path's "edits" track: before each frame, every edit whose time
// has come is applied to the live scene, and the renderer is told where the world
// changed so temporal history there restarts.
#include "engine/scene/live_scene.h"
#include "voxel/camera_path_desc.h"

#include <vector>

namespace grotto {

class Renderer;

// Refuses (grotto::Error naming the path's file and the edit's field) any edit
// of the path that the world would refuse when its time came: out of range, not
// in the palette, past the memory budget. Commands call it as soon as they have
// the path and the world, before anything is rendered or written.
void checkPathEdits(const voxel::CameraPathDesc& path, const voxel::World& world);

class PathEdits {
public:
    // Checks every edit first (checkPathEdits).
    PathEdits(const voxel::CameraPathDesc& path, const voxel::World& world);

    // Applies the edits due by `time` not applied yet, in order; returns the union
    // of what they changed (empty when nothing did). With a renderer, its history
    // is restarted within the AO radius of that box. An edit the world refuses
    // throws grotto::Error naming the path's file and the edit's field.
    voxel::WorldBox applyUpTo(double time, LiveScene& scene, Renderer* renderer = nullptr);

    // Is an edit due by `time` not applied yet?
    bool pending(double time) const { return next_ < path_.edits.size() && path_.edits[next_].time <= time; }
    size_t applied() const { return next_; }

private:
    const voxel::CameraPathDesc& path_;
    size_t next_ = 0;
};

}  // namespace grotto
