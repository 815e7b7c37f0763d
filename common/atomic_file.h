#pragma once
// Outputs are written under a temporary name beside the target and renamed into
// place, so a crash or a full disk never leaves a truncated file that looks valid.
#include <filesystem>
#include <functional>

namespace grotto {

// Throws grotto::Error (input) naming the path when its directory cannot be written.
void requireWritableDirectory(const std::filesystem::path& file);

// Calls write(tmp) with a temporary path that keeps the target's extension, then
// renames it to target. On any exception the temporary file is removed.
void writeAtomically(const std::filesystem::path& target,
                     const std::function<void(const std::filesystem::path& tmp)>& write);

}  // namespace grotto
