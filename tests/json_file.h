#pragma once
// A JSON file the test's run wrote (stats, manifests, reports), parsed.
#include <nlohmann/json.hpp>

#include <filesystem>
#include <fstream>

namespace grotto::test {

inline nlohmann::json readJsonFile(const std::filesystem::path& file) {
    std::ifstream in(file);
    return nlohmann::json::parse(in);
}

}  // namespace grotto::test
