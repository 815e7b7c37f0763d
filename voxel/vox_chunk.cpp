#include "voxel/vox_chunk.h"

#include "common/printable.h"
#include "voxel/vox_read.h"

#include <charconv>
#include <cmath>

namespace grotto::voxel::vox {

void fail(const std::string& file, const ChunkRef& chunk, const std::string& what, const std::string& hint) {
    throw Error(file, "chunk '" + chunk.id + "' at byte " + std::to_string(chunk.at) + ": " + what, hint);
}

std::string chunkId(std::span<const uint8_t> bytes, size_t at) {
    return printable(std::string_view(reinterpret_cast<const char*>(bytes.data() + at), 4));
}

std::string quoted(std::string_view text) {
    constexpr size_t kShown = 40;
    return "'" + printable(text.substr(0, kShown)) + (text.size() > kShown ? "...'" : "'");
}

namespace {

std::optional<int64_t> toInteger(std::string_view v) {
    int64_t n = 0;
    if (v.empty()) return std::nullopt;
    const auto [end, ec] = std::from_chars(v.data(), v.data() + v.size(), n);
    if (ec != std::errc() || end != v.data() + v.size()) return std::nullopt;
    return n;
}

}  // namespace

int64_t integer(const Cursor& c, std::string_view key, std::string_view v, int64_t lo, int64_t hi) {
    const auto n = toInteger(v);
    if (!n || *n < lo || *n > hi)
        c.fail("'" + std::string(key) + "' is " + quoted(v) + ", not an integer in " + std::to_string(lo) + ".." +
               std::to_string(hi));
    return *n;
}

float number(const Cursor& c, std::string_view key, std::string_view v) {
    float f = 0.0f;
    if (!v.empty()) {
        const auto [end, ec] = std::from_chars(v.data(), v.data() + v.size(), f);
        if (ec == std::errc() && end == v.data() + v.size() && std::isfinite(f)) return f;
    }
    c.fail("'" + std::string(key) + "' is " + quoted(v) + ", not a finite number");
}

// `_hidden` and the like: "0" or "1", absent = 0.
bool flag(const Cursor& c, const Dict& d, std::string_view key) {
    const auto v = d.get(key);
    return v && integer(c, key, *v, 0, 1) == 1;
}

// `_f`: the animation frame a keyframe is for, absent = 0.
int64_t frameIndex(const Cursor& c, const Dict& d) {
    const auto v = d.get("_f");
    return v ? integer(c, "_f", *v, 0, INT32_MAX) : 0;
}

// `_t`: "x y z", each within kMaxVoxTranslation.
glm::ivec3 translation(const Cursor& c, std::string_view v) {
    glm::ivec3 t(0);
    int n = 0;
    for (size_t i = 0; i < v.size();) {
        if (v[i] == ' ') {
            ++i;
            continue;
        }
        if (n == 3) {  // a fourth value
            n = 4;
            break;
        }
        const size_t end = std::min(v.find(' ', i), v.size());
        const auto x = toInteger(v.substr(i, end - i));
        if (!x) break;
        if (*x < -kMaxVoxTranslation || *x > kMaxVoxTranslation)
            c.fail("'_t' is " + quoted(v) + ", beyond " + str(kMaxVoxTranslation) + " voxels from the origin",
                   "Grotto reads .vox content within 2^24 voxels of the origin: move it closer in MagicaVoxel");
        t[n++] = int(*x);
        i = end;
    }
    if (n != 3) c.fail("'_t' is " + quoted(v) + ", not three integers 'x y z'");
    return t;
}

}  // namespace grotto::voxel::vox
