#pragma once
// Progress of a long run: a bar with an ETA redrawn in place on a terminal, one
// plain line per step otherwise (logs and pipes get no carriage returns).
#include <chrono>
#include <cstdio>
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

// "1:05" or "1:02:03".
std::string formatDuration(double seconds);

}  // namespace grotto::app
