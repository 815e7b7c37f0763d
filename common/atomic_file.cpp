#include "atomic_file.h"

#include "error.h"

#include <fcntl.h>
#include <unistd.h>

#include <atomic>
#include <string>
#include <system_error>

namespace grotto {
namespace fs = std::filesystem;

void requireWritableDirectory(const fs::path& file) {
    fs::path dir = file.parent_path();
    if (dir.empty()) dir = ".";
    std::error_code ec;
    if (!fs::is_directory(dir, ec))
        throw Error(file.string(), "output directory '" + dir.string() + "' does not exist",
                    "create it first");
    if (access(dir.c_str(), W_OK) != 0)
        throw Error(file.string(), "output directory '" + dir.string() + "' is not writable",
                    "choose a directory you can write to");
}

void writeAtomically(const fs::path& target, const std::function<void(const fs::path&)>& write) {
    requireWritableDirectory(target);
    static std::atomic<int> counter{0};
    fs::path tmp = target;
    tmp.replace_filename("." + target.stem().string() + ".tmp" + std::to_string(getpid()) + "-" +
                         std::to_string(counter++) + target.extension().string());
    try {
        write(tmp);
        // Flush to disk before the rename, so a crash never leaves an empty target.
        if (int fd = open(tmp.c_str(), O_RDONLY); fd >= 0) {
            fsync(fd);
            close(fd);
        }
        std::error_code ec;
        fs::rename(tmp, target, ec);
        if (ec) throw Error(target.string(), "cannot be replaced: " + ec.message());
    } catch (...) {
        std::error_code ec;
        fs::remove(tmp, ec);
        throw;
    }
}

}  // namespace grotto
