#pragma once
// Progress of a long run: a bar with an ETA redrawn in place on a terminal, one
// plain line per step otherwise (logs and pipes get no carriage returns), or
// with --progress jsonl one JSON object a line, for a farm manager to read.
#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include <chrono>
#include <cstddef>
#include <cstdio>
#include <optional>
#include <string>

namespace grotto::app {

// auto: a bar on a terminal, plain lines otherwise; jsonl: JSON lines on stdout.
enum class ProgressFormat { Auto, Jsonl };
void addProgressOption(CLI::App* cmd, ProgressFormat& format);

class Progress {
public:
    Progress(int total, std::FILE* out, ProgressFormat format = ProgressFormat::Auto);
    // One more step done: `what` says which to a person, `fields` to a program
    // (jsonl: {"done", "total", "eta_s"} and these, on one line).
    void step(const std::string& what, const nlohmann::ordered_json& fields = nlohmann::ordered_json::object());
    void finish();  // ends the bar's line on a terminal

private:
    std::FILE* out_;
    ProgressFormat format_;
    bool terminal_;
    int total_, done_ = 0;
    std::chrono::steady_clock::time_point start_;
};

// A face bake's progress (voxel::bakeFacesInSteps calls it: 0 first, then after
// each run of faces), as a bar of "N of M faces"; pass it as std::ref(progress).
class FaceBakeProgress {
public:
    // jsonl goes to stdout, each line with `fields` added.
    explicit FaceBakeProgress(std::FILE* out, ProgressFormat format = ProgressFormat::Auto,
                              nlohmann::ordered_json fields = nlohmann::ordered_json::object())
        : out_(format == ProgressFormat::Jsonl ? stdout : out), format_(format), fields_(std::move(fields)) {}
    void operator()(size_t done, size_t total);
    void finish();

private:
    std::FILE* out_;
    ProgressFormat format_;
    nlohmann::ordered_json fields_;
    std::optional<Progress> bar_;
};

// "1:05" or "1:02:03".
std::string formatDuration(double seconds);

}  // namespace grotto::app
