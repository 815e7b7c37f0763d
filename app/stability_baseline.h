#pragma once
// `grotto stability --baseline FILE`: this run's metrics against an earlier run's
// JSON, by the rule the regression tests use (tests/baselines/): a figure regresses
// when it exceeds was * (1 + relative) + absolute. Lower is better for every
// figure compared, so improvements pass (and are worth re-blessing).
#include "engine/lab/color_thumbnail.h"

#include <nlohmann/json.hpp>

#include <filesystem>
#include <string>
#include <utility>
#include <vector>

namespace grotto::app {

// A run keeps the display colour of its first frame measured, of every
// kThumbnailEvery-th after it and of its last as thumbnails (engine/lab/color_thumbnail.h):
// what a later run's frames are compared with.
inline constexpr int kThumbnailEvery = 8;
inline bool keepsThumbnail(int frame, int first, int last) { return (frame - first) % kThumbnailEvery == 0 || frame == last; }
using FrameThumbnails = std::vector<std::pair<int, ColorThumbnail>>;  // (frame, thumbnail)
// {"every": 8, "cells": [w, h], "frames": [{"frame": i, "rgb": "hex"}, ...]}
nlohmann::json thumbnailsJson(const FrameThumbnails& thumbnails);

struct Tolerance {
    double relative = 0.05;    // 5 %
    double absolute = 0.0005;  // so a figure near zero may wobble
};

struct BaselineCheck {
    std::string metric;     // e.g. "flicker/temporal"
    double was, is, limit;  // the baseline's figure, this run's, and the most it may be
    bool regressed() const { return !(is <= limit); }  // a NaN figure too
};

// The baseline, read and checked against `run`: the fields of a stability JSON that
// say what was measured (world file name, path, size, fps, frames, quality, ...),
// every one of which must match, and its figures: finite and not negative, the
// thumbnails whole. Throws grotto::Error (input) naming the file, and the field
// that differs or is wrong, for anything else.
nlohmann::json loadBaseline(const std::filesystem::path& file, const nlohmann::json& run);

// Flicker (raw, spatial, temporal AO and the display colour) and steady-state
// error (spatial and temporal RMSE, temporal MAE) of `result` against the same
// figures of `baseline`; the display colour's error against the baseline's
// frames (the mean RMSE of the thumbnails of the same frames, which is 0 in the
// baseline itself); on a path with edits also the stale share after the edit
// frame and the frames the edited region took to recover.
std::vector<BaselineCheck> checkBaseline(const nlohmann::json& baseline, const nlohmann::json& result, Tolerance t);

}  // namespace grotto::app
