#pragma once
// What kind of thing a path names, for the checks on inputs and outputs: both
// must be regular files (an input FIFO would hang a run, and renaming onto a
// device node would replace it).
#include <filesystem>
#include <string>

namespace grotto {

// "a directory", "a FIFO", "a character device", ... for anything that is not a
// regular file (symbolic links followed); empty for a regular file or nothing.
std::string irregularKind(const std::filesystem::path& path);

// Throws grotto::Error (input) naming the path unless it is an existing regular
// file; `hint` says what the file should be.
void requireInputFile(const std::filesystem::path& path, const std::string& hint);

// The path's extension in lower case (".VOX" -> ".vox"): what a file's kind is chosen by.
std::string lowerExtension(const std::filesystem::path& path);

}  // namespace grotto
