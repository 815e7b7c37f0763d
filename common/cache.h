#pragma once
// A result cache on disk: float arrays stored under a text key. The file name is
// a hash of the key and the key itself is kept in the entry and compared on load,
// so a hash collision reads as a miss, never as someone else's result.
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace grotto {

// 64-bit FNV-1a: stable across builds and platforms, for cache keys (not security).
class Fnv1a {
public:
    Fnv1a& bytes(const void* data, size_t size);
    Fnv1a& text(std::string_view s) { return bytes(s.data(), s.size()); }
    // Throws grotto::Error (input) naming the file when it cannot be read.
    Fnv1a& file(const std::filesystem::path& path);
    uint64_t digest() const { return h_; }
    std::string hex() const;

private:
    uint64_t h_ = 0xcbf29ce484222325ull;
};

// $GROTTO_CACHE_DIR, else $XDG_CACHE_HOME/grotto, else ~/.cache/grotto.
std::filesystem::path cacheDirectory();

using CachedArrays = std::vector<std::vector<float>>;

// The entry's path for `kind` (a file-name prefix, e.g. "reference") and `key`.
std::filesystem::path cachePath(const std::string& kind, const std::string& key);
// The arrays stored under key, or nothing (absent, unreadable or another key's).
std::optional<CachedArrays> loadCached(const std::string& kind, const std::string& key);
// Writes the entry atomically, creating the directory; throws grotto::Error on failure.
void storeCached(const std::string& kind, const std::string& key, const CachedArrays& arrays);

}  // namespace grotto
