#include "app/stability_baseline.h"

#include "common/error.h"
#include "common/json_text.h"

#include <cmath>

namespace grotto::app {
namespace {

using json = nlohmann::json;

// The figures compared, as JSON pointers; every one is better lower.
const char* const kMetrics[] = {"/flicker/raw",           "/flicker/spatial",          "/flicker/temporal",
                                "/error_mean/spatial/rmse", "/error_mean/temporal/rmse", "/error_mean/temporal/mae"};

// Compared when the baseline has them: a path with edits (docs/metrics.md).
const char* const kEditMetrics[] = {"/edit_recovery/stale_after_edit_frame", "/edit_recovery/recovered_within_frames"};

// "/error_mean/spatial/rmse" -> "error_mean/spatial/rmse"
std::string metricName(const char* pointer) { return pointer + 1; }

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
    for (const char* m : kMetrics)
        if (!baseline.contains(json::json_pointer(m)) || !baseline[json::json_pointer(m)].is_number())
            throw Error(file.string() + ": " + metricName(m), "is missing or not a number",
                        "give the --json output of an earlier stability run");
    return baseline;
}

std::vector<BaselineCheck> checkBaseline(const json& baseline, const json& result, Tolerance t) {
    std::vector<BaselineCheck> checks;
    for (const char* m : kMetrics) {
        const double was = baseline[json::json_pointer(m)], is = result[json::json_pointer(m)];
        checks.push_back({metricName(m), was, is, was * (1.0 + t.relative) + t.absolute});
    }
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
