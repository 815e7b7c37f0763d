#pragma once
// "Did you mean ...?": the known name a mistyped one was most likely meant to be.
#include <string>
#include <vector>

namespace grotto {

// The name of `known` closest to `typed` by edit distance (letters inserted,
// removed, changed or swapped, case ignored), when it is close enough to be a
// typo of it: at most one edit per three letters, and three at most. Empty otherwise.
std::string closestName(const std::string& typed, const std::vector<std::string>& known);

}  // namespace grotto
