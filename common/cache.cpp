#include "common/cache.h"

#include "common/atomic_file.h"
#include "grotto/error.h"

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>

namespace grotto {
namespace fs = std::filesystem;

namespace {
constexpr char kMagic[8] = {'G', 'R', 'C', 'A', 'C', 'H', 'E', '1'};

template <class T>
bool readValue(std::istream& in, T& v) {
    return bool(in.read(reinterpret_cast<char*>(&v), sizeof v));
}
}  // namespace

Fnv1a& Fnv1a::bytes(const void* data, size_t size) {
    const auto* p = static_cast<const unsigned char*>(data);
    for (size_t i = 0; i < size; ++i) h_ = (h_ ^ p[i]) * 0x100000001b3ull;
    return *this;
}

Fnv1a& Fnv1a::file(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in) throw Error(path.string(), "cannot be read");
    char buf[1 << 16];
    while (in.read(buf, sizeof buf) || in.gcount() > 0) bytes(buf, size_t(in.gcount()));
    return *this;
}

std::string Fnv1a::hex() const {
    char s[17];
    std::snprintf(s, sizeof s, "%016llx", static_cast<unsigned long long>(h_));
    return s;
}

fs::path cacheDirectory() {
    if (const char* d = std::getenv("GROTTO_CACHE_DIR"); d && *d) return d;
    if (const char* d = std::getenv("XDG_CACHE_HOME"); d && *d) return fs::path(d) / "grotto";
    if (const char* d = std::getenv("HOME"); d && *d) return fs::path(d) / ".cache" / "grotto";
    return fs::temp_directory_path() / "grotto-cache";
}

fs::path cachePath(const std::string& kind, const std::string& key) {
    return cacheDirectory() / (kind + "-" + Fnv1a().text(key).hex() + ".bin");
}

// Layout: magic, key length and key, array count, then per array its length and floats.
std::optional<CachedArrays> loadCached(const std::string& kind, const std::string& key) {
    const fs::path path = cachePath(kind, key);
    std::ifstream in(path, std::ios::binary);
    std::error_code ec;
    const uint64_t fileBytes = fs::file_size(path, ec);
    if (ec) return std::nullopt;
    char magic[8];
    uint64_t keyLength = 0, count = 0;
    if (!in.read(magic, 8) || std::memcmp(magic, kMagic, 8) != 0 || !readValue(in, keyLength) ||
        keyLength != key.size())
        return std::nullopt;
    std::string stored(keyLength, '\0');
    if (!in.read(stored.data(), std::streamsize(keyLength)) || stored != key || !readValue(in, count) || count > 64)
        return std::nullopt;
    CachedArrays arrays(count);
    for (auto& a : arrays) {
        uint64_t n = 0;
        // A damaged length must not allocate more than the file could hold.
        if (!readValue(in, n) || n > fileBytes / sizeof(float)) return std::nullopt;
        a.resize(n);
        if (!in.read(reinterpret_cast<char*>(a.data()), std::streamsize(n * sizeof(float)))) return std::nullopt;
    }
    return arrays;
}

void storeCached(const std::string& kind, const std::string& key, const CachedArrays& arrays) {
    const fs::path path = cachePath(kind, key);
    std::error_code ec;
    fs::create_directories(path.parent_path(), ec);
    if (ec) throw Error(path.parent_path().string(), "cache directory cannot be created: " + ec.message());
    writeAtomically(path, [&](std::ostream& out) {
        const uint64_t keyLength = key.size(), count = arrays.size();
        out.write(kMagic, 8);
        out.write(reinterpret_cast<const char*>(&keyLength), 8);
        out.write(key.data(), std::streamsize(key.size()));
        out.write(reinterpret_cast<const char*>(&count), 8);
        for (const auto& a : arrays) {
            const uint64_t n = a.size();
            out.write(reinterpret_cast<const char*>(&n), 8);
            out.write(reinterpret_cast<const char*>(a.data()), std::streamsize(n * sizeof(float)));
        }
    });
}

}  // namespace grotto
