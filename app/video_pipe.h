#pragma once
// A video of a flythrough's frames: their 8-bit sRGB pixels (the PNG's) piped
// as raw RGB to Debian's ffmpeg, encoded at a constant rate factor into yuv420p
// (BT.709) in the container the file's extension names, written under a
// temporary name beside the target and renamed into place only when ffmpeg
// exits 0 and ffprobe finds every frame in what it wrote, so nothing
// half-written is ever left under the target's name. ffmpeg gets a bounded time
// (GROTTO_VIDEO_TIMEOUT seconds, 300 by default) to take each part of a frame and
// to finish, and 10 s (or that, if less) to take the first of them, so one that
// stops reading or never starts cannot hold the run.
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

// The programs a video needs: ffmpeg encodes it, ffprobe checks what it wrote;
// and how long either may take to read a frame or to finish.
struct VideoTools {
    std::string ffmpeg, ffprobe;
    int timeoutSeconds;
};

// Both found on PATH, the time from GROTTO_VIDEO_TIMEOUT; throws grotto::Error
// (input) naming `option` and how to install them when either is not there,
// naming GROTTO_VIDEO_TIMEOUT when it is not a number of seconds.
VideoTools findVideoTools(const std::string& option = "--video");

// The extensions a video can be written as: .mp4, .mov and .mkv (H.264), .webm (VP9).
inline constexpr const char* kVideoExtensions = ".mp4, .mov, .mkv, .webm";

// Throws grotto::Error (input) naming `option` unless a video of this size can
// be written as `target`: an extension of kVideoExtensions, an even width and
// height (yuv420p halves the chroma both ways) and a path requireOutputPath takes.
void requireVideoOutput(const std::filesystem::path& target, uint32_t width, uint32_t height,
                        const std::string& option = "--video");

class VideoPipe {
public:
    // Starts ffmpeg writing the video of frames `first` on, at `fps` frames a
    // second, constant rate factor `crf` (0 best to 51 worst).
    VideoPipe(const VideoTools& tools, const std::filesystem::path& target, uint32_t width, uint32_t height, int fps,
              int crf, int first);
    ~VideoPipe();  // without finish(): stops ffmpeg and removes the temporary file
    VideoPipe(const VideoPipe&) = delete;
    VideoPipe& operator=(const VideoPipe&) = delete;

    // Frame `index`'s pixels, 3 bytes a pixel, row 0 on top. Frames may come in
    // any order from any thread; each is piped once the ones before it have been.
    // Throws grotto::Error (internal) with the end of ffmpeg's messages when it
    // has stopped reading.
    void frame(int index, std::vector<uint8_t> rgb);
    // Ends the input, waits for ffmpeg, checks the video holds every frame and
    // renames it into place; throws like frame() when ffmpeg failed, frames are
    // missing or the video does not read back.
    void finish();

private:
    void write(const std::vector<uint8_t>& rgb);  // with the mutex held
    bool taken() const;                           // has ffmpeg read any of the frames yet?
    [[noreturn]] void stalled(int seconds);       // stops ffmpeg: it took nothing for that long
    void drain();                                 // waits (bounded) for ffmpeg to take what the pipe holds
    [[noreturn]] void failed(const std::string& what);
    int probeFrames();  // frames ffprobe counts in the temporary file, -1 when it cannot read it

    std::filesystem::path target_;
    VideoTools tools_;
    PendingFile file_;
    size_t frameBytes_;
    int timeoutSeconds_;
    pid_t child_ = -1;
    int status_ = 0;
    std::string failure_;  // the first failure's message: later frames report it too, whichever thread sees them
    int input_ = -1;            // the pipe to ffmpeg's stdin
    size_t written_ = 0;        // bytes written to it
    std::FILE* log_ = nullptr;  // ffmpeg's stderr, an unnamed temporary file
    int first_, next_;          // the first frame, the next frame to pipe
    std::map<int, std::vector<uint8_t>> waiting_;
    std::mutex mutex_;
    struct sigaction oldPipe_ {};
};

}  // namespace grotto::app
