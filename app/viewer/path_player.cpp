#include "app/viewer/path_player.h"

#include <algorithm>

namespace grotto::viewer {

void PathPlayer::play(const voxel::CameraPathDesc& path, const voxel::CameraDesc& defaults) {
    path_.emplace(path, defaults);
    clock_ = lastTime_ = 0.0;
}

PathPlayer::Frame PathPlayer::next(double dt, uint32_t width, uint32_t height) {
    const double t = std::min(clock_, path_->duration());
    Frame f{path_->camera(t, width, height), t > 0.0 && path_->cutBetween(lastTime_, t), t >= path_->duration()};
    lastTime_ = t;
    clock_ += dt;
    if (f.ended) path_.reset();
    return f;
}

voxel::CameraDesc describe(const Camera& camera, const voxel::CameraDesc& lens) {
    voxel::CameraDesc d = lens;
    d.position = camera.position;
    d.target = camera.position - camera.basis[2];  // basis columns: right, up, back
    d.fovDegrees = glm::degrees(camera.fovY);
    return d;
}

}  // namespace grotto::viewer
