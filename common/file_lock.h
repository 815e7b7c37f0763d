#pragma once
// An exclusive advisory lock (flock) on a file, held for the object's lifetime:
// runs that share an output directory (render-farm chunks) take turns through it.
#include <filesystem>

namespace grotto {

class FileLock {
public:
    // Creates the file if needed and waits for the lock; throws grotto::Error.
    explicit FileLock(const std::filesystem::path& file);
    ~FileLock();
    FileLock(const FileLock&) = delete;
    FileLock& operator=(const FileLock&) = delete;

    // The lock if nobody holds it now, else false; the file must exist.
    static bool tryHold(const std::filesystem::path& file, int& fd);

private:
    int fd_ = -1;
};

}  // namespace grotto
