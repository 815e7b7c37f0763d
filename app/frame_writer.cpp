#include "app/frame_writer.h"

#include <sys/resource.h>
#include <sys/syscall.h>
#include <unistd.h>

#include <algorithm>

namespace grotto::app {

FrameWriter::FrameWriter(vk::Context& ctx, bool aovs, unsigned threads) {
    for (int k = 0; k < 2; ++k) {
        slots_.push_back(std::make_unique<FrameCopy>(ctx, aovs));
        free_.push_back(slots_.back().get());
    }
    for (unsigned k = 0; k < std::max(threads, 1u); ++k) threads_.emplace_back([this] { work(); });
}

FrameWriter::~FrameWriter() {
    {
        std::lock_guard lock(mutex_);
        stopping_ = true;
        queue_.clear();
    }
    changed_.notify_all();
    for (std::thread& t : threads_) t.join();
}

unsigned FrameWriter::threadsFor(size_t bytesPerFrame) {
    constexpr size_t kBudget = size_t(2) << 30;
    const size_t fit = kBudget / std::max<size_t>(bytesPerFrame, 1);
    return unsigned(std::clamp<size_t>(fit, 1, std::max(std::thread::hardware_concurrency(), 1u)));
}

void FrameWriter::rethrow() {
    if (error_) std::rethrow_exception(error_);
}

void FrameWriter::release(FrameCopy* slot) {
    free_.push_back(slot);
    changed_.notify_all();
}

FrameCopy& FrameWriter::slot() {
    std::unique_lock lock(mutex_);
    changed_.wait(lock, [&] { return error_ || !free_.empty(); });
    rethrow();
    FrameCopy* s = free_.back();
    free_.pop_back();
    return *s;
}

void FrameWriter::submit(FrameCopy& slot, Job job) {
    {
        std::lock_guard lock(mutex_);
        if (error_) {
            release(&slot);
            rethrow();
        }
        queue_.push_back({&slot, std::move(job)});
    }
    changed_.notify_all();
}

void FrameWriter::finish() {
    std::unique_lock lock(mutex_);
    changed_.wait(lock, [&] { return error_ || (queue_.empty() && running_ == 0); });
    if (error_) changed_.wait(lock, [&] { return running_ == 0; });  // no job outlives the run's end
    rethrow();
}

void FrameWriter::work() {
    // Encoding yields the cores to the renderer's threads, which set the pace,
    // and takes what they leave (the lowest priority: nice 19, this thread only).
    // Where it cannot be lowered the thread keeps the process's priority.
    setpriority(PRIO_PROCESS, id_t(syscall(SYS_gettid)), 19);
    std::unique_lock lock(mutex_);
    for (;;) {
        changed_.wait(lock, [&] { return stopping_ || !queue_.empty(); });
        if (queue_.empty()) return;  // stopping
        Item item = std::move(queue_.front());
        queue_.pop_front();
        if (error_) {  // a frame before failed: the run fails, write nothing more
            release(item.slot);
            continue;
        }
        ++running_;
        lock.unlock();
        bool released = false;
        try {
            const FrameImages frame = item.slot->decode();
            lock.lock();
            release(item.slot);
            released = true;
            lock.unlock();
            item.job(frame);
            lock.lock();
        } catch (...) {
            if (!lock.owns_lock()) lock.lock();
            if (!released) release(item.slot);
            if (!error_) error_ = std::current_exception();
        }
        --running_;
        changed_.notify_all();
    }
}

}  // namespace grotto::app
