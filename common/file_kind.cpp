#include "file_kind.h"

#include "grotto/error.h"

#include <cctype>

namespace grotto {
namespace fs = std::filesystem;

std::string irregularKind(const fs::path& path) {
    std::error_code ec;
    switch (fs::status(path, ec).type()) {
        case fs::file_type::regular:
        case fs::file_type::not_found:
        case fs::file_type::none: return {};
        case fs::file_type::directory: return "a directory";
        case fs::file_type::fifo: return "a FIFO";
        case fs::file_type::character: return "a character device";
        case fs::file_type::block: return "a block device";
        case fs::file_type::socket: return "a socket";
        default: return "not a regular file";
    }
}

void requireInputFile(const fs::path& path, const std::string& hint) {
    std::error_code ec;
    if (!fs::exists(path, ec)) throw Error(path.string(), "no such file", hint);
    if (const std::string kind = irregularKind(path); !kind.empty())
        throw Error(path.string(), "is " + kind + ", not a regular file", hint);
}

std::string lowerExtension(const std::filesystem::path& path) {
    std::string ext = path.extension().string();
    for (char& c : ext) c = char(std::tolower(static_cast<unsigned char>(c)));
    return ext;
}

}  // namespace grotto
