#pragma once
// A number as a message quotes it: printf's "%g", six significant digits, no
// trailing zeros ("0.5", "1e+12").
#include <cstdio>
#include <string>

namespace grotto {

inline std::string numberText(double d) {
    char text[32];
    std::snprintf(text, sizeof text, "%g", d);
    return text;
}

}  // namespace grotto
