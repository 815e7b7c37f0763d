#pragma once
// A strict reader of one JSON object, shared by world, camera-path and viewer script
// files: every field read is checked, and an unknown field is an error naming file
// and field. nlohmann-json is a private dependency of grotto_voxel: code outside
// voxel/ that includes this links nlohmann_json itself.
#include "grotto/error.h"

#include <glm/gtc/quaternion.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>
#include <nlohmann/json.hpp>

#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <limits>
#include <set>
#include <string>

namespace grotto::voxel {

// Objects keep their fields in file order ("the first camera" is the first written).
using json = nlohmann::ordered_json;

// Parses a whole JSON file; a missing, unreadable, malformed, too large or too
// deeply nested file (common/json_text.h) throws grotto::Error (input) naming it,
// with `hint` saying what the file should hold.
json readJsonFile(const std::filesystem::path& path, const std::string& hint);

// Reads one JSON object strictly: every field is checked, unknown ones refused.
class Reader {
public:
    Reader(const std::filesystem::path& file, const json& object, std::string path)
        : file_(file), obj_(object), path_(std::move(path)) {
        if (!obj_.is_object()) fail("", "expected an object");
    }
    // Refuses the fields never asked about, suggesting the known one meant.
    ~Reader() noexcept(false);

    bool has(const std::string& key) {
        seen_.insert(key);
        return obj_.contains(key);
    }
    const json& at(const std::string& key) { return obj_.at(key); }

    double number(const std::string& key, double fallback, double lo, double hi) {
        if (!has(key)) return fallback;
        const json& v = obj_.at(key);
        if (!v.is_number() || !std::isfinite(v.get<double>()))
            fail(key, "expected a finite number");
        double d = v.get<double>();
        if (d < lo || d > hi)
            fail(key, "value " + v.dump() + " is out of range",
                 "accepted: " + format(lo) + " to " + format(hi));
        return d;
    }
    // A whole number within [lo, hi]: 2.7 is refused, not truncated (2.0 and 2e1 are whole).
    int64_t integer(const std::string& key, int64_t fallback, int64_t lo, int64_t hi) {
        if (!has(key)) return fallback;
        const double d = number(key, double(fallback), double(lo), double(hi));
        if (d != std::floor(d))
            fail(key, "value " + obj_.at(key).dump() + " is not a whole number", "accepted: whole numbers " + format(double(lo)) + " to " + format(double(hi)));
        return int64_t(d);
    }
    bool boolean(const std::string& key, bool fallback) {
        if (!has(key)) return fallback;
        if (!obj_.at(key).is_boolean()) fail(key, "expected true or false");
        return obj_.at(key).get<bool>();
    }
    std::string string(const std::string& key, std::string fallback) {
        if (!has(key)) return fallback;
        if (!obj_.at(key).is_string()) fail(key, "expected a string");
        return obj_.at(key).get<std::string>();
    }
    // What a message calls each component of an array: "albedo[2] (blue)".
    using ComponentNames = std::array<const char*, 4>;
    static constexpr ComponentNames kAxes{"x", "y", "z", "w"};
    static constexpr ComponentNames kChannels{"red", "green", "blue", "alpha"};

    glm::dvec3 vec3(const std::string& key, glm::dvec3 fallback, double lo = -1e12, double hi = 1e12,
                    const ComponentNames& names = kAxes) {
        return vec<3>(key, fallback, lo, hi, names);
    }
    // A JSON array of N finite numbers, each within [lo, hi]; one that is not is
    // named by index and name with its value.
    template <glm::length_t N>
    glm::vec<N, double> vec(const std::string& key, glm::vec<N, double> fallback, double lo, double hi,
                            const ComponentNames& names = kAxes) {
        if (!has(key)) return fallback;
        const json& v = obj_.at(key);
        const std::string accepted = "accepted: an array of " + std::to_string(N) + " numbers, each " + format(lo) + " to " + format(hi);
        if (!v.is_array() || v.size() != size_t(N)) fail(key, "expected an array of " + std::to_string(N) + " numbers", accepted);
        glm::vec<N, double> r;
        for (glm::length_t i = 0; i < N; ++i) {
            const std::string component = key + "[" + std::to_string(i) + "] (" + names[size_t(i)] + ")";
            if (!v[i].is_number() || !std::isfinite(v[i].get<double>()))
                fail(key, component + " is not a finite number", accepted);
            r[i] = v[i].get<double>();
            if (r[i] < lo || r[i] > hi) fail(key, component + " = " + v[i].dump() + " is out of range", accepted);
        }
        return r;
    }
    // [x, y, z, w] (glTF's order): any finite, non-zero quaternion, normalised.
    glm::dquat quaternion(const std::string& key);
    const std::filesystem::path& file() const { return file_; }
    Reader child(const std::string& key) { return Reader(file_, obj_.at(key), field(key)); }
    const std::filesystem::path& fileName() const { return file_; }

    // Throws grotto::Error naming the file and field. When `key` is absent and
    // an unknown field is a near miss of it ("angle_degree"), that one is named.
    [[noreturn]] void fail(const std::string& key, const std::string& what, const std::string& hint = {}) const;
    std::string field(const std::string& key) const {
        return path_.empty() ? key : key.empty() ? path_ : path_ + "." + key;
    }

    static std::string format(double d) {
        char buf[32];
        snprintf(buf, sizeof buf, "%g", d);
        return buf;
    }

private:
    [[noreturn]] void failUnknown(const std::string& key, const std::string& meant) const;

    const std::filesystem::path& file_;
    const json& obj_;
    std::string path_;
    std::set<std::string> seen_;
};

}  // namespace grotto::voxel
