#pragma once
// libFuzzer hands the target bytes; Grotto's loaders read files. Each run writes
// its bytes to one file in a directory of this process's own, so names that the
// input resolves beside itself (grid and path files) find nothing but the input.
#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>

namespace grotto::fuzz {

inline std::filesystem::path writeInput(const uint8_t* data, size_t size, const std::string& name) {
    static const std::filesystem::path dir = [] {
        auto d = std::filesystem::temp_directory_path() / ("grotto-fuzz-" + std::to_string(getpid()));
        std::filesystem::create_directories(d);
        return d;
    }();
    const std::filesystem::path file = dir / name;
    std::ofstream(file, std::ios::binary | std::ios::trunc).write(reinterpret_cast<const char*>(data), std::streamsize(size));
    return file;
}

}  // namespace grotto::fuzz
