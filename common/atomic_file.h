#pragma once
// Outputs are written under a temporary name beside the target and renamed into
// place only once every byte is known to be on disk: every write is checked and
// the file synced before the rename, so a crash, a full disk or a quota never
// leaves a truncated file under the target's name.
#include <filesystem>
#include <functional>
#include <ostream>
#include <string>
#include <string_view>

namespace grotto {

// Throws grotto::Error (input) naming the path when its directory cannot be
// written or the path names something other than a regular file (a device, a
// FIFO, a directory): an output replaces only a file or nothing.
void requireOutputPath(const std::filesystem::path& file);

// Throws grotto::Error (internal, exit code 1: an environment failure worth
// retrying) naming `target`, for a write, sync or rename that failed with `err`
// (errno); a full disk (ENOSPC, EDQUOT, EFBIG) says so.
[[noreturn]] void throwWriteFailed(const std::filesystem::path& target, int err);

// Writes `bytes` as `target`, atomically; a failed write throws as throwWriteFailed
// and the temporary file is removed.
void writeAtomically(const std::filesystem::path& target, std::string_view bytes);

// The same for a file streamed by write(out) rather than held whole: a failed
// write makes `out` bad, and is thrown once write returns.
void writeAtomically(const std::filesystem::path& target, const std::function<void(std::ostream& out)>& write);

// A file written over a longer span, or by another program (a video from an
// encoder that runs beside the render): tmp() is the temporary path, commit()
// syncs it and renames it into place, and destruction without commit() removes
// it. The temporary file is locked while it exists, so a later run can tell one
// left by a killed run from one another run is writing (removeAbandonedTemporaries).
class PendingFile {
public:
    explicit PendingFile(const std::filesystem::path& target);  // checks the target as requireOutputPath
    ~PendingFile();
    PendingFile(const PendingFile&) = delete;
    PendingFile& operator=(const PendingFile&) = delete;
    const std::filesystem::path& tmp() const { return tmp_; }
    int fd() const { return fd_; }  // the temporary file, open for writing
    void commit();  // throws as throwWriteFailed when the file cannot be synced or renamed

private:
    std::filesystem::path target_, tmp_;
    int fd_ = -1;
    bool committed_ = false;
};

// Removes the temporary files in `dir` that PendingFile left behind when its
// process died (kill -9, a crash), for targets whose file name `ours` accepts.
// One is kept while the process named in it lives or anyone holds its lock: a
// live writer's, or one just created and not yet locked. Returns how many were removed.
int removeAbandonedTemporaries(const std::filesystem::path& dir,
                               const std::function<bool(const std::string& target)>& ours);
// The same for one output: what killed runs writing `target` left beside it.
int removeAbandonedTemporariesOf(const std::filesystem::path& target);

}  // namespace grotto
