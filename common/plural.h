#pragma once
// "1 material", "2 materials": a count with its noun, in the plural unless it is one.
#include <cstdint>
#include <string>
#include <string_view>

namespace grotto {

// The plural is the noun with an "s" unless `plural` is given ("vertex", "vertices").
inline std::string counted(uint64_t n, std::string_view noun, std::string_view plural = {}) {
    return std::to_string(n) + " " +
           std::string(n == 1 ? noun : plural.empty() ? std::string(noun) + "s" : std::string(plural));
}

}  // namespace grotto
