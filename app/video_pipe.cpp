#include "app/video_pipe.h"

#include "common/error.h"

#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <sstream>

extern char** environ;

namespace grotto::app {

namespace fs = std::filesystem;

std::string findFfmpeg(const std::string& option) {
    const char* path = std::getenv("PATH");
    std::stringstream dirs(path ? path : "/usr/bin:/bin");
    for (std::string dir; std::getline(dirs, dir, ':');) {
        const fs::path candidate = fs::path(dir.empty() ? "." : dir) / "ffmpeg";
        std::error_code ec;
        if (fs::is_regular_file(candidate, ec) && access(candidate.c_str(), X_OK) == 0)
            return fs::absolute(candidate).string();
    }
    throw Error(option, "needs ffmpeg, which is not on PATH",
                "install it with apt-get install ffmpeg, or run scripts/setup.sh as root");
}

void requireVideoSize(uint32_t width, uint32_t height, const std::string& option) {
    if (width % 2 == 0 && height % 2 == 0) return;
    throw Error(option, "needs an even width and height (yuv420p), not " + std::to_string(width) + "x" + std::to_string(height),
                "choose --size with even numbers, e.g. " + std::to_string(width + width % 2) + "x" +
                    std::to_string(height + height % 2));
}

VideoPipe::VideoPipe(const std::string& ffmpeg, const fs::path& target, uint32_t width, uint32_t height, int fps,
                     int crf, int first)
    : target_(target), file_(target), frameBytes_(size_t(width) * height * 3), next_(first) {
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
    const std::vector<std::string> args = {
        ffmpeg, "-hide_banner", "-loglevel", "error", "-nostdin", "-f", "rawvideo", "-pixel_format", "rgb24",
        "-video_size", size, "-framerate", std::to_string(fps), "-i", "pipe:0", "-an", "-c:v", "libx264",
        "-crf", std::to_string(crf), "-vf", "scale=out_color_matrix=bt709:out_range=tv,format=yuv420p",
        "-colorspace", "bt709", "-color_primaries", "bt709", "-color_trc", "bt709", "-color_range", "tv",
        "-movflags", "+faststart", "-f", "mp4", "-y", file_.tmp().string()};
    std::vector<char*> argv;
    for (const std::string& a : args) argv.push_back(const_cast<char*>(a.c_str()));
    argv.push_back(nullptr);

    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    posix_spawn_file_actions_adddup2(&actions, fds[0], 0);
    posix_spawn_file_actions_addopen(&actions, 1, "/dev/null", O_WRONLY, 0);
    posix_spawn_file_actions_adddup2(&actions, fileno(log_), 2);
    posix_spawnattr_t attr;
    posix_spawnattr_init(&attr);
    sigset_t none, pipeSignal;
    sigemptyset(&none);
    sigemptyset(&pipeSignal);
    sigaddset(&pipeSignal, SIGPIPE);
    posix_spawnattr_setsigmask(&attr, &none);
    posix_spawnattr_setsigdefault(&attr, &pipeSignal);  // ffmpeg gets the usual SIGPIPE
    posix_spawnattr_setflags(&attr, POSIX_SPAWN_SETSIGMASK | POSIX_SPAWN_SETSIGDEF);
    const int spawned = posix_spawn(&child_, ffmpeg.c_str(), &actions, &attr, argv.data(), environ);
    posix_spawn_file_actions_destroy(&actions);
    posix_spawnattr_destroy(&attr);
    close(fds[0]);
    if (spawned != 0) {
        close(fds[1]);
        std::fclose(log_);
        sigaction(SIGPIPE, &oldPipe_, nullptr);
        throw Error::internal(target.string(), "cannot start " + ffmpeg + ": " + std::strerror(spawned));
    }
    input_ = fds[1];
}

VideoPipe::~VideoPipe() {
    if (input_ >= 0) close(input_);
    if (child_ > 0) {
        kill(child_, SIGTERM);
        wait();
    }
    if (log_) std::fclose(log_);
    sigaction(SIGPIPE, &oldPipe_, nullptr);
}

int VideoPipe::wait() {
    int status = 0;
    while (waitpid(child_, &status, 0) < 0 && errno == EINTR) {
    }
    child_ = -1;
    return status_ = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

void VideoPipe::failed(const std::string& what) {
    if (input_ >= 0) close(input_), input_ = -1;
    const int status = child_ > 0 ? wait() : status_;
    // The end of ffmpeg's messages, on one line.
    std::string tail;
    std::fflush(log_);
    std::rewind(log_);
    for (int c; (c = std::fgetc(log_)) != EOF;) tail += char(c);
    if (tail.size() > 600) tail = "..." + tail.substr(tail.size() - 600);
    std::replace(tail.begin(), tail.end(), '\n', ' ');
    while (!tail.empty() && tail.back() == ' ') tail.pop_back();
    throw Error::internal(target_.string(), what + (status > 0 ? " (ffmpeg exit status " + std::to_string(status) + ")" : "") +
                                                (tail.empty() ? "" : ": " + tail));
}

void VideoPipe::write(const std::vector<uint8_t>& rgb) {
    if (rgb.size() != frameBytes_) throw Error::internal(target_.string(), "a frame of the wrong size");
    size_t done = 0;
    while (done < rgb.size()) {
        const ssize_t n = ::write(input_, rgb.data() + done, rgb.size() - done);
        if (n < 0 && errno == EINTR) continue;
        if (n < 0) failed(errno == EPIPE ? "ffmpeg stopped reading frames" : std::string("cannot pipe a frame to ffmpeg: ") + std::strerror(errno));
        done += size_t(n);
    }
}

void VideoPipe::frame(int index, std::vector<uint8_t> rgb) {
    std::lock_guard lock(mutex_);
    if (input_ < 0) throw Error::internal(target_.string(), "ffmpeg has already failed");
    waiting_[index] = std::move(rgb);
    for (auto it = waiting_.begin(); it != waiting_.end() && it->first == next_; it = waiting_.erase(it), ++next_)
        write(it->second);
}

void VideoPipe::finish() {
    std::lock_guard lock(mutex_);
    if (!waiting_.empty()) failed("frame " + std::to_string(next_) + " never came");
    close(input_);
    input_ = -1;
    if (wait() != 0) failed("ffmpeg failed");
    file_.commit();
}

}  // namespace grotto::app
