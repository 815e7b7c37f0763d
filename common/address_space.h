#pragma once
// How much more address space this process may map: under an address-space
// limit (RLIMIT_AS, `ulimit -v`) an allocation past it fails however much memory
// the machine has, so estimates are checked against it before the work starts.
#include <cstddef>
#include <optional>

namespace grotto {

// The limit less what is mapped now; nothing when there is no limit.
std::optional<size_t> addressSpaceLeft();

}  // namespace grotto
