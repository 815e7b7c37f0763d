#pragma once
// Progress of a long run: a bar with an ETA redrawn in place on a terminal, one
// plain line per step otherwise (logs and pipes get no carriage returns).
#include <chrono>
#include <cstddef>
#include <cstdio>
#include <optional>
#include <string>

namespace grotto::app {

class Progress {
public:
    Progress(int total, std::FILE* out);
    void step(const std::string& what);  // one more step done; `what` says which
    void finish();                        // ends the bar's line on a terminal

private:
    std::FILE* out_;
    bool terminal_;
    int total_, done_ = 0;
    std::chrono::steady_clock::time_point start_;
};

// A face bake's progress (voxel::bakeFacesInSteps calls it: 0 first, then after
// each run of faces), as a bar of "N of M faces"; pass it as std::ref(progress).
class FaceBakeProgress {
public:
    explicit FaceBakeProgress(std::FILE* out) : out_(out) {}
    void operator()(size_t done, size_t total);
    void finish();

private:
    std::FILE* out_;
    std::optional<Progress> bar_;
};

// "1:05" or "1:02:03".
std::string formatDuration(double seconds);

}  // namespace grotto::app
