#pragma once
// Evaluates a camera path (voxel/camera_path_desc.h) at a time in seconds:
// position on a centripetal Catmull-Rom curve through the keys, rotation by squad
// between the keys' rotations (look-at keys stay roll-free, Y up), fov by a
// monotone cubic; or, for a linear path, straight lines, slerp and linear fov. Keys are met at their times, unless the path asks for constant
// speed, which spreads each shot's curve evenly over its keys' time span. A key
// marked "cut" starts a new shot: the camera jumps there and the curve restarts.
#include "engine/camera.h"
#include "engine/spline.h"
#include "voxel/camera_path_desc.h"

#include <cstdint>
#include <span>
#include <vector>

namespace grotto {

struct CameraPose {
    glm::dvec3 position{0.0};
    glm::dmat3 basis{1.0};  // columns: right, up, back, as Camera::basis
    double fovDegrees = 60.0;
};

class CameraPath {
public:
    // `defaults` supplies fov, near and far where the path leaves them unset
    // (the world's default camera: World::camera("")).
    CameraPath(const voxel::CameraPathDesc& desc, const voxel::CameraDesc& defaults);

    double duration() const { return duration_; }  // the last key's time
    CameraPose pose(double time) const;
    Camera camera(double time, uint32_t width, uint32_t height) const;

    // The shot (0-based) that shows `time`. Where it changes between two frames the
    // view jumped, so temporal history must restart (Renderer::resetHistory).
    size_t shotAt(double time) const;
    bool cutBetween(double from, double to) const { return shotAt(from) != shotAt(to); }

    // Frame i (1-based) shows time (i - 1) / fps; frames cover [0, duration].
    // 64-bit, saturating: a long path at a high rate must not wrap to a negative count.
    int64_t frameCount(double fps) const;

private:
    // The keys from one cut to the next: one curve. A single key holds still.
    class Shot {
    public:
        Shot(std::span<const voxel::PathKey> keys, const voxel::CameraPathDesc& desc, double defaultFov);
        double start() const { return times_.front(); }
        CameraPose pose(double time) const;

    private:
        double curveParameter(double time) const;
        CameraPose linearPose(double time) const;

        std::vector<double> times_;
        spline::CentripetalCurve curve_;
        spline::RotationSpline rotations_;
        spline::MonotoneCubic timeToCurve_, fov_;
        std::vector<double> arcKnot_, arcLength_;  // cumulative length along the curve, for constant speed
        // A linear shot's keys, as they are.
        std::vector<glm::dvec3> points_;
        std::vector<glm::dquat> keyRotations_;
        std::vector<double> fovs_;
        bool linear_ = false, constantSpeed_ = false, rollFree_ = true;
        CameraPose still_;  // a one-key shot's pose
    };

    std::vector<Shot> shots_;  // in time order
    double duration_ = 0.0, nearPlane_ = 0.05, farPlane_ = 0.0;
};

}  // namespace grotto
