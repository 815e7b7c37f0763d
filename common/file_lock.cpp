#include "file_lock.h"

#include "grotto/error.h"

#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <utility>

namespace grotto {

FileLock::FileLock(const std::filesystem::path& file, Mode mode) {
    // Shared: read-only, so another user's file (a farm's) can be held too.
    fd_ = mode == Mode::Shared ? open(file.c_str(), O_RDONLY | O_CLOEXEC)
                               : open(file.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644);
    if (fd_ < 0) throw Error(file.string(), std::string("cannot be opened as a lock: ") + std::strerror(errno));
    while (flock(fd_, mode == Mode::Shared ? LOCK_SH : LOCK_EX) != 0)
        if (errno != EINTR) {
            const int err = errno;
            close(fd_);
            throw Error(file.string(), std::string("cannot be locked: ") + std::strerror(err));
        }
}

FileLock::FileLock(FileLock&& other) noexcept : fd_(std::exchange(other.fd_, -1)) {}

FileLock::~FileLock() {
    if (fd_ >= 0) close(fd_);  // closing releases the lock
}

bool FileLock::tryHold(const std::filesystem::path& file, int& fd) {
    fd = open(file.c_str(), O_RDONLY | O_CLOEXEC);
    if (fd < 0) return false;
    if (flock(fd, LOCK_EX | LOCK_NB) == 0) return true;
    close(fd);
    fd = -1;
    return false;
}

bool FileLock::heldElsewhere(const std::filesystem::path& file) {
    // Read-write where allowed: on NFS flock becomes a POSIX lock, whose exclusive kind needs it.
    int fd = open(file.c_str(), O_RDWR | O_CLOEXEC);
    if (fd < 0) fd = open(file.c_str(), O_RDONLY | O_CLOEXEC);
    if (fd < 0) return false;
    const bool held = flock(fd, LOCK_EX | LOCK_NB) != 0 && errno == EWOULDBLOCK;
    close(fd);  // releases it if it was taken
    return held;
}

}  // namespace grotto
