#include "common/json_text.h"

#include "grotto/error.h"
#include "common/file_kind.h"

#include <fstream>

namespace grotto {

// Counts brackets outside strings; stops at the first too deep.
void requireShallowJson(std::string_view text, const std::string& where) {
    int depth = 0;
    bool inString = false, escaped = false;
    for (const char c : text) {
        if (inString) {
            if (escaped) escaped = false;
            else if (c == '\\') escaped = true;
            else if (c == '"') inString = false;
        } else if (c == '"') {
            inString = true;
        } else if (c == '[' || c == '{') {
            if (++depth > kMaxJsonDepth)
                throw Error(where, "nests arrays and objects more than " + std::to_string(kMaxJsonDepth) + " deep",
                            "accepted: JSON nested at most " + std::to_string(kMaxJsonDepth) + " levels");
        } else if (c == ']' || c == '}') {
            --depth;  // unbalanced brackets are the parser's to report
        }
    }
}

std::string readJsonText(const std::filesystem::path& path, const std::string& hint, size_t maxBytes) {
    requireInputFile(path, hint);
    const std::string tooLarge = "is larger than " + std::to_string(maxBytes >> 20) + " MiB, the most this JSON input may be";
    std::error_code ec;
    const auto size = std::filesystem::file_size(path, ec);
    if (!ec && size > maxBytes) throw Error(path.string(), tooLarge, hint);
    std::ifstream in(path, std::ios::binary);
    if (!in) throw Error(path.string(), "cannot be read", hint);
    std::string text;
    if (!ec) text.reserve(size_t(size));
    char chunk[1 << 16];
    while (in.read(chunk, sizeof chunk) || in.gcount() > 0) {
        text.append(chunk, size_t(in.gcount()));
        if (text.size() > maxBytes) throw Error(path.string(), tooLarge, hint);  // it grew since
    }
    if (in.bad()) throw Error(path.string(), "cannot be read", hint);
    requireShallowJson(text, path.string());
    return text;
}

}  // namespace grotto
