#include "tests/test_util.h"

#include <fcntl.h>
#include <sys/mount.h>
#include <sys/resource.h>
#include <sys/statvfs.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cerrno>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <iterator>
#include <sstream>
#include <vector>

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
        if (limits.fileBytes > 0) {
            signal(SIGXFSZ, SIG_IGN);  // kept across exec: a write beyond the limit fails instead of killing
            // The soft limit only (ulimit -S -f): the library raises it, in a
            // child of its own, to write its reader program into memory.
            rlimit l{};
            getrlimit(RLIMIT_FSIZE, &l);
            l.rlim_cur = rlim_t(limits.fileBytes);
            setrlimit(RLIMIT_FSIZE, &l);
        }
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

int startGrotto(const std::string& args, const std::string& env) {
    const std::string cmd = "exec " + (env.empty() ? "" : "env " + env + " ") + std::string(GROTTO_EXE) + " " + args +
                            " >/dev/null 2>&1";
    std::fflush(nullptr);
    const pid_t pid = fork();
    if (pid == 0) {
        execl("/bin/sh", "sh", "-c", cmd.c_str(), static_cast<char*>(nullptr));
        _exit(127);
    }
    return pid;
}

SmallDisk::SmallDisk(size_t bytes) {
    const std::string options = "size=" + std::to_string(bytes);
    if (mount("tmpfs", dir_.path.c_str(), "tmpfs", 0, options.c_str()) != 0)
        reason_ = std::string("cannot mount a tmpfs to fill up (") + std::strerror(errno) + "): run as root to test a full disk";
}

SmallDisk::~SmallDisk() {
    if (mounted()) umount2(dir_.path.c_str(), MNT_DETACH);
}

void SmallDisk::fillLeaving(size_t bytes) {
    struct statvfs fs {};
    statvfs(dir_.path.c_str(), &fs);
    const size_t free = size_t(fs.f_bavail) * fs.f_frsize;
    const int fd = open((dir_.path / ".filler").c_str(), O_WRONLY | O_CREAT | O_APPEND, 0644);
    const std::vector<char> zeros(4096, 0);
    for (size_t left = free > bytes ? free - bytes : 0; left > 0;) {
        const ssize_t n = write(fd, zeros.data(), std::min(left, zeros.size()));
        if (n <= 0) break;
        left -= size_t(n);
    }
    close(fd);
}

void SmallDisk::makeRoom() { fs::remove(dir_.path / ".filler"); }

fs::path worldsDir() { return fs::path(GROTTO_SOURCE_DIR) / "worlds"; }

std::string fileBytes(const std::filesystem::path& file) {
    std::ifstream in(file, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), {}};
}

}  // namespace grotto::test
