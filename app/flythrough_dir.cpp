#include "app/flythrough_dir.h"

#include "app/options.h"
#include "common/atomic_file.h"
#include "common/error.h"
#include "common/file_lock.h"

#include <fstream>
#include <sstream>
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
    writeAtomically(file, [&](const fs::path& tmp) {
        std::ofstream out(tmp);
        out << text << "\n";
        out.close();
        if (!out) throw Error(file.string(), "write failed", "is the disk full?");
    });
}

void requireSameRun(const fs::path& dir, const json& manifest, const FrameNames& names) {
    const fs::path file = dir / "flythrough.json";
    if (fs::exists(file)) {
        std::ifstream in(file);
        std::stringstream previous;
        previous << in.rdbuf();
        if (previous.str() != manifest.dump(2, ' ', false, json::error_handler_t::replace) + "\n")
            throw Error(file.string(), "holds frames of a flythrough with other settings",
                        "render into another directory, or delete this one to start over");
        return;
    }
    for (const auto& entry : fs::directory_iterator(dir)) {
        const std::string name = entry.path().filename().string();
        if (name.rfind("frame.", 0) == 0 || names.matches(name))
            throw Error(dir.string(), "already holds frames but no flythrough.json saying how they were made",
                        "render into another directory");
    }
    writeJson(file, manifest);
}

void removeAbandonedFiles(const fs::path& dir, const FrameNames& names) {
    removeAbandonedTemporaries(dir, [&](const std::string& name) {
        return name.rfind("frame.", 0) == 0 || names.matches(name) || name == "stats.json" || name == "flythrough.json";
    });
}

std::map<int, json> earlierFrames(const fs::path& file) {
    std::map<int, json> frames;
    if (!fs::exists(file)) return frames;
    std::ifstream in(file);
    const json doc = json::parse(in, nullptr, false);
    const std::string hint = "delete it to start the stats afresh";
    if (doc.is_discarded() || !doc.is_object() || !doc.contains("frames") || !doc["frames"].is_array())
        throw Error(file.string(), "is not a flythrough stats file (no \"frames\" array)", hint);
    for (size_t k = 0; k < doc["frames"].size(); ++k) {
        const json& f = doc["frames"][k];
        bool ok = f.is_object() && f.contains("frame") && f["frame"].is_number_integer() && f.contains("wall_ms") &&
                  f["wall_ms"].is_number() && f.contains("pass_ms") && f["pass_ms"].is_object() &&
                  f.contains("written") && f["written"].is_boolean();
        if (ok)
            for (const auto& [name, ms] : f["pass_ms"].items()) ok = ok && ms.is_number();
        if (!ok)
            throw Error(file.string(), "frames[" + std::to_string(k) + "] is not a frame entry",
                        "expected {\"frame\", \"written\", \"wall_ms\", \"pass_ms\"}; " + hint);
        frames[f["frame"].get<int>()] = f;
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

}  // namespace grotto::app
