#pragma once
// Outputs are written under a temporary name beside the target and renamed into
// place, so a crash or a full disk never leaves a truncated file that looks valid.
#include <filesystem>
#include <functional>
#include <string>

namespace grotto {

// Throws grotto::Error (input) naming the path when its directory cannot be
// written or the path names something other than a regular file (a device, a
// FIFO, a directory): an output replaces only a file or nothing.
void requireOutputPath(const std::filesystem::path& file);

// Calls write(tmp) with a temporary path that keeps the target's extension, then
// renames it to target. On any exception the temporary file is removed. The
// temporary file is locked while it exists, so a later run can tell one left by
// a killed run from one another run is writing (removeAbandonedTemporaries).
void writeAtomically(const std::filesystem::path& target,
                     const std::function<void(const std::filesystem::path& tmp)>& write);

// The same for a file written over a longer span (a video from an encoder that
// runs beside the render): tmp() is the temporary path, commit() renames it into
// place, and destruction without commit() removes it.
class PendingFile {
public:
    explicit PendingFile(const std::filesystem::path& target);  // checks the target as requireOutputPath
    ~PendingFile();
    PendingFile(const PendingFile&) = delete;
    PendingFile& operator=(const PendingFile&) = delete;
    const std::filesystem::path& tmp() const { return tmp_; }
    void commit();  // flushes the temporary file to disk and renames it to the target

private:
    std::filesystem::path target_, tmp_;
    int lock_ = -1;
    bool committed_ = false;
};

// Removes the temporary files in `dir` that writeAtomically left behind when its
// process died, for targets whose file name `ours` accepts; files that a live
// writer still holds are kept. Returns how many were removed.
int removeAbandonedTemporaries(const std::filesystem::path& dir,
                               const std::function<bool(const std::string& target)>& ours);

}  // namespace grotto
