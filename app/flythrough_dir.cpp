#include "app/flythrough_dir.h"

#include "app/options.h"
#include "common/atomic_file.h"
#include "grotto/error.h"
#include "common/file_lock.h"
#include "common/json_text.h"
#include "engine/image_output.h"

#include <cmath>
#include <optional>
#include <vector>

namespace grotto::app {

namespace fs = std::filesystem;
using nlohmann::json;

json pathManifest(const voxel::CameraPathDesc& p) {
    json keys = json::array();
    for (const voxel::PathKey& k : p.keys) {
        json key = {{"time", k.time}, {"position", {k.position.x, k.position.y, k.position.z}}};
        if (k.target) key["target"] = {k.target->x, k.target->y, k.target->z};
        if (k.rotation) key["quaternion"] = {k.rotation->x, k.rotation->y, k.rotation->z, k.rotation->w};
        if (k.fovDegrees) key["fov"] = *k.fovDegrees;
        if (k.cut) key["cut"] = true;
        keys.push_back(key);
    }
    json j = {{"keys", keys}, {"constant_speed", p.constantSpeed}};
    if (!p.edits.empty()) {  // only then: a resumed run of a path without edits keeps its manifest
        json edits = json::array();
        for (const voxel::TimedEdit& t : p.edits) {
            const voxel::Edit& e = t.edit;
            json edit = {{"time", t.time}, {"op", int(e.op)}, {"material", e.material}};
            if (e.shape == voxel::Edit::Shape::Box)
                edit["voxels"] = {{e.box.min.x, e.box.min.y, e.box.min.z}, {e.box.max.x, e.box.max.y, e.box.max.z}};
            else
                edit["sphere"] = {e.centre.x, e.centre.y, e.centre.z, e.radius};
            edits.push_back(edit);
        }
        j["edits"] = edits;
    }
    if (p.fovDegrees) j["fov"] = *p.fovDegrees;
    if (p.nearPlane) j["near"] = *p.nearPlane;
    if (p.farPlane) j["far"] = *p.farPlane;
    return j;
}

void writeJson(const fs::path& file, const json& j) {
    const std::string text = j.dump(2, ' ', false, json::error_handler_t::replace);
    writeAtomically(file, text + "\n");
}

namespace {

// A frame's entry in stats.json is well under 1 KiB: room for the longest path.
constexpr size_t kMaxStatsBytes = size_t(1) << 30;

// A JSON file the run keeps in its directory, null when it does not parse.
// Anything but a regular file is refused (a FIFO would block the run), and so
// is one nested past reason (common/json_text.h).
json readDirectoryJson(const fs::path& file, const std::string& hint) {
    json j = json::parse(readJsonText(file, hint, kMaxStatsBytes), nullptr, false);
    return j.is_discarded() ? json() : j;
}

// The first setting in which two manifests differ, e.g. `size was "64x32", this run's is "32x16"`.
std::string firstDifference(const json& was, const json& is, const std::string& at = "") {
    auto shown = [](const json& j) {
        std::string text = j.dump();
        return text.size() > 60 ? text.substr(0, 57) + "..." : text;
    };
    if (was.is_object() && is.is_object()) {
        json keys = was;
        keys.update(is);
        for (const auto& [key, value] : keys.items()) {
            const std::string name = at.empty() ? key : at + "." + key;
            if (!was.contains(key)) return name + " was not set, this run's is " + shown(is[key]);
            if (!is.contains(key)) return name + " was " + shown(was[key]) + ", this run has none";
            if (was[key] != is[key]) return firstDifference(was[key], is[key], name);
        }
    }
    if (was.is_array() && is.is_array() && was.size() == is.size())
        for (size_t k = 0; k < was.size(); ++k)
            if (was[k] != is[k]) return firstDifference(was[k], is[k], at + "[" + std::to_string(k) + "]");
    return (at.empty() ? "the manifest" : at) + " was " + shown(was) + ", this run's is " + shown(is);
}

// Whether `dir` holds a frame by `names`, or by the names `previous` (a manifest) recorded.
bool holdsFrames(const fs::path& dir, const FrameNames& names, const json& previous) {
    std::optional<FrameNames> old;
    try {
        if (previous.is_object())
            old.emplace(previous.value("name", std::string(kDefaultFramePattern)), previous.value("start_number", 1),
                        previous.value("format", std::string("png")));
    } catch (const std::exception&) {  // a damaged manifest: its frames are found by the default names
    }
    for (const auto& entry : fs::directory_iterator(dir)) {
        const std::string name = entry.path().filename().string();
        if (name.rfind("frame.", 0) == 0 || names.matches(name) || (old && old->matches(name))) return true;
    }
    return false;
}

}  // namespace

bool requireSameRun(const fs::path& dir, const json& manifest, const FrameNames& names) {
    const fs::path file = dir / "flythrough.json";
    const std::string hint = "render into another directory, or delete this one to start over";
    earlierFrames(dir / "stats.json");  // refused here, before anything is written, when it is not a stats file
    if (!fs::exists(file)) {
        if (holdsFrames(dir, names, json()))
            throw Error(dir.string(), "already holds frames but no flythrough.json saying how they were made",
                        "render into another directory");
        return true;
    }
    const json previous = readDirectoryJson(file, hint);
    if (previous == manifest) return false;
    const std::string difference = previous.is_object() ? firstDifference(previous, manifest) : "it does not parse";
    if (holdsFrames(dir, names, previous))
        throw Error(file.string(), "holds frames made with other settings: " + difference, hint);
    // No frames yet: a run of those settings that is still starting holds the
    // manifest (claimDirectory); one killed before its first frame does not.
    if (FileLock::heldElsewhere(file))
        throw Error(file.string(), "is a running flythrough's, made with other settings: " + difference,
                    "wait for it to end, or render into another directory");
    return true;
}

FileLock claimDirectory(const fs::path& dir, const json& manifest, const FrameNames& names) {
    FileLock lock(dir / kFlythroughLock);
    if (requireSameRun(dir, manifest, names)) {
        std::error_code ec;
        fs::remove(dir / "stats.json", ec);  // a stale manifest's (or none's): the frames they list are gone
        writeJson(dir / "flythrough.json", manifest);
    }
    removeAbandonedFiles(dir, names);
    return FileLock(dir / "flythrough.json", FileLock::Mode::Shared);  // taken before `lock` is let go
}

void removeAbandonedFiles(const fs::path& dir, const FrameNames& names) {
    removeAbandonedTemporaries(dir, [&](const std::string& name) {
        return name.rfind("frame.", 0) == 0 || names.matches(name) || name == "stats.json" || name == "flythrough.json";
    });
}

std::map<int, json> earlierFrames(const fs::path& file) {
    std::map<int, json> frames;
    const std::string hint = "delete it to start the stats afresh";
    if (!fs::exists(file)) return frames;
    const json doc = readDirectoryJson(file, hint);
    if (!doc.is_object() || !doc.contains("frames") || !doc["frames"].is_array())
        throw Error(file.string(), "is not a flythrough stats file (no \"frames\" array)", hint);
    // Times are finite and not negative: medians of them stay numbers.
    auto isTime = [](const json& ms) { return ms.is_number() && std::isfinite(ms.get<double>()) && ms.get<double>() >= 0.0; };
    for (size_t k = 0; k < doc["frames"].size(); ++k) {
        const json& f = doc["frames"][k];
        bool ok = f.is_object() && f.contains("frame") && f["frame"].is_number_integer() && f.contains("wall_ms") &&
                  isTime(f["wall_ms"]) && f.contains("pass_ms") && f["pass_ms"].is_object() && f.contains("written") &&
                  f["written"].is_boolean();
        if (ok)
            for (const auto& [name, ms] : f["pass_ms"].items()) ok = ok && isTime(ms);
        if (!ok)
            throw Error(file.string(), "frames[" + std::to_string(k) + "] is not a frame entry",
                        "expected {\"frame\", \"written\", \"wall_ms\", \"pass_ms\"}, times in milliseconds (finite, "
                        "not negative); " + hint);
        frames[f["frame"].get<int>()] = f;
    }
    return frames;
}

std::vector<int> framesToWrite(const fs::path& dir, const FrameNames& names, int first, int last, uint32_t width,
                               uint32_t height) {
    const std::map<int, json> recorded = earlierFrames(dir / "stats.json");
    std::vector<int> frames;
    for (int i = first; i <= last; ++i) {
        const auto entry = recorded.find(i);
        const bool done = entry != recorded.end() && entry->second["written"].get<bool>() &&
                          imageDecodes(dir / names.name(i), width, height);
        if (!done) frames.push_back(i);
    }
    return frames;
}

void mergeFrame(std::map<int, json>& frames, const json& entry) {
    json& slot = frames[entry["frame"].get<int>()];
    if (slot.is_null() || entry["written"].get<bool>() || !slot["written"].get<bool>()) slot = entry;
}

namespace {

// Per-frame times, in frame order, and their medians.
json statsJson(const std::map<int, json>& byFrame) {
    json frames = json::array();
    for (const auto& [i, f] : byFrame) frames.push_back(f);
    std::vector<double> wall;
    std::map<std::string, std::vector<double>> passes;
    for (const json& f : frames) {
        wall.push_back(f["wall_ms"].get<double>());
        for (auto& [name, ms] : f["pass_ms"].items()) passes[name].push_back(ms.get<double>());
    }
    json medians = {{"wall_ms", median(wall)}, {"pass_ms", json::object()}};
    for (auto& [name, ms] : passes) medians["pass_ms"][name] = median(ms);
    return {{"frames", frames}, {"median", medians}};
}

}  // namespace

void mergeStats(const fs::path& dir, const std::vector<json>& entries) {
    FileLock lock(dir / kFlythroughLock);
    std::map<int, json> frames = earlierFrames(dir / "stats.json");
    for (const json& entry : entries) mergeFrame(frames, entry);
    writeJson(dir / "stats.json", statsJson(frames));
}

void StatsRecorder::add(json entry) {
    std::lock_guard lock(mutex_);
    added_.push_back(std::move(entry));
}

void StatsRecorder::mergeIfDue() {
    if (std::chrono::steady_clock::now() - last_ >= kInterval) merge();
}

void StatsRecorder::merge() {
    std::vector<json> entries;
    {
        std::lock_guard lock(mutex_);
        entries.swap(added_);
    }
    last_ = std::chrono::steady_clock::now();
    if (!entries.empty()) mergeStats(dir_, entries);
}

}  // namespace grotto::app
