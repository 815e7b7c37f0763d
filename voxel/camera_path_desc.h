#pragma once
// What a camera path says, as plain data: keyframes and options, read strictly
// from a world file's "paths" or from a path .json of its own. OpenVDB-free.
// docs/paths.md describes the format; engine/camera_path.h evaluates it.
#include "voxel/edit.h"

#include <glm/gtc/quaternion.hpp>
#include <glm/vec3.hpp>

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace grotto::voxel {

class Reader;

// A key's position and target: each coordinate within ±kMaxPathCoordinate (world
// units), for paths read from JSON and imported from glTF alike.
inline constexpr double kMaxPathCoordinate = 1e12;

struct PathKey {
    double time = 0.0;                   // seconds; strictly increasing, >= 0
    glm::dvec3 position{0.0};
    std::optional<glm::dvec3> target;    // look-at point (roll-free, Y up) ...
    std::optional<glm::dquat> rotation;  // ... or world-from-camera rotation, unit length
    std::optional<double> fovDegrees;    // vertical; unset = the path's fov
    bool cut = false;                    // starts a new shot: the camera jumps here, history restarts
};

// An edit the path applies at its time: flythrough and stability apply every edit
// whose time has come before rendering a frame, so an edit sequence replays the
// same on every run.
struct TimedEdit {
    double time = 0.0;  // seconds; non-decreasing along the track, >= 0
    Edit edit;
    std::string field;  // where in the file ("paths.dig.edits[2]"), for errors found later
};

// A key of the "day" track: the hour of the day at a path time.
struct DayKey {
    double time = 0.0;   // seconds; strictly increasing, >= 0
    double hours = 0.0;  // hours of local solar time, 0 to 240, increasing or not; 24 and 0 are the same hour
};

// The hour of a day track at path `time`: linear between keys, held before the
// first and after the last, taken modulo 24 (a track from 0 to 24 is one whole day).
double hourAt(const std::vector<DayKey>& track, double time);

// How the camera moves between keys.
enum class PathInterpolation {
    Smooth,  // a centripetal Catmull-Rom curve, squad rotations, monotone cubic fov
    Linear,  // straight lines, slerp and linear fov: a path sampled from an animation
};

struct CameraPathDesc {
    std::filesystem::path source;  // the file the path was read from
    std::string field;             // where in it ("paths.walk"), empty for a whole path file
    std::vector<PathKey> keys;     // at least two
    PathInterpolation interpolation = PathInterpolation::Smooth;
    bool constantSpeed = false;    // reparametrise by arc length (smooth paths only)
    std::vector<TimedEdit> edits;  // the "edits" track, in time order; empty = a static world
    std::vector<DayKey> day;       // the "day" track; empty = the world's lighting as it is
    // Unset = the world's camera conventions (its default camera).
    std::optional<double> fovDegrees, nearPlane, farPlane;
};

// Reads a path .json of its own. Throws grotto::Error (input) naming the file and
// field for anything missing, malformed or unknown.
CameraPathDesc loadCameraPath(const std::filesystem::path& file);

// Reads a path object from an open reader (world files hold paths inline).
CameraPathDesc parseCameraPath(Reader& reader, const std::filesystem::path& file, const std::string& field);

}  // namespace grotto::voxel
