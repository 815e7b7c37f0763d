#pragma once
// Reading one .vox chunk's content field by field (voxel/vox_read.cpp walks the
// chunks): every count, string and dictionary checked against the bytes left in
// the chunk before it is read or anything is reserved for it, and errors that
// name the file, the chunk and where in it. Internal to voxel/.
#include "grotto/error.h"

#include <glm/vec3.hpp>

#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace grotto::voxel::vox {

constexpr size_t kChunkHeaderBytes = 12;  // id, content size, children size
const char* const kDamaged = "the file is damaged or was not written by MagicaVoxel: save it again from MagicaVoxel";

// A chunk as errors name it: "chunk 'nTRN' at byte 1234".
struct ChunkRef {
    std::string id;  // made printable: a damaged file's ids are any bytes
    size_t at = 0;
};

[[noreturn]] void fail(const std::string& file, const ChunkRef& chunk, const std::string& what,
                       const std::string& hint = kDamaged);

inline uint32_t le32(const uint8_t* p) {
    return uint32_t(p[0]) | uint32_t(p[1]) << 8 | uint32_t(p[2]) << 16 | uint32_t(p[3]) << 24;
}

// A chunk's four-character id, made printable.
std::string chunkId(std::span<const uint8_t> bytes, size_t at);

// A value from the file, quoted and cut short for a one-line message.
std::string quoted(std::string_view text);

inline std::string str(uint64_t n) { return std::to_string(n); }

// A DICT: key-value strings, viewed in the file's bytes. The first of a repeated key counts.
struct Dict {
    std::vector<std::pair<std::string_view, std::string_view>> entries;
    std::optional<std::string_view> get(std::string_view key) const {
        for (const auto& [k, v] : entries)
            if (k == key) return v;
        return std::nullopt;
    }
};

// Reads one chunk's content field by field, each checked against the bytes left
// in the chunk before it is read or anything is reserved for it.
class Cursor {
public:
    Cursor(std::span<const uint8_t> content, const std::string& file, ChunkRef chunk)
        : bytes_(content), file_(file), chunk_(std::move(chunk)) {}

    size_t left() const { return bytes_.size() - pos_; }
    const ChunkRef& chunk() const { return chunk_; }

    [[noreturn]] void fail(const std::string& what, const std::string& hint = kDamaged) const {
        vox::fail(file_, chunk_, what, hint);
    }

    uint32_t u32(std::string_view what) {
        need(4, what);
        const uint32_t v = le32(bytes_.data() + pos_);
        pos_ += 4;
        return v;
    }
    int32_t i32(std::string_view what) { return int32_t(u32(what)); }  // two's complement, as written

    // A count of items of at least `minBytes` each, refused when the bytes left cannot hold that many.
    uint32_t count(std::string_view what, size_t minBytes) {
        const uint32_t n = u32(what);
        if (uint64_t(n) * minBytes > left())
            fail(std::string(what) + " is " + str(n) + ", more than the " + str(left()) +
                 " bytes left in the chunk hold");
        return n;
    }

    std::span<const uint8_t> take(size_t n, std::string_view what) {
        need(n, what);
        const auto s = bytes_.subspan(pos_, n);
        pos_ += n;
        return s;
    }

    std::string_view text(std::string_view what) {
        const auto s = take(u32(what), what);
        return {reinterpret_cast<const char*>(s.data()), s.size()};
    }

    Dict dict(std::string_view what) {
        const uint32_t n = count(std::string(what) + "' entry count", 8);  // a key and a value: two lengths at least
        Dict d;
        d.entries.reserve(n);
        for (uint32_t i = 0; i < n; ++i) {
            const std::string_view key = text(std::string(what) + "' key");
            d.entries.emplace_back(key, text(std::string(what) + "' value"));
        }
        return d;
    }

private:
    void need(uint64_t n, std::string_view what) const {
        if (n > left())
            fail("truncated: " + std::string(what) + " needs " + str(n) + " bytes at byte " +
                 str(chunk_.at + kChunkHeaderBytes + pos_) + ", the chunk has " + str(left()) + " left");
    }

    std::span<const uint8_t> bytes_;
    size_t pos_ = 0;
    const std::string& file_;
    ChunkRef chunk_;
};

// Dictionary values: a whole number in lo..hi, a finite number, a 0/1 flag (absent
// 0), a keyframe's `_f` (absent 0) and a `_t` translation within kMaxVoxTranslation.
int64_t integer(const Cursor& c, std::string_view key, std::string_view v, int64_t lo, int64_t hi);
float number(const Cursor& c, std::string_view key, std::string_view v);
bool flag(const Cursor& c, const Dict& d, std::string_view key);
int64_t frameIndex(const Cursor& c, const Dict& d);
glm::ivec3 translation(const Cursor& c, std::string_view v);

}  // namespace grotto::voxel::vox
