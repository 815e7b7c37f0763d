#include "file_lock.h"

#include "grotto/error.h"

#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

namespace grotto {

FileLock::FileLock(const std::filesystem::path& file) {
    fd_ = open(file.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644);
    if (fd_ < 0) throw Error(file.string(), std::string("cannot be opened as a lock: ") + std::strerror(errno));
    while (flock(fd_, LOCK_EX) != 0)
        if (errno != EINTR) {
            const int err = errno;
            close(fd_);
            throw Error(file.string(), std::string("cannot be locked: ") + std::strerror(err));
        }
}

FileLock::~FileLock() { close(fd_); }  // closing releases the lock

bool FileLock::tryHold(const std::filesystem::path& file, int& fd) {
    fd = open(file.c_str(), O_RDONLY | O_CLOEXEC);
    if (fd < 0) return false;
    if (flock(fd, LOCK_EX | LOCK_NB) == 0) return true;
    close(fd);
    fd = -1;
    return false;
}

}  // namespace grotto
