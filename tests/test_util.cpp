#include "tests/test_util.h"

#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <cstdio>
#include <fstream>
#include <sstream>

namespace grotto::test {
namespace fs = std::filesystem;

ScratchDir::ScratchDir() {
    static std::atomic<int> counter{0};
    path = fs::temp_directory_path() /
           ("grotto-test-" + std::to_string(getpid()) + "-" + std::to_string(counter++));
    fs::remove_all(path);
    fs::create_directories(path);
}

ScratchDir::~ScratchDir() {
    std::error_code ec;
    fs::remove_all(path, ec);
}

RunResult runGrotto(const std::string& args, const std::string& env, const RunLimits& limits) {
    ScratchDir dir;
    const fs::path out = dir / "stdout", err = dir / "stderr";
    const std::string guard = limits.hangSeconds > 0 ? "timeout -s KILL " + std::to_string(limits.hangSeconds) + " " : "";
    const std::string cmd = "exec " + (env.empty() ? "" : "env " + env + " ") + guard + std::string(GROTTO_EXE) + " " + args +
                            " >" + out.string() + " 2>" + err.string();
    RunResult r;
    std::fflush(nullptr);
    const pid_t pid = fork();
    if (pid == 0) {
        auto cap = [](int resource, rlim_t value) {
            const rlimit l{value, value};
            setrlimit(resource, &l);
        };
        if (limits.memoryMiB > 0 && !kAddressSanitizer) cap(RLIMIT_AS, rlim_t(limits.memoryMiB) << 20);
        if (limits.cpuSeconds > 0) cap(RLIMIT_CPU, rlim_t(limits.cpuSeconds));
        execl("/bin/sh", "sh", "-c", cmd.c_str(), static_cast<char*>(nullptr));
        _exit(127);
    }
    int status = 0;
    rusage usage{};
    while (wait4(pid, &status, 0, &usage) < 0 && errno == EINTR) {}
    r.exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    r.peakMiB = double(usage.ru_maxrss) / 1024.0;  // kilobytes on Linux
    auto slurp = [](const fs::path& p) {
        std::ifstream in(p);
        std::stringstream ss;
        ss << in.rdbuf();
        return ss.str();
    };
    r.out = slurp(out);
    r.err = slurp(err);
    return r;
}

fs::path worldsDir() { return fs::path(GROTTO_SOURCE_DIR) / "worlds"; }

}  // namespace grotto::test
