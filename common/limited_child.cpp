#include "limited_child.h"

#include "error.h"

#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <new>

namespace grotto {
namespace {

size_t g_inheritedBytes = 0;  // the child's address space when it started
size_t g_allowedBytes = 0;    // what it may add to that now

size_t addressSpaceBytes() {
    unsigned long pages = 0;
    if (std::FILE* f = std::fopen("/proc/self/statm", "r")) {
        if (std::fscanf(f, "%lu", &pages) != 1) pages = 0;
        std::fclose(f);
    }
    return size_t(pages) * size_t(sysconf(_SC_PAGESIZE));
}

void limitAddressSpace(size_t extra) {
    g_allowedBytes = extra;
    rlimit r{};
    getrlimit(RLIMIT_AS, &r);
    rlim_t want = rlim_t(g_inheritedBytes + extra);
    if (r.rlim_max != RLIM_INFINITY && want > r.rlim_max) want = r.rlim_max;
    r.rlim_cur = want;
    setrlimit(RLIMIT_AS, &r);
}

std::string mib(size_t bytes) { return std::to_string((bytes + (1 << 20) - 1) >> 20) + " MiB"; }

// The child's report on the pipe: a kind letter, then where, what and hint, NUL-separated.
void report(int fd, char kind, const std::string& where = {}, const std::string& what = {},
            const std::string& hint = {}) {
    std::string msg(1, kind);
    msg += where + '\0' + what + '\0' + hint;
    for (size_t done = 0; done < msg.size();) {
        const ssize_t n = write(fd, msg.data() + done, msg.size() - done);
        if (n <= 0 && errno != EINTR) break;
        if (n > 0) done += size_t(n);
    }
}

[[noreturn]] void runChild(int fd, const ChildLimits& limits, const std::function<void()>& work) {
    // What the child prints (a library's warnings, a sanitizer's report) is not
    // the user's business: the parent turns the outcome into one line.
    if (std::FILE* null = std::freopen("/dev/null", "w", stderr); !null) {}
    g_inheritedBytes = addressSpaceBytes();
    limitAddressSpace(limits.memoryBytes);
    rlimit cpu{};
    getrlimit(RLIMIT_CPU, &cpu);
    const rlim_t soft = rlim_t(limits.cpuSeconds);
    if (cpu.rlim_max == RLIM_INFINITY || soft < cpu.rlim_max) {
        cpu.rlim_cur = soft;
        cpu.rlim_max = soft + 1;  // SIGXCPU at the soft limit, SIGKILL a second later
        setrlimit(RLIMIT_CPU, &cpu);
    }
    try {
        work();
        report(fd, 'K');
    } catch (const Error& e) {
        report(fd, "IXR"[int(e.kind())], e.where(), e.problem(), e.hint());
    } catch (const std::bad_alloc&) {
        report(fd, 'M', {}, std::to_string(g_allowedBytes));
    } catch (const std::exception& e) {
        report(fd, 'E', {}, e.what());
    } catch (...) {
        report(fd, 'E', {}, "unknown exception");
    }
    _exit(0);  // no destructors, atexit handlers or leak checks of the parent's state
}

}  // namespace

void allowChildMemory(size_t bytes) {
    if (g_inheritedBytes > 0 && bytes > g_allowedBytes) limitAddressSpace(bytes);  // in a child only
}

void runInLimitedChild(const std::string& where, const ChildLimits& limits, const std::function<void()>& work) {
    int fds[2];
    if (pipe2(fds, O_CLOEXEC) != 0) throw Error::internal(where, "cannot create a pipe to a reader process");
    std::fflush(nullptr);
    const pid_t pid = fork();
    if (pid < 0) {
        close(fds[0]);
        close(fds[1]);
        throw Error::internal(where, "cannot start a reader process");
    }
    if (pid == 0) {
        close(fds[0]);
        runChild(fds[1], limits, work);
    }
    close(fds[1]);
    // The child's CPU limit stops a spinning parse; this stops one that waits on
    // something forever (it uses no CPU meanwhile).
    const int waitMs = (limits.cpuSeconds * 10 + 10) * 1000;
    std::string msg;
    bool timedOut = false;
    for (char buf[4096];;) {
        pollfd p{fds[0], POLLIN, 0};
        const int ready = poll(&p, 1, waitMs);
        if (ready < 0 && errno == EINTR) continue;
        if (ready == 0) {
            timedOut = true;
            kill(pid, SIGKILL);
            break;
        }
        const ssize_t n = read(fds[0], buf, sizeof buf);
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) break;
        msg.append(buf, size_t(n));
    }
    close(fds[0]);
    int status = 0;
    while (waitpid(pid, &status, 0) < 0 && errno == EINTR) {}

    const std::string damaged = "the file is damaged, truncated or not what it claims to be";
    if (timedOut) throw Error::internal(where, "reading it stalled for " + std::to_string(waitMs / 1000) + " s");
    if (msg.empty()) {
        const int sig = WIFSIGNALED(status) ? WTERMSIG(status) : 0;
        if (sig == SIGXCPU || sig == SIGKILL)
            throw Error(where, "reading it took more than " + std::to_string(limits.cpuSeconds) + " s of CPU time",
                        damaged);
        // An allocator that aborts rather than throwing (a sanitizer's) ends here too.
        throw Error(where, "reading it failed within " + mib(limits.memoryBytes) + " of memory and " +
                               std::to_string(limits.cpuSeconds) + " s of CPU time" +
                               (sig ? " (signal " + std::to_string(sig) + ")" : ""),
                    damaged);
    }
    const char kind = msg[0];
    std::string parts[3];
    size_t at = 1;
    for (std::string& part : parts) {
        const size_t end = std::min(msg.find('\0', at), msg.size());
        part = msg.substr(at, end - at);
        at = end + 1;
    }
    switch (kind) {
        case 'K': return;
        case 'I': throw Error(parts[0], parts[1], parts[2]);
        case 'X': throw Error::internal(parts[0], parts[1], parts[2]);
        case 'R': throw Error::regression(parts[0], parts[1], parts[2]);
        case 'M':
            throw Error(where, "reading it needed more than the " + mib(std::stoull(parts[1])) + " of memory allowed for it",
                        damaged);
        default: throw Error(where, "cannot be read: " + parts[1], damaged);
    }
}

}  // namespace grotto
