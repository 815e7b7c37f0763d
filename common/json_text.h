#pragma once
// The text of a JSON input, bounded before any parser sees it: a parser builds a
// node per bracket, so ten megabytes of '[' would cost gigabytes. Every JSON file
// grotto reads (worlds, paths, viewer scripts, stability baselines) comes through here.
#include <cstddef>
#include <filesystem>
#include <string>
#include <string_view>

namespace grotto {

// Far above what any of grotto's files holds (a path of a hundred thousand keys
// is a few megabytes; the deepest file nests six levels).
inline constexpr size_t kMaxJsonBytes = size_t(16) << 20;
inline constexpr int kMaxJsonDepth = 64;

// The whole file, once it is known to be a regular file of at most `maxBytes`
// whose arrays and objects nest at most kMaxJsonDepth deep. Throws grotto::Error
// (input) naming the file otherwise; `hint` says what the file should hold.
// (A file that grows with a run, like a flythrough's stats, may allow more bytes.)
std::string readJsonText(const std::filesystem::path& path, const std::string& hint, size_t maxBytes = kMaxJsonBytes);

// The depth check alone, for JSON text found inside another file (a .glb's JSON
// chunk): throws grotto::Error (input) naming `where` past kMaxJsonDepth.
void requireShallowJson(std::string_view text, const std::string& where);

}  // namespace grotto
