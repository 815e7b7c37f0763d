#include "atomic_file.h"

#include "error.h"
#include "file_kind.h"
#include "file_lock.h"

#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>

#include <atomic>
#include <regex>
#include <string>
#include <system_error>

namespace grotto {
namespace fs = std::filesystem;

namespace {

// ".NAME.tmpPID-N.EXT" for target NAME.EXT: hidden, unique per process and call.
fs::path temporaryFor(const fs::path& target) {
    static std::atomic<int> counter{0};
    fs::path tmp = target;
    tmp.replace_filename("." + target.stem().string() + ".tmp" + std::to_string(getpid()) + "-" +
                         std::to_string(counter++) + target.extension().string());
    return tmp;
}

}  // namespace

void requireOutputPath(const fs::path& file) {
    fs::path dir = file.parent_path();
    if (dir.empty()) dir = ".";
    std::error_code ec;
    if (!fs::is_directory(dir, ec))
        throw Error(file.string(), "output directory '" + dir.string() + "' does not exist",
                    "create it first");
    if (access(dir.c_str(), W_OK) != 0)
        throw Error(file.string(), "output directory '" + dir.string() + "' is not writable",
                    "choose a directory you can write to");
    if (const std::string kind = irregularKind(file); !kind.empty())
        throw Error(file.string(), "is " + kind + ", not a regular file",
                    "an output may only replace a regular file; name a file path");
}

PendingFile::PendingFile(const fs::path& target) : target_(target) {
    requireOutputPath(target);
    tmp_ = temporaryFor(target);
    lock_ = open(tmp_.c_str(), O_RDWR | O_CREAT | O_EXCL | O_CLOEXEC, 0644);
    if (lock_ < 0) throw Error(target.string(), "cannot create a temporary file beside it");
    flock(lock_, LOCK_EX);  // held until the rename: the file is not abandoned
}

PendingFile::~PendingFile() {
    if (!committed_) {
        std::error_code ec;
        fs::remove(tmp_, ec);
    }
    close(lock_);
}

void PendingFile::commit() {
    // Flush to disk before the rename, so a crash never leaves an empty target.
    if (int fd = open(tmp_.c_str(), O_RDONLY | O_CLOEXEC); fd >= 0) {
        fsync(fd);
        close(fd);
    }
    std::error_code ec;
    fs::rename(tmp_, target_, ec);
    if (ec) throw Error(target_.string(), "cannot be replaced: " + ec.message());
    committed_ = true;
}

void writeAtomically(const fs::path& target, const std::function<void(const fs::path&)>& write) {
    PendingFile file(target);
    write(file.tmp());
    file.commit();
}

int removeAbandonedTemporaries(const fs::path& dir, const std::function<bool(const std::string&)>& ours) {
    static const std::regex pattern(R"(\.(.*)\.tmp[0-9]+-[0-9]+(\.[^.]*)?)");
    int removed = 0;
    std::error_code ec;
    for (const auto& entry : fs::directory_iterator(dir, ec)) {
        const std::string name = entry.path().filename().string();
        std::smatch m;
        if (!std::regex_match(name, m, pattern) || !ours(m[1].str() + m[2].str())) continue;
        int fd = -1;
        if (!FileLock::tryHold(entry.path(), fd)) continue;  // a live run is writing it
        std::error_code rm;
        if (fs::remove(entry.path(), rm)) ++removed;
        close(fd);
    }
    return removed;
}

}  // namespace grotto
