#pragma once
// An advisory lock (flock) on a file, held for the object's lifetime: runs that
// share an output directory (render-farm chunks) take turns through an exclusive
// one, and say they are alive with a shared one.
#include <filesystem>

namespace grotto {

class FileLock {
public:
    enum class Mode { Exclusive, Shared };
    // Waits for the lock; throws grotto::Error. An exclusive lock creates the
    // file if needed; a shared one needs it there.
    explicit FileLock(const std::filesystem::path& file, Mode mode = Mode::Exclusive);
    ~FileLock();
    FileLock(FileLock&& other) noexcept;
    FileLock(const FileLock&) = delete;
    FileLock& operator=(const FileLock&) = delete;
    FileLock& operator=(FileLock&&) = delete;

    // The lock if nobody holds it now, else false; the file must exist.
    static bool tryHold(const std::filesystem::path& file, int& fd);
    // Whether another open file holds a lock on `file` (shared or exclusive) now;
    // false when the file does not exist.
    static bool heldElsewhere(const std::filesystem::path& file);

private:
    int fd_ = -1;
};

}  // namespace grotto
