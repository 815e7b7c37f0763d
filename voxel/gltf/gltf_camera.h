#pragma once
// A camera animated in a glTF 2.0 file, as Blender and game engines export it,
// played as a Grotto camera path. glTF and Grotto agree on the frame: right-handed,
// Y up, a camera looking down its node's -Z with +Y up; one glTF unit (a metre)
// is one Grotto world unit.
//
// The camera's node and every ancestor may be animated (translation, rotation,
// scale; STEP, LINEAR or CUBICSPLINE samplers). The path is a linear one
// (voxel/camera_path_desc.h) whose keys reproduce the animation: the samplers' own
// key times, plus keys between them wherever straight lines and slerp would stray
// from the animation by more than kPathPositionTolerance of the path's extent or
// kPathRotationTolerance radians (CUBICSPLINE curves, animated parents). A LINEAR
// animation of one node needs no extra keys; a STEP jump becomes a camera cut.
#include "voxel/camera_path_desc.h"

#include <glm/gtc/quaternion.hpp>

#include <filesystem>
#include <memory>
#include <string>

namespace grotto::voxel {

inline constexpr double kPathPositionTolerance = 1e-5;  // of the extent of the camera's positions
inline constexpr double kPathRotationTolerance = 1e-4;  // radians (0.006 degrees)
inline constexpr size_t kMaxImportedPathKeys = 200000;
inline constexpr size_t kMaxAnimationKeys = size_t(1) << 20;  // over the samplers that move the camera

struct GltfCameraChoice {
    std::string camera;     // a node's or a camera's name; empty: the first animated camera node
    std::string animation;  // an animation's name; empty: the first that moves the camera
};

// The chosen camera's animation, evaluated exactly as the file's samplers say.
class GltfCameraAnimation {
public:
    // Throws grotto::Error (input) naming the file and what is wrong or missing.
    GltfCameraAnimation(const std::filesystem::path& file, const GltfCameraChoice& choice = {});
    ~GltfCameraAnimation();
    GltfCameraAnimation(GltfCameraAnimation&&) noexcept;

    struct Pose {
        glm::dvec3 position{0.0};
        glm::dquat rotation{1.0, 0.0, 0.0, 0.0};  // world from camera
    };
    // At `time` seconds; `before`: the limit from earlier times, where a STEP sampler jumps.
    Pose pose(double time, bool before = false) const;
    double fovDegrees() const;                    // the camera's yfov
    double nearPlane() const, farPlane() const;   // far 0: infinite (no zfar)
    // Every key time of the samplers that move the camera, ascending, without repeats.
    const std::vector<double>& keyTimes() const;

    // The linear path described above.
    CameraPathDesc path() const;

    struct Data;

private:
    std::unique_ptr<Data> d_;
};

// GltfCameraAnimation(file, choice).path().
CameraPathDesc importGltfCameraPath(const std::filesystem::path& file, const GltfCameraChoice& choice = {});

}  // namespace grotto::voxel
