#include "limited_child.h"

#include "grotto/error.h"

#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <spawn.h>
#include <sys/mman.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <new>

extern char** environ;

namespace grotto {
namespace {

// The child's descriptors: what it reads, and where it reports.
constexpr int kInputFd = 3;
constexpr int kReportFd = 4;

size_t g_startBytes = 0;    // the child's address space when it started
size_t g_allowedBytes = 0;  // what it may add to that now

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
    rlim_t want = rlim_t(g_startBytes + extra);
    if (r.rlim_max != RLIM_INFINITY && want > r.rlim_max) want = r.rlim_max;
    r.rlim_cur = want;
    setrlimit(RLIMIT_AS, &r);
}

void limitCpu(int seconds) {
    rlimit cpu{};
    getrlimit(RLIMIT_CPU, &cpu);
    const rlim_t soft = rlim_t(seconds);
    if (cpu.rlim_max == RLIM_INFINITY || soft < cpu.rlim_max) {
        cpu.rlim_cur = soft;
        cpu.rlim_max = soft + 1;  // SIGXCPU at the soft limit, SIGKILL a second later
        setrlimit(RLIMIT_CPU, &cpu);
    }
}

std::string mib(size_t bytes) { return std::to_string((bytes + (1 << 20) - 1) >> 20) + " MiB"; }

// The child's report: a kind letter, then where, what and hint, NUL-separated.
void report(char kind, const std::string& where = {}, const std::string& what = {}, const std::string& hint = {}) {
    std::string msg(1, kind);
    msg += where + '\0' + what + '\0' + hint;
    for (size_t done = 0; done < msg.size();) {
        const ssize_t n = write(kReportFd, msg.data() + done, msg.size() - done);
        if (n <= 0 && errno != EINTR) break;
        if (n > 0) done += size_t(n);
    }
}

// A copy of fd numbered above the child's fixed descriptors, so that placing
// those cannot overwrite it (the original is closed).
int aboveChildFds(int fd) {
    const int high = fd < 0 ? -1 : fcntl(fd, F_DUPFD_CLOEXEC, kReportFd + 1);
    if (fd >= 0) close(fd);
    return high;
}

// Writes all of `bytes` to fd from its start; 0 or an errno. Safe after a fork.
int writeAll(int fd, std::span<const unsigned char> bytes) {
    for (size_t done = 0; done < bytes.size();) {
        const ssize_t n = pwrite(fd, bytes.data() + done, bytes.size() - done, off_t(done));
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) return n < 0 ? errno : EIO;
        done += size_t(n);
    }
    return 0;
}

// A file-size limit (ulimit -f) applies to memory files too. Below the program's
// size, a child writes it with its own limit raised to the hard one (it calls
// only what is safe after a fork; the parent's limit stays as its user set it).
int writeProgram(int fd, std::span<const unsigned char> program) {
    rlimit r{};
    getrlimit(RLIMIT_FSIZE, &r);
    if (r.rlim_cur == RLIM_INFINITY || r.rlim_cur >= program.size()) return writeAll(fd, program);
    const pid_t pid = fork();
    if (pid < 0) return errno;
    if (pid == 0) {
        r.rlim_cur = r.rlim_max;
        setrlimit(RLIMIT_FSIZE, &r);
        _exit(writeAll(fd, program));
    }
    int status = 0;
    while (waitpid(pid, &status, 0) < 0 && errno == EINTR) {}
    return WIFEXITED(status) ? WEXITSTATUS(status) : EFBIG;  // killed: by SIGXFSZ, past the hard limit
}

// The program's bytes as a file that can be executed (sealed: nothing changes it).
int programFile(const std::string& where, std::span<const unsigned char> program) {
    const int fd = aboveChildFds(memfd_create("grotto-reader", MFD_CLOEXEC | MFD_ALLOW_SEALING));
    if (fd < 0) throw Error::internal(where, std::string("cannot create the reader program: ") + std::strerror(errno));
    if (const int err = writeProgram(fd, program)) {
        close(fd);
        throw Error::internal(where, std::string("cannot write the reader program to memory: ") + std::strerror(err));
    }
    fcntl(fd, F_ADD_SEALS, F_SEAL_SHRINK | F_SEAL_GROW | F_SEAL_WRITE | F_SEAL_SEAL);
    return fd;
}

pid_t spawn(const std::string& where, int programFd, int input, int reportWrite, const std::vector<std::string>& argv) {
    const std::string path = "/proc/self/fd/" + std::to_string(programFd);
    std::vector<char*> args;
    for (const std::string& a : argv) args.push_back(const_cast<char*>(a.c_str()));
    args.push_back(nullptr);
    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    posix_spawn_file_actions_adddup2(&actions, input, kInputFd);
    posix_spawn_file_actions_adddup2(&actions, reportWrite, kReportFd);
    // What the child prints (a library's warnings, a sanitizer's report) is not
    // the user's business: the parent turns the outcome into one line.
    posix_spawn_file_actions_addopen(&actions, STDOUT_FILENO, "/dev/null", O_WRONLY, 0);
    posix_spawn_file_actions_addopen(&actions, STDERR_FILENO, "/dev/null", O_WRONLY, 0);
    pid_t pid = -1;
    const int err = posix_spawn(&pid, path.c_str(), &actions, nullptr, args.data(), environ);
    posix_spawn_file_actions_destroy(&actions);
    if (err != 0) throw Error::internal(where, std::string("cannot start a reader process: ") + std::strerror(err));
    return pid;
}

}  // namespace

void allowChildMemory(size_t bytes) {
    if (g_startBytes > 0 && bytes > g_allowedBytes) limitAddressSpace(bytes);  // in a child only
}

void serveAsLimitedChild(int argc, char** argv, const std::function<void(const std::vector<std::string>&)>& work) {
    try {
        if (argc < 3) throw Error::internal(argc > 0 ? argv[0] : "reader", "started without its limits");
        g_startBytes = addressSpaceBytes();
        limitAddressSpace(std::stoull(argv[1]));
        limitCpu(std::stoi(argv[2]));
        work(std::vector<std::string>(argv + 3, argv + argc));
        report('K');
    } catch (const Error& e) {
        report("IXR"[int(e.kind())], e.where(), e.problem(), e.hint());
    } catch (const std::bad_alloc&) {
        report('M', {}, std::to_string(g_allowedBytes));
    } catch (const std::exception& e) {
        report('E', {}, e.what());
    } catch (...) {
        report('E', {}, "unknown exception");
    }
    _exit(0);  // no destructors, atexit handlers or leak checks of what the reading left
}

void runInLimitedChild(const std::string& where, const ChildLimits& limits, std::span<const unsigned char> program,
                       const std::vector<std::string>& args, int input) {
    const int programFd = programFile(where, program);
    int fds[2];
    if (pipe2(fds, O_CLOEXEC) != 0) {
        close(programFd);
        throw Error::internal(where, "cannot create a pipe to a reader process");
    }
    const int inputFd = aboveChildFds(fcntl(input, F_DUPFD_CLOEXEC, 0)), reportWrite = aboveChildFds(fds[1]);
    std::vector<std::string> argv = {"grotto-reader", std::to_string(limits.memoryBytes),
                                     std::to_string(limits.cpuSeconds)};
    argv.insert(argv.end(), args.begin(), args.end());
    pid_t pid = -1;
    try {
        if (inputFd < 0 || reportWrite < 0) throw Error::internal(where, "cannot pass descriptors to a reader process");
        pid = spawn(where, programFd, inputFd, reportWrite, argv);
    } catch (...) {
        for (int fd : {programFd, inputFd, reportWrite, fds[0]})
            if (fd >= 0) close(fd);
        throw;
    }
    for (int fd : {programFd, inputFd, reportWrite}) close(fd);
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
        if (WIFEXITED(status) && WEXITSTATUS(status) == 127)
            throw Error::internal(where, "the reader process could not run");
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
