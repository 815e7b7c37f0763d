#pragma once
// Writes a flythrough's frames on worker threads while the main thread renders
// the next ones. A frame is read back through one of two FrameCopy slots, which
// the renderer fills in the frame's own command buffer (double-buffered
// read-back); a worker decodes the slot, hands it back for the frame after next,
// then encodes and writes the frame. At most two frames wait in slots and
// `threads` are being encoded, so memory stays bounded however slow the disk.
// The workers run at the lowest CPU priority: the renderer sets the pace, and
// encoding takes the cores it leaves.
// The first error a job throws is rethrown on the main thread by the next call,
// and jobs not yet started are then dropped.
#include "engine/frame/frame_copy.h"

#include <condition_variable>
#include <deque>
#include <exception>
#include <functional>
#include <memory>
#include <mutex>
#include <thread>
#include <vector>

namespace grotto::app {

class FrameWriter {
public:
    using Job = std::function<void(const FrameImages&)>;

    // `aovs`: the slots copy the AOVs too.
    FrameWriter(vk::Context& ctx, bool aovs, unsigned threads);
    ~FrameWriter();  // waits for the jobs running; drops those not started
    FrameWriter(const FrameWriter&) = delete;
    FrameWriter& operator=(const FrameWriter&) = delete;

    // A free slot for the next frame's copy, waiting for one.
    FrameCopy& slot();
    // Hands `slot`, filled by Renderer::render, to a worker that decodes it,
    // frees it and runs `job` on the images.
    void submit(FrameCopy& slot, Job job);
    // Waits until every job has run.
    void finish();

    // One thread per core, at least one, and no more than keep frames of
    // `bytesPerFrame` (decoded and encoded) within a fixed budget of memory.
    static unsigned threadsFor(size_t bytesPerFrame);

private:
    struct Item {
        FrameCopy* slot;
        Job job;
    };
    void work();
    void release(FrameCopy* slot);  // with the mutex held
    void rethrow();                 // with the mutex held

    std::vector<std::unique_ptr<FrameCopy>> slots_;
    std::vector<FrameCopy*> free_;
    std::deque<Item> queue_;
    int running_ = 0;
    bool stopping_ = false;
    std::exception_ptr error_;
    std::mutex mutex_;
    std::condition_variable changed_;
    std::vector<std::thread> threads_;
};

}  // namespace grotto::app
