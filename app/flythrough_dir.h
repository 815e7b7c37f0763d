#pragma once
// What a flythrough keeps in its output directory beside the frames: the
// manifest (DIR/flythrough.json: the settings that decide the frames, so a
// resumed run never mixes sequences), the stats (DIR/stats.json: every run's
// frame times, merged by frame number), the lock that serialises the runs
// sharing the directory while they read and write those two, and the shared
// lock on the manifest by which a run says it is alive.
#include "app/frame_names.h"
#include "common/file_lock.h"
#include "engine/camera_path.h"

#include <nlohmann/json.hpp>

#include <chrono>
#include <filesystem>
#include <map>
#include <mutex>
#include <string>
#include <vector>

namespace grotto::app {

// Hidden, like the temporary files.
inline constexpr const char* kFlythroughLock = ".flythrough.lock";

// The path as the manifest records it: keys, edits and the camera settings.
nlohmann::json pathManifest(const voxel::CameraPathDesc& path);

// Whether `dir` may take a run of `manifest` (its settings): throws grotto::Error
// (input) naming the first setting that differs when dir/flythrough.json records
// others and the directory holds frames of them (or frames `names` matches are
// there with no manifest), or a live run of them holds it (claimDirectory); and
// for a stats.json that is not a stats file. Writes nothing: called before the
// directory is made, every refusal leaves it as it was. Returns whether the
// manifest is to be written: there is none, or a run killed before its
// first frame left one of other settings (its stats go with it).
bool requireSameRun(const std::filesystem::path& dir, const nlohmann::json& manifest, const FrameNames& names);

// Takes `dir` for this run: with the directory's lock held, checks it again
// (requireSameRun: chunks may have started together), writes the manifest, clears
// what killed runs left (removeAbandonedFiles), and returns a shared lock on the
// manifest to hold while the run lasts. That lock tells a run of other settings
// that this one is alive, though none of its frames may be written yet.
FileLock claimDirectory(const std::filesystem::path& dir, const nlohmann::json& manifest, const FrameNames& names);

// Removes what killed runs left: temporaries of frames, stats and manifest.
void removeAbandonedFiles(const std::filesystem::path& dir, const FrameNames& names);

// The per-frame entries of earlier runs (DIR/stats.json), by frame number.
// Throws grotto::Error (input) for a file that is not a stats file: read it
// before rendering, so a damaged file is refused before anything is written.
std::map<int, nlohmann::json> earlierFrames(const std::filesystem::path& file);

// The frames from `first` to `last` a run writes: all but those in `dir` whole
// (decoding as width x height images) and marked written in its stats, so a
// frame a failed write damaged, or one whose run was killed before it recorded
// the frame, is written again. Throws as earlierFrames.
std::vector<int> framesToWrite(const std::filesystem::path& dir, const FrameNames& names, int first, int last,
                               uint32_t width, uint32_t height);

// This run's entry replaces an earlier one of the same frame, except that a
// warm-up render keeps the entry of the run that wrote the frame.
void mergeFrame(std::map<int, nlohmann::json>& frames, const nlohmann::json& entry);

// Merges `entries` into DIR/stats.json as it is now (other chunks may have
// written it since this run read it), with the lock held; written atomically.
void mergeStats(const std::filesystem::path& dir, const std::vector<nlohmann::json>& entries);

// A run's frame entries, merged into DIR/stats.json while it renders (every
// kInterval at most) and at its end, so a run that is killed loses the entries
// of its last seconds only: the next run writes those frames again.
class StatsRecorder {
public:
    static constexpr std::chrono::seconds kInterval{5};
    explicit StatsRecorder(std::filesystem::path dir) : dir_(std::move(dir)) {}
    void add(nlohmann::json entry);  // any thread: a written frame's entry once the frame is on disk
    void mergeIfDue();               // merges what was added when kInterval has passed since the last merge
    void merge();

private:
    std::filesystem::path dir_;
    std::mutex mutex_;
    std::vector<nlohmann::json> added_;
    std::chrono::steady_clock::time_point last_ = std::chrono::steady_clock::now();
};

// A JSON file written atomically.
void writeJson(const std::filesystem::path& file, const nlohmann::json& j);

}  // namespace grotto::app
