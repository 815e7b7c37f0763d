#include "app/video_pipe.h"

#include "common/file_kind.h"
#include "grotto/error.h"

#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <sys/prctl.h>
#include <sys/ioctl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <chrono>
#include <cstdlib>
#include <cstring>
#include <sstream>
#include <thread>

extern char** environ;

namespace grotto::app {

namespace fs = std::filesystem;

namespace {

// A program's absolute path, found on PATH; empty when it is not there.
std::string onPath(const std::string& program) {
    const char* path = std::getenv("PATH");
    std::stringstream dirs(path ? path : "/usr/bin:/bin");
    for (std::string dir; std::getline(dirs, dir, ':');) {
        const fs::path candidate = fs::path(dir.empty() ? "." : dir) / program;
        std::error_code ec;
        if (fs::is_regular_file(candidate, ec) && access(candidate.c_str(), X_OK) == 0)
            return fs::absolute(candidate).string();
    }
    return {};
}

// How long ffmpeg may take to accept a write, or to finish once its input ends.
int videoTimeoutSeconds() {
    constexpr int kDefault = 300, kMost = 86400;
    const char* text = std::getenv("GROTTO_VIDEO_TIMEOUT");
    if (!text || !*text) return kDefault;
    char* end = nullptr;
    errno = 0;
    const long seconds = std::strtol(text, &end, 10);
    if (errno != 0 || *end != '\0' || seconds < 1 || seconds > kMost)
        throw Error("GROTTO_VIDEO_TIMEOUT", "'" + std::string(text) + "' is not a number of seconds",
                    "accepted: a whole number from 1 to " + std::to_string(kMost));
    return int(seconds);
}

// ffmpeg reads its input as soon as it starts: one that has taken nothing of the
// first frame by then never will, whatever GROTTO_VIDEO_TIMEOUT allows once it runs.
constexpr int kStartSeconds = 10;

// The bytes written to a pipe that its reader has not taken yet.
size_t unreadBytes(int pipe) {
    int n = 0;
    return ioctl(pipe, FIONREAD, &n) == 0 && n > 0 ? size_t(n) : 0;
}

// The container ffmpeg writes for an extension, and whether it holds VP9 rather than H.264.
struct Container {
    const char* extension;
    const char* muxer;
    bool vp9;
};
constexpr Container kContainers[] = {{".mp4", "mp4", false}, {".mov", "mov", false}, {".mkv", "matroska", false},
                                     {".webm", "webm", true}};

const Container* containerFor(const fs::path& target) {
    const std::string ext = lowerExtension(target);
    for (const Container& c : kContainers)
        if (ext == c.extension) return &c;
    return nullptr;
}

// Starts `args` with stdin, stdout and stderr on these descriptors (-1: /dev/null)
// and SIGPIPE at its default; throws grotto::Error (internal) naming `target`.
// The child dies with the thread that starts it: a killed grotto leaves no
// ffmpeg behind to finish (and, with +faststart, write again) a temporary the
// next run has cleared. Between fork and exec the child does only what is safe
// in a copy of a threaded process.
pid_t spawn(const std::vector<std::string>& args, int in, int out, int err, const fs::path& target) {
    std::vector<char*> argv;
    for (const std::string& a : args) argv.push_back(const_cast<char*>(a.c_str()));
    argv.push_back(nullptr);
    int report[2];  // the child's exec error, if any; closed by a successful exec
    if (pipe2(report, O_CLOEXEC) != 0)
        throw Error::internal(target.string(), "cannot start " + args[0] + ": " + std::strerror(errno));
    const pid_t parent = getpid();
    const pid_t pid = fork();
    if (pid == 0) {
        close(report[0]);
        int error = 0;
        if (prctl(PR_SET_PDEATHSIG, SIGKILL) != 0 || getppid() != parent) _exit(127);
        const int fds[3] = {in, out, err};
        for (int k = 0; k < 3 && error == 0; ++k) {
            const int fd = fds[k] >= 0 ? fds[k] : open("/dev/null", k == 0 ? O_RDONLY : O_WRONLY);
            if (fd < 0 || dup2(fd, k) < 0) error = errno;
        }
        sigset_t none;
        sigemptyset(&none);
        sigprocmask(SIG_SETMASK, &none, nullptr);
        signal(SIGPIPE, SIG_DFL);  // the usual SIGPIPE, whatever grotto does with it
        if (error == 0) {
            execve(argv[0], argv.data(), environ);
            error = errno;
        }
        [[maybe_unused]] const ssize_t n = write(report[1], &error, sizeof error);
        _exit(127);
    }
    const int forkError = errno;
    close(report[1]);
    if (pid < 0) {
        close(report[0]);
        throw Error::internal(target.string(), "cannot start " + args[0] + ": " + std::strerror(forkError));
    }
    int error = 0;
    ssize_t n;
    while ((n = read(report[0], &error, sizeof error)) < 0 && errno == EINTR) {
    }
    close(report[0]);
    if (n > 0) {
        while (waitpid(pid, nullptr, 0) < 0 && errno == EINTR) {
        }
        throw Error::internal(target.string(), "cannot start " + args[0] + ": " + std::strerror(error));
    }
    return pid;
}

// Waits up to `seconds` for `pid` to exit, and kills it when it has not by then.
// Its exit status; -1 when a signal ended it, kTimedOut when it ran out of time.
constexpr int kTimedOut = -2;
int waitFor(pid_t pid, int seconds) {
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(seconds);
    int status = 0;
    for (;;) {
        const pid_t done = waitpid(pid, &status, WNOHANG);
        if (done == pid) return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
        if (done < 0 && errno != EINTR) return -1;
        if (std::chrono::steady_clock::now() >= deadline) {
            kill(pid, SIGKILL);
            while (waitpid(pid, &status, 0) < 0 && errno == EINTR) {
            }
            return kTimedOut;
        }
        std::this_thread::sleep_for(std::chrono::milliseconds(10));
    }
}

}  // namespace

VideoTools findVideoTools(const std::string& option) {
    VideoTools tools{onPath("ffmpeg"), onPath("ffprobe"), videoTimeoutSeconds()};
    if (tools.ffmpeg.empty() || tools.ffprobe.empty())
        throw Error(option, std::string("needs ") + (tools.ffmpeg.empty() ? "ffmpeg" : "ffprobe") + ", which is not on PATH",
                    "install it with apt-get install ffmpeg, or run scripts/setup.sh as root");
    return tools;
}

void requireVideoOutput(const fs::path& target, uint32_t width, uint32_t height, const std::string& option) {
    if (!containerFor(target))
        throw Error(option, "cannot write a video as '" + target.extension().string() + "'",
                    std::string("accepted extensions: ") + kVideoExtensions);
    if (width % 2 != 0 || height % 2 != 0)
        throw Error(option,
                    "needs an even width and height (yuv420p), not " + std::to_string(width) + "x" + std::to_string(height),
                    "choose --size with even numbers, e.g. " + std::to_string(width + width % 2) + "x" +
                        std::to_string(height + height % 2));
    requireOutputPath(target);
}

VideoPipe::VideoPipe(const VideoTools& tools, const fs::path& target, uint32_t width, uint32_t height, int fps, int crf,
                     int first)
    : target_(target), tools_(tools), file_(target),
      frameBytes_(size_t(width) * height * 3), timeoutSeconds_(tools.timeoutSeconds), first_(first), next_(first) {
    const Container* container = containerFor(target);
    if (!container) throw Error::internal(target.string(), "not a video extension");
    // A write to a pipe whose reader has gone raises SIGPIPE, which would end
    // grotto without a word: ignored while the pipe is open, write() reports EPIPE.
    struct sigaction ignore {};
    ignore.sa_handler = SIG_IGN;
    sigemptyset(&ignore.sa_mask);
    sigaction(SIGPIPE, &ignore, &oldPipe_);

    log_ = std::tmpfile();
    int fds[2] = {-1, -1};
    if (!log_ || pipe2(fds, O_CLOEXEC) != 0) {
        if (log_) std::fclose(log_);
        sigaction(SIGPIPE, &oldPipe_, nullptr);
        throw Error::internal(target.string(), std::string("cannot start ffmpeg: ") + std::strerror(errno));
    }
    const std::string size = std::to_string(width) + "x" + std::to_string(height);
    std::vector<std::string> args = {tools.ffmpeg, "-hide_banner", "-loglevel", "error", "-nostdin", "-f", "rawvideo",
                                     "-pixel_format", "rgb24", "-video_size", size, "-framerate", std::to_string(fps),
                                     "-i", "pipe:0", "-an"};
    const std::vector<std::string> codec =
        container->vp9 ? std::vector<std::string>{"-c:v", "libvpx-vp9", "-crf", std::to_string(crf), "-b:v", "0",
                                                  "-row-mt", "1", "-deadline", "good", "-cpu-used", "4"}
                       : std::vector<std::string>{"-c:v", "libx264", "-crf", std::to_string(crf)};
    args.insert(args.end(), codec.begin(), codec.end());
    for (const char* a : {"-vf", "scale=out_color_matrix=bt709:out_range=tv,format=yuv420p", "-colorspace", "bt709",
                          "-color_primaries", "bt709", "-color_trc", "bt709", "-color_range", "tv"})
        args.push_back(a);
    if (std::string(container->muxer) == "mp4" || std::string(container->muxer) == "mov")
        args.insert(args.end(), {"-movflags", "+faststart"});
    args.insert(args.end(), {"-f", container->muxer, "-y", file_.tmp().string()});
    try {
        child_ = spawn(args, fds[0], -1, fileno(log_), target);
    } catch (...) {
        close(fds[0]);
        close(fds[1]);
        std::fclose(log_);
        sigaction(SIGPIPE, &oldPipe_, nullptr);
        throw;
    }
    close(fds[0]);
    input_ = fds[1];
    fcntl(input_, F_SETFL, fcntl(input_, F_GETFL) | O_NONBLOCK);  // writes wait in poll, for a bounded time
}

VideoPipe::~VideoPipe() {
    if (input_ >= 0) close(input_);
    if (child_ > 0) {
        kill(child_, SIGKILL);
        waitFor(child_, timeoutSeconds_);
    }
    if (log_) std::fclose(log_);
    sigaction(SIGPIPE, &oldPipe_, nullptr);
}

void VideoPipe::failed(const std::string& what) {
    if (input_ >= 0) close(input_), input_ = -1;
    if (child_ > 0) status_ = waitFor(child_, timeoutSeconds_), child_ = -1;
    // The end of ffmpeg's (and ffprobe's) messages, on one line.
    std::string tail;
    std::fflush(log_);
    std::rewind(log_);
    for (int c; (c = std::fgetc(log_)) != EOF;) tail += char(c);
    if (tail.size() > 600) tail = "..." + tail.substr(tail.size() - 600);
    std::replace(tail.begin(), tail.end(), '\n', ' ');
    while (!tail.empty() && tail.back() == ' ') tail.pop_back();
    failure_ = what + (status_ > 0 ? " (ffmpeg exit status " + std::to_string(status_) + ")" : "") +
               (tail.empty() ? "" : ": " + tail);
    throw Error::internal(target_.string(), failure_);
}

void VideoPipe::write(const std::vector<uint8_t>& rgb) {
    if (rgb.size() != frameBytes_) throw Error::internal(target_.string(), "a frame of the wrong size");
    size_t done = 0;
    while (done < rgb.size()) {
        const ssize_t n = ::write(input_, rgb.data() + done, rgb.size() - done);
        if (n > 0) {
            done += size_t(n);
            written_ += size_t(n);
        } else if (n < 0 && errno == EAGAIN) {
            pollfd ready{input_, POLLOUT, 0};
            const int seconds = taken() ? timeoutSeconds_ : std::min(timeoutSeconds_, kStartSeconds);
            if (poll(&ready, 1, seconds * 1000) == 0) stalled(seconds);
        } else if (n < 0 && errno != EINTR) {
            failed(errno == EPIPE ? "ffmpeg stopped reading frames"
                                  : std::string("cannot pipe a frame to ffmpeg: ") + std::strerror(errno));
        }
    }
}

void VideoPipe::frame(int index, std::vector<uint8_t> rgb) {
    std::lock_guard lock(mutex_);
    if (input_ < 0) throw Error::internal(target_.string(), failure_.empty() ? "ffmpeg has already failed" : failure_);
    waiting_[index] = std::move(rgb);
    for (auto it = waiting_.begin(); it != waiting_.end() && it->first == next_; it = waiting_.erase(it), ++next_)
        write(it->second);
}

bool VideoPipe::taken() const { return written_ > unreadBytes(input_); }

void VideoPipe::stalled(int seconds) {
    kill(child_, SIGKILL);
    failed(seconds < timeoutSeconds_ ? "ffmpeg read none of its input in the " + std::to_string(seconds) + " s after it started"
                                     : "ffmpeg took no frame data for " + std::to_string(seconds) + " s (GROTTO_VIDEO_TIMEOUT)");
}

void VideoPipe::drain() {
    // Frames that fit in the pipe are written at once: wait until ffmpeg has taken
    // them, within the same bounds as a write, before waiting for it to finish.
    auto progress = std::chrono::steady_clock::now();
    for (size_t unread = unreadBytes(input_), before = unread; unread > 0; before = unread, unread = unreadBytes(input_)) {
        pollfd reader{input_, 0, 0};
        if (poll(&reader, 1, 0) > 0 && (reader.revents & POLLERR)) return;  // ffmpeg has gone: its exit status says why
        if (unread < before) progress = std::chrono::steady_clock::now();
        const int seconds = taken() ? timeoutSeconds_ : std::min(timeoutSeconds_, kStartSeconds);
        if (std::chrono::steady_clock::now() - progress >= std::chrono::seconds(seconds)) stalled(seconds);
        std::this_thread::sleep_for(std::chrono::milliseconds(10));
    }
}

int VideoPipe::probeFrames() {
    std::FILE* out = std::tmpfile();
    if (!out) return -1;
    const pid_t pid = spawn({tools_.ffprobe, "-v", "error", "-select_streams", "v:0", "-count_packets", "-show_entries",
                             "stream=nb_read_packets", "-of", "csv=p=0", file_.tmp().string()},
                            -1, fileno(out), fileno(log_), target_);
    int frames = -1;
    if (waitFor(pid, timeoutSeconds_) != 0 || (std::rewind(out), std::fscanf(out, "%d", &frames)) != 1) frames = -1;
    std::fclose(out);
    return frames;
}

void VideoPipe::finish() {
    std::lock_guard lock(mutex_);
    if (!waiting_.empty()) failed("frame " + std::to_string(next_) + " never came");
    drain();
    close(input_);
    input_ = -1;
    status_ = waitFor(child_, timeoutSeconds_);
    child_ = -1;
    if (status_ == kTimedOut)
        failed("ffmpeg did not finish within " + std::to_string(timeoutSeconds_) + " s (GROTTO_VIDEO_TIMEOUT)");
    if (status_ != 0) failed("ffmpeg failed");
    // ffmpeg has exited 0 leaving a video without its index on a full disk: trust what reads back.
    const int frames = probeFrames(), expected = next_ - first_;
    if (frames != expected)
        failed(frames < 0 ? "the video ffmpeg wrote does not read back"
                          : "the video ffmpeg wrote holds " + std::to_string(frames) + " frames, not " + std::to_string(expected));
    file_.commit();
}

}  // namespace grotto::app
