#pragma once
// Helpers shared by the tests: scratch directories and running the grotto CLI.
#include "common/sanitizers.h"

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
constexpr bool kAddressSanitizer = GROTTO_ASAN;

// `full` in an ordinary build, `reduced` under the sanitizers (the sanitize
// preset builds AddressSanitizer and UndefinedBehaviorSanitizer together), for
// a loop that repeats one code path many times: the frames of a path, random
// edits, seeds, points checked against the CPU. The sanitizers look for memory
// errors, undefined behaviour and leaks, which the first iterations of such a
// loop meet as well as the last; the numerical and visual checks run at full
// strength in the other builds. A count (underSanitizers(1000, 250) edits) or a
// stride (every underSanitizers(1, 4)th frame). Only for loops whose reduced
// form can still fail; docs/hardening.md lists the tests that use it.
constexpr int underSanitizers(int full, int reduced) { return kAddressSanitizer ? reduced : full; }

// Resource caps for a run, set with setrlimit before grotto starts; 0 = none.
// hangSeconds is a wall-clock guard against a test hanging, not a measurement:
// the run is killed after it.
struct RunLimits {
    int memoryMiB = 0;   // address space (RLIMIT_AS); not under AddressSanitizer
    int cpuSeconds = 0;  // RLIMIT_CPU
    int hangSeconds = 0;
    // The largest file it may write (RLIMIT_FSIZE's soft limit, SIGXFSZ ignored):
    // a write beyond it fails with EFBIG, as a write onto a full disk fails.
    long fileBytes = 0;
};

// Runs the grotto executable with the given arguments (shell-quoted here),
// with `env` ("NAME=value ...") added to its environment.
RunResult runGrotto(const std::string& args, const std::string& env = "", const RunLimits& limits = {});

// Starts the grotto executable in the background with its output discarded, for
// a test that kills it mid-run; returns its process id (the caller waits for it).
int startGrotto(const std::string& args, const std::string& env = "");

// A small filesystem of its own (a tmpfs mounted over a scratch directory) that
// a test can fill up; where mounting is not allowed (not root), mounted() is
// false and reason() says why.
class SmallDisk {
public:
    explicit SmallDisk(size_t bytes);
    ~SmallDisk();
    SmallDisk(const SmallDisk&) = delete;
    SmallDisk& operator=(const SmallDisk&) = delete;
    bool mounted() const { return reason_.empty(); }
    const std::string& reason() const { return reason_; }
    std::filesystem::path operator/(const std::string& name) const { return dir_.path / name; }
    const std::filesystem::path& path() const { return dir_.path; }
    void fillLeaving(size_t bytes);  // a filler file takes all but about `bytes`
    void makeRoom();                 // removes the filler

private:
    ScratchDir dir_;
    std::string reason_;
};

// The source tree's worlds/ directory.
std::filesystem::path worldsDir();

// A file's bytes, all of them (empty when it cannot be read).
std::string fileBytes(const std::filesystem::path& file);

}  // namespace grotto::test
