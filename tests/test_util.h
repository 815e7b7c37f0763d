#pragma once
// Helpers shared by the tests: scratch directories and running the grotto CLI.
#include <filesystem>
#include <string>

namespace grotto::test {

// A fresh, empty directory under the system temp dir, removed on destruction.
struct ScratchDir {
    std::filesystem::path path;
    ScratchDir();
    ~ScratchDir();
    std::filesystem::path operator/(const std::string& name) const { return path / name; }
};

struct RunResult {
    int exitCode = -1;
    std::string out, err;
    double peakMiB = 0;  // the largest resident set of grotto and the processes it waited for
};

// AddressSanitizer reserves terabytes of address space and inflates resident
// memory: memory caps and figures do not apply under it.
#if defined(__SANITIZE_ADDRESS__)
constexpr bool kAddressSanitizer = true;
#else
constexpr bool kAddressSanitizer = false;
#endif

// Resource caps for a run, set with setrlimit before grotto starts; 0 = none.
// hangSeconds is a wall-clock guard against a test hanging, not a measurement:
// the run is killed after it.
struct RunLimits {
    int memoryMiB = 0;   // address space (RLIMIT_AS); not under AddressSanitizer
    int cpuSeconds = 0;  // RLIMIT_CPU
    int hangSeconds = 0;
};

// Runs the grotto executable with the given arguments (shell-quoted here),
// with `env` ("NAME=value ...") added to its environment.
RunResult runGrotto(const std::string& args, const std::string& env = "", const RunLimits& limits = {});

// The source tree's worlds/ directory.
std::filesystem::path worldsDir();

}  // namespace grotto::test
