#include "voxel/json_reader.h"

#include "common/file_kind.h"

#include <fstream>

namespace grotto::voxel {

json readJsonFile(const std::filesystem::path& path, const std::string& hint) {
    requireInputFile(path, hint);
    std::ifstream in(path);
    if (!in) throw Error(path.string(), "cannot be read");
    try {
        return json::parse(in);
    } catch (const json::exception& e) {  // syntax errors and out-of-range numbers
        std::string msg = e.what();
        auto colon = msg.find("parse error");
        throw Error(path.string(), "malformed JSON: " + msg.substr(colon == std::string::npos ? 0 : colon), hint);
    }
}

}  // namespace grotto::voxel
