#pragma once
// A world's camera path played in the viewer, on the viewer's clock: each frame
// shows the path at its clock, which then advances by the frame's step.
#include "engine/camera_path.h"

#include <optional>

namespace grotto::viewer {

class PathPlayer {
public:
    // Starts `path` at its time 0; `defaults`: the world's default camera (lens).
    void play(const voxel::CameraPathDesc& path, const voxel::CameraDesc& defaults);
    void stop() { path_.reset(); }
    bool playing() const { return path_.has_value(); }

    struct Frame {
        Camera camera;
        bool cut = false;    // the path cut since the last frame: the history restarts
        bool ended = false;  // the path's end: the player has stopped
    };
    // The camera now, then the clock moves on by `dt` seconds. Needs playing().
    Frame next(double dt, uint32_t width, uint32_t height);

private:
    std::optional<CameraPath> path_;
    double clock_ = 0.0, lastTime_ = 0.0;
};

// The fly camera's description of a camera (position, view direction, fov).
voxel::CameraDesc describe(const Camera& camera, const voxel::CameraDesc& lens);

}  // namespace grotto::viewer
