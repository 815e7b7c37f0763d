#include "voxel/camera_path_desc.h"

#include "voxel/edit_track.h"
#include "voxel/json_reader.h"

#include <glm/geometric.hpp>

#include <cmath>

namespace grotto::voxel {
namespace fs = std::filesystem;

namespace {

PathKey parseKey(Reader r) {
    PathKey k;
    if (!r.has("time")) r.fail("time", "missing", "seconds from the start of the path");
    k.time = r.number("time", 0.0, 0.0, 1e7);
    if (!r.has("position")) r.fail("position", "missing");
    k.position = r.vec3("position", k.position, -kMaxPathCoordinate, kMaxPathCoordinate);
    const bool target = r.has("target"), rotation = r.has("quaternion");
    if (target == rotation)
        r.fail(target ? "quaternion" : "target", target ? "given with 'target'" : "missing",
               "each key gives either a look-at 'target' or a 'quaternion', not both");
    if (target) {
        k.target = r.vec3("target", k.position, -kMaxPathCoordinate, kMaxPathCoordinate);
        if (glm::length(*k.target - k.position) < 1e-9) r.fail("target", "equals position", "a camera must look somewhere");
    } else {
        k.rotation = r.quaternion("quaternion");
    }
    if (r.has("fov")) k.fovDegrees = r.number("fov", 60.0, 1.0, 170.0);
    k.cut = r.boolean("cut", false);
    return k;
}

std::vector<DayKey> parseDayTrack(Reader& path, const fs::path& file, const std::string& field) {
    const json& track = path.at("day");
    const std::string where = (field.empty() ? "" : field + ".") + "day";
    if (!track.is_array() || track.size() < 2)
        path.fail("day", "expected an array of at least two keys", "e.g. [{\"time\": 0, \"hours\": 6}, {\"time\": 60, \"hours\": 30}]");
    std::vector<DayKey> keys;
    for (size_t i = 0; i < track.size(); ++i) {
        const std::string name = where + "[" + std::to_string(i) + "]";
        Reader r(file, track[i], name);
        for (const char* needed : {"time", "hours"})
            if (!r.has(needed)) r.fail(needed, "missing", "each key of a day track gives a path 'time' and the 'hours' then");
        keys.push_back({.time = r.number("time", 0.0, 0.0, 1e7), .hours = r.number("hours", 0.0, 0.0, 240.0)});
        if (i > 0 && !(keys[i].time > keys[i - 1].time))
            r.fail("time", Reader::format(keys[i].time) + " does not come after the previous key's " + Reader::format(keys[i - 1].time),
                   "key times must increase strictly");
    }
    return keys;
}

}  // namespace

double hourAt(const std::vector<DayKey>& track, double time) {
    double hours = track.front().hours;
    if (time >= track.back().time) {
        hours = track.back().hours;
    } else if (time > track.front().time) {
        size_t i = 1;
        while (track[i].time <= time) ++i;
        const DayKey &a = track[i - 1], &b = track[i];
        hours = a.hours + (b.hours - a.hours) * (time - a.time) / (b.time - a.time);
    }
    return std::fmod(hours, 24.0);
}

CameraPathDesc parseCameraPath(Reader& r, const fs::path& file, const std::string& field) {
    CameraPathDesc p;
    p.source = file;
    p.field = field;
    const std::string interpolation = r.string("interpolation", "smooth");
    if (interpolation != "smooth" && interpolation != "linear")
        r.fail("interpolation", "'" + interpolation + "' is not an interpolation", "accepted: smooth, linear");
    p.interpolation = interpolation == "linear" ? PathInterpolation::Linear : PathInterpolation::Smooth;
    p.constantSpeed = r.boolean("constant_speed", false);
    if (p.constantSpeed && p.interpolation == PathInterpolation::Linear)
        r.fail("constant_speed", "is for smooth paths", "a linear path meets its keys at their times");
    if (r.has("fov")) p.fovDegrees = r.number("fov", 60.0, 1.0, 170.0);
    if (r.has("near")) p.nearPlane = r.number("near", 0.05, 1e-4, 10.0);
    if (r.has("far")) p.farPlane = r.number("far", 0.0, 0.0, 1e7);
    if (p.nearPlane && p.farPlane && *p.farPlane != 0.0 && *p.farPlane <= *p.nearPlane)
        r.fail("far", "must exceed 'near' (or be 0 for an infinite far plane)");
    if (r.has("edits")) p.edits = parseEditTrack(r, "edits", field);
    if (r.has("day")) p.day = parseDayTrack(r, file, field);
    if (!r.has("keys")) r.fail("keys", "missing", "a path needs at least two keys");
    const json& keys = r.at("keys");
    if (!keys.is_array()) r.fail("keys", "expected an array of keys");
    if (keys.size() < 2)
        r.fail("keys", "has " + std::to_string(keys.size()) + " key(s)", "a path needs at least two keys");
    for (size_t i = 0; i < keys.size(); ++i) {
        const std::string name = (field.empty() ? "" : field + ".") + "keys[" + std::to_string(i) + "]";
        p.keys.push_back(parseKey(Reader(file, keys[i], name)));
        if (i == 0 && p.keys[0].cut)
            throw Error(file.string(), "field '" + name + ".cut': the first key cannot be a cut",
                        "a cut jumps from the previous key's shot; the first key starts the first shot");
        if (i > 0 && !(p.keys[i].time > p.keys[i - 1].time))
            throw Error(file.string(), "field '" + name + ".time': " + Reader::format(p.keys[i].time) +
                                           " does not come after the previous key's " +
                                           Reader::format(p.keys[i - 1].time),
                        "key times must increase strictly");
    }
    return p;
}

CameraPathDesc loadCameraPath(const fs::path& file) {
    const json doc = readJsonFile(file, "a path file is a JSON object with \"keys\": [{\"time\", \"position\", \"target\"}, ...]");
    CameraPathDesc p;
    {
        Reader r(file, doc, "");
        p = parseCameraPath(r, file, "");
    }  // r refuses unknown fields here, before p is returned (clang leaks a returned object if a destructor throws)
    return p;
}

}  // namespace grotto::voxel
