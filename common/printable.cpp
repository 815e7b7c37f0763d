#include "printable.h"

#include <cstdio>

namespace grotto {
namespace {

// The length of the valid UTF-8 sequence at s (2 to 4 bytes), or 0.
size_t utf8Length(std::string_view s) {
    const auto b = [&](size_t i) { return i < s.size() ? (unsigned char)s[i] : 0u; };
    const auto cont = [&](size_t i) { return (b(i) & 0xC0u) == 0x80u; };
    const unsigned c = b(0);
    if (c >= 0xC2 && c <= 0xDF) return cont(1) ? 2 : 0;
    if (c >= 0xE0 && c <= 0xEF) {
        const unsigned lo = c == 0xE0 ? 0xA0 : 0x80, hi = c == 0xED ? 0x9F : 0xBF;  // no overlongs, no surrogates
        return b(1) >= lo && b(1) <= hi && cont(2) ? 3 : 0;
    }
    if (c >= 0xF0 && c <= 0xF4) {
        const unsigned lo = c == 0xF0 ? 0x90 : 0x80, hi = c == 0xF4 ? 0x8F : 0xBF;
        return b(1) >= lo && b(1) <= hi && cont(2) && cont(3) ? 4 : 0;
    }
    return 0;
}

}  // namespace

std::string printable(std::string_view text) {
    std::string out;
    out.reserve(text.size());
    char buf[16];
    for (size_t i = 0; i < text.size();) {
        const unsigned char c = text[i];
        if (c >= 0x20 && c < 0x7F) {
            out += char(c);
            ++i;
        } else if (c == '\n') {
            out += "\\n", ++i;
        } else if (c == '\t') {
            out += "\\t", ++i;
        } else if (c == '\r') {
            out += "\\r", ++i;
        } else if (const size_t n = c >= 0x80 ? utf8Length(text.substr(i)) : 0; n > 0) {
            // C1 controls (U+0080..U+009F) act as escapes on some terminals.
            if (n == 2 && c == 0xC2 && (unsigned char)text[i + 1] < 0xA0) {
                std::snprintf(buf, sizeof buf, "\\u{%02X}", unsigned((unsigned char)text[i + 1]));
                out += buf;
            } else {
                out.append(text.substr(i, n));
            }
            i += n;
        } else {
            std::snprintf(buf, sizeof buf, "\\x%02X", unsigned(c));
            out += buf;
            ++i;
        }
    }
    return out;
}

std::string printableExcerpt(std::string_view text, size_t limit) {
    if (text.size() <= limit) return printable(text);
    size_t cut = limit;
    while (cut > 0 && ((unsigned char)text[cut] & 0xC0u) == 0x80u) --cut;  // not inside a UTF-8 sequence
    return printable(text.substr(0, cut)) + "... (" + std::to_string(text.size()) + " bytes)";
}

}  // namespace grotto
