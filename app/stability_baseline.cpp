#include "app/stability_baseline.h"

#include "grotto/error.h"
#include "common/json_text.h"

#include <cmath>
#include <fstream>
#include <map>
#include <optional>

namespace grotto::app {
namespace {

using json = nlohmann::json;

// The figures compared, as JSON pointers; every one is better lower.
const char* const kMetrics[] = {"/flicker/raw",           "/flicker/spatial",          "/flicker/temporal",
                                "/error_mean/spatial/rmse", "/error_mean/temporal/rmse", "/error_mean/temporal/mae",
                                "/color/flicker"};

// Compared when the baseline has them: a path with edits (docs/metrics.md).
const char* const kEditMetrics[] = {"/edit_recovery/stale_after_edit_frame", "/edit_recovery/recovered_within_frames"};

// "/error_mean/spatial/rmse" -> "error_mean/spatial/rmse"
std::string metricName(const char* pointer) { return pointer + 1; }

// A figure compared must be one: a finite number, not negative (every one is a
// mean of magnitudes or a count). Anything else would pass or fail any run.
void requireFigure(const std::filesystem::path& file, const json& figure, const std::string& name) {
    if (!figure.is_number() || !std::isfinite(figure.get<double>()) || figure.get<double>() < 0.0)
        throw Error(file.string() + ": " + name, "is " + figure.dump() + ", not a figure of a stability run",
                    "accepted: a finite number, 0 or more; give the --json output of an earlier stability run");
}

// The thumbnails of "color/thumbnails" by frame; Error naming `where` and the field if any is malformed.
std::map<int, ColorThumbnail> readThumbnails(const json& run, const std::string& where) {
    const json::json_pointer at("/color/thumbnails");
    auto fail = [&](const std::string& field, const std::string& what) -> void {
        throw Error(where + ": color.thumbnails" + field, what, "give the --json output of an earlier stability run");
    };
    if (!run.contains(at) || !run[at].is_object()) fail("", "is missing");
    const json& t = run[at];
    if (!t.contains("cells") || !t["cells"].is_array() || t["cells"].size() != 2 || !t["cells"][0].is_number_unsigned() ||
        !t["cells"][1].is_number_unsigned() || t["cells"][0] < 1 || t["cells"][0] > kThumbnailCells ||
        t["cells"][1] < 1 || t["cells"][1] > kThumbnailCells)
        fail(".cells", "is not [w, h] of 1 to " + std::to_string(kThumbnailCells) + " cells");
    const uint32_t w = t["cells"][0], h = t["cells"][1];
    if (!t.contains("frames") || !t["frames"].is_array() || t["frames"].empty()) fail(".frames", "is not a list of frames");
    std::map<int, ColorThumbnail> out;
    for (size_t i = 0; i < t["frames"].size(); ++i) {
        const json& f = t["frames"][i];
        const std::string field = ".frames[" + std::to_string(i) + "]";
        if (!f.is_object() || !f.contains("frame") || !f["frame"].is_number_integer() || !f.contains("rgb") ||
            !f["rgb"].is_string())
            fail(field, "is not {\"frame\": N, \"rgb\": hex}");
        const std::optional<std::vector<uint8_t>> rgb = fromHex(f["rgb"].get<std::string>());
        if (!rgb || rgb->size() != size_t(3) * w * h)
            fail(field + ".rgb", "is not " + std::to_string(6 * w * h) + " hex digits (3 bytes a cell)");
        out[f["frame"].get<int>()] = ColorThumbnail{w, h, *rgb};
    }
    return out;
}

}  // namespace

json thumbnailsJson(const FrameThumbnails& thumbnails) {
    json frames = json::array();
    for (const auto& [frame, t] : thumbnails) frames.push_back({{"frame", frame}, {"rgb", toHex(t.rgb)}});
    const ColorThumbnail& any = thumbnails.empty() ? ColorThumbnail{} : thumbnails.front().second;
    return {{"every", kThumbnailEvery}, {"cells", {any.width, any.height}}, {"frames", frames}};
}

namespace {

// The mean over the baseline's thumbnails of the RMSE against this run's of the
// same frame (NaN for a frame this run has none of).
double thumbnailError(const std::map<int, ColorThumbnail>& baseline, const std::map<int, ColorThumbnail>& run) {
    double sum = 0.0;
    for (const auto& [frame, t] : baseline) {
        const auto it = run.find(frame);
        sum += it == run.end() ? NAN : thumbnailRmse(it->second, t);
    }
    return sum / double(baseline.size());
}

}  // namespace

json loadBaseline(const std::filesystem::path& file, const json& run) {
    json baseline = json::parse(readJsonText(file, "give the --json output of an earlier stability run"), nullptr, false);
    if (baseline.is_discarded() || !baseline.is_object())
        throw Error(file.string(), "is not JSON", "give the --json output of an earlier stability run");
    auto require = [&](const std::string& field, json was, json is) {
        if (was != is)
            throw Error(file.string() + ": " + field, "is " + was.dump() + " there but " + is.dump() + " in this run",
                        "a baseline compares only the same run; make a new one with --json");
    };
    for (auto& [field, value] : run.items()) {
        if (!baseline.contains(field))
            throw Error(file.string(), "has no field '" + field + "'", "is it the --json output of grotto stability?");
        const json& was = baseline[field];
        if (field == "world" && was.is_string())  // run from anywhere: the world file's name identifies it
            require(field, std::filesystem::path(was.get<std::string>()).filename().string(),
                    std::filesystem::path(value.get<std::string>()).filename().string());
        else if (value.is_object())  // e.g. reference: its spp and spacing, not what it traced
            for (auto& [key, inner] : value.items())
                require(field + "." + key, was.is_object() && was.contains(key) ? was[key] : json(), inner);
        else
            require(field, was, value);
    }
    for (const char* m : kMetrics) {
        if (!baseline.contains(json::json_pointer(m)) || !baseline[json::json_pointer(m)].is_number())
            throw Error(file.string() + ": " + metricName(m), "is missing or not a number",
                        "give the --json output of an earlier stability run of this version; older ones lack "
                        "the colour figures: make it again");
        requireFigure(file, baseline[json::json_pointer(m)], metricName(m));
    }
    for (const char* m : kEditMetrics)  // compared when there (null: not measured)
        if (baseline.contains(json::json_pointer(m)) && !baseline[json::json_pointer(m)].is_null())
            requireFigure(file, baseline[json::json_pointer(m)], metricName(m));
    readThumbnails(baseline, file.string());
    return baseline;
}

std::vector<BaselineCheck> checkBaseline(const json& baseline, const json& result, Tolerance t) {
    std::vector<BaselineCheck> checks;
    for (const char* m : kMetrics) {
        const double was = baseline[json::json_pointer(m)], is = result[json::json_pointer(m)];
        checks.push_back({metricName(m), was, is, was * (1.0 + t.relative) + t.absolute});
    }
    // Against the baseline's own frames: 0 there, so only the absolute tolerance is left.
    checks.push_back({"color/error_vs_baseline", 0.0,
                      thumbnailError(readThumbnails(baseline, "baseline"), readThumbnails(result, "this run")), t.absolute});
    for (const char* m : kEditMetrics) {
        const json::json_pointer p(m);
        if (!baseline.contains(p) || !baseline[p].is_number()) continue;
        // A run whose edits were not measured (no figure) has regressed: it proves nothing.
        const double was = baseline[p], is = result.contains(p) && result[p].is_number() ? result[p].get<double>() : NAN;
        checks.push_back({metricName(m), was, is, was * (1.0 + t.relative) + t.absolute});
    }
    return checks;
}

}  // namespace grotto::app
