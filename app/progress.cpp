#include "app/progress.h"

#include "voxel/face_bake.h"

#include <unistd.h>

#include <cmath>

namespace grotto::app {

void addProgressOption(CLI::App* cmd, ProgressFormat& format) {
    cmd->add_option_function<std::string>(
           "--progress", [&format](const std::string& v) { format = v == "jsonl" ? ProgressFormat::Jsonl : ProgressFormat::Auto; },
           "auto: a bar on a terminal, a line a step otherwise; jsonl: one JSON object a step on stdout, for a farm manager")
        ->check(CLI::IsMember({"auto", "jsonl"}))
        ->default_str("auto");
}

Progress::Progress(int total, std::FILE* out, ProgressFormat format)
    : out_(out), format_(format), terminal_(format == ProgressFormat::Auto && isatty(fileno(out))), total_(total),
      start_(std::chrono::steady_clock::now()) {}

std::string formatDuration(double seconds) {
    const long s = long(std::lround(std::max(seconds, 0.0)));
    char buf[32];
    if (s >= 3600)
        std::snprintf(buf, sizeof buf, "%ld:%02ld:%02ld", s / 3600, s / 60 % 60, s % 60);
    else
        std::snprintf(buf, sizeof buf, "%ld:%02ld", s / 60, s % 60);
    return buf;
}

void Progress::step(const std::string& what, const nlohmann::ordered_json& fields) {
    ++done_;
    const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
    const double etaSeconds = elapsed / done_ * (total_ - done_);
    const std::string eta = formatDuration(etaSeconds);
    if (format_ == ProgressFormat::Jsonl) {
        nlohmann::ordered_json line = {{"done", done_}, {"total", total_}, {"eta_s", std::round(etaSeconds * 10) / 10}};
        line.update(fields);
        std::fprintf(out_, "%s\n", line.dump().c_str());
    } else if (terminal_) {
        constexpr int kWidth = 30;
        const int filled = total_ > 0 ? done_ * kWidth / total_ : kWidth;
        const std::string bar = std::string(size_t(filled), '#') + std::string(size_t(kWidth - filled), '-');
        std::fprintf(out_, "\r[%s] %d/%d %3d%% ETA %s  %s\033[K", bar.c_str(), done_, total_,
                     total_ > 0 ? done_ * 100 / total_ : 100, eta.c_str(), what.c_str());
    } else {
        std::fprintf(out_, "%d/%d %s (ETA %s)\n", done_, total_, what.c_str(), eta.c_str());
    }
    std::fflush(out_);
}

void Progress::finish() {
    if (terminal_ && done_ > 0) std::fprintf(out_, "\n");
    std::fflush(out_);
}

void FaceBakeProgress::operator()(size_t done, size_t total) {
    // Started by the first call, before the first run of faces, so its ETA counts every run.
    if (!bar_) return void(bar_.emplace(voxel::bakeSteps(total), out_, format_));
    nlohmann::ordered_json fields = {{"faces_done", done}, {"faces_total", total}};
    fields.update(fields_);
    bar_->step(std::to_string(done) + " of " + std::to_string(total) + " faces", fields);
}

void FaceBakeProgress::finish() {
    if (bar_) bar_->finish();
}

}  // namespace grotto::app
