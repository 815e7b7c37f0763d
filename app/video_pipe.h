#pragma once
// A video of a flythrough's frames: their 8-bit sRGB pixels (the PNG's) piped
// as raw RGB to Debian's ffmpeg, encoded with libx264 at a constant rate factor
// into yuv420p (BT.709), written under a temporary name beside the target and
// renamed into place only when ffmpeg exits 0, so nothing half-written is ever
// left under the target's name.
#include "common/atomic_file.h"

#include <sys/types.h>

#include <csignal>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <map>
#include <mutex>
#include <string>
#include <vector>

namespace grotto::app {

// ffmpeg's absolute path, found on PATH; throws grotto::Error (input) naming
// `option` and how to install it when it is not there.
std::string findFfmpeg(const std::string& option = "--video");

// Throws grotto::Error (input) naming `option` unless a video of this size can
// be made: yuv420p halves the chroma both ways, so both must be even.
void requireVideoSize(uint32_t width, uint32_t height, const std::string& option = "--video");

class VideoPipe {
public:
    // Starts ffmpeg writing the video of frames `first` on, at `fps` frames a
    // second, constant rate factor `crf` (0 best to 51 worst).
    VideoPipe(const std::string& ffmpeg, const std::filesystem::path& target, uint32_t width, uint32_t height,
              int fps, int crf, int first);
    ~VideoPipe();  // without finish(): stops ffmpeg and removes the temporary file
    VideoPipe(const VideoPipe&) = delete;
    VideoPipe& operator=(const VideoPipe&) = delete;

    // Frame `index`'s pixels, 3 bytes a pixel, row 0 on top. Frames may come in
    // any order from any thread; each is piped once the ones before it have been.
    // Throws grotto::Error (internal) with the end of ffmpeg's messages when it
    // has stopped reading.
    void frame(int index, std::vector<uint8_t> rgb);
    // Ends the input, waits for ffmpeg and renames the video into place; throws
    // like frame() when ffmpeg failed or frames are missing.
    void finish();

private:
    void write(const std::vector<uint8_t>& rgb);  // with the mutex held
    [[noreturn]] void failed(const std::string& what);
    int wait();  // ffmpeg's exit status (-1: killed by a signal), kept in status_

    std::filesystem::path target_;
    PendingFile file_;
    size_t frameBytes_;
    pid_t child_ = -1;
    int status_ = 0;
    int input_ = -1;            // the pipe to ffmpeg's stdin
    std::FILE* log_ = nullptr;  // ffmpeg's stderr, an unnamed temporary file
    int next_;                  // the next frame to pipe
    std::map<int, std::vector<uint8_t>> waiting_;
    std::mutex mutex_;
    struct sigaction oldPipe_ {};
};

}  // namespace grotto::app
