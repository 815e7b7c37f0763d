// Paths in the viewer. A world's path plays through the session as flythrough
// plays it: its camera, its objects' keys, its edits and its cuts, frame n at
// the path's clock numbered n as flythrough's frame n. Recording keeps camera
// keys and the edits made between them, saved as a path file.
#include "app/viewer/viewer_internal.h"

#include "common/printable.h"
#include "engine/camera_path.h"

#include <algorithm>
#include <cstdio>

namespace grotto::viewer {
namespace {

// The fly camera's description of a camera (position, view direction, fov).
voxel::CameraDesc cameraDescOf(const Camera& camera, const voxel::CameraDesc& lens) {
    voxel::CameraDesc d = lens;
    d.position = camera.position;
    d.target = camera.position - camera.basis[2];  // basis columns: right, up, back
    d.fovDegrees = glm::degrees(camera.fovY);
    return d;
}

}  // namespace

// The playing path's next frame (its end hands the camera back to the fly
// camera there), else the fly camera with the objects on the play clock.
Viewer::View Viewer::nextView(double dt) {
    if (!session_->playing()) {
        session_->setTime(playClock_);
        return {makeCamera(fly_->desc(), renderSize_.width, renderSize_.height), sequence_++};
    }
    const double t = std::min(pathClock_, session_->path().duration());
    const RenderSession::PathFrame f = session_->pathFrame(t, renderSize_.width, renderSize_.height);
    if (!f.edited.empty()) {
        panel_.quads = session_->scene().gpu().quadCount;
        panel_.activeVoxels = session_->world().stats().solidVoxels;
    }
    pathClock_ += dt;
    const View view{f.camera, ++pathFrames_};
    if (t >= session_->path().duration()) stopPath(f.camera);
    return view;
}

// From the path's start; its edits are checked against the world first.
void Viewer::playPath(const std::string& name) {
    session_->playPath(desc_.paths.at(name), session_->world().camera("", aspect()));
    panel_.playing = name;
    pathClock_ = 0.0;
    pathFrames_ = 0;
    cut();
}

// The fly camera takes over where the path stopped; the noise sequence goes on.
void Viewer::stopPath(const Camera& at) {
    fly_->jumpTo(cameraDescOf(at, fly_->desc()));
    session_->stopPath();
    sequence_ = pathFrames_ + 1;
    panel_.playing.clear();
}

// Records this frame's camera once it has moved (flyFromInput), so a key is the
// camera of the frame shown at its time.
void Viewer::addPendingKey() {
    if (!std::exchange(recordPending_, false)) return;
    if (!recordStart_) recordStart_ = playClock_;
    if (recorder_.add(playClock_ - *recordStart_, fly_->desc()))
        panel_.message = "path key " + std::to_string(recorder_.size()) + " at " +
                         std::to_string(playClock_ - *recordStart_) + " s";
    panel_.recordedKeys = recorder_.size();
}

void Viewer::savePath(const std::filesystem::path& file) {
    recorder_.save(file);
    panel_.message = "wrote " + file.string();
    std::printf("wrote %s (%zu keys, %zu edits)\n", printable(file.string()).c_str(), recorder_.size(),
                recorder_.edits());
}

}  // namespace grotto::viewer
