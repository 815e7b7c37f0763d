#include "common/address_space.h"

#include <sys/resource.h>
#include <unistd.h>

#include <cstdio>

namespace grotto {

std::optional<size_t> addressSpaceLeft() {
    rlimit r{};
    if (getrlimit(RLIMIT_AS, &r) != 0 || r.rlim_cur == RLIM_INFINITY) return std::nullopt;
    // /proc/self/statm's first field: the pages mapped now.
    size_t pages = 0;
    if (std::FILE* f = std::fopen("/proc/self/statm", "r")) {
        if (std::fscanf(f, "%zu", &pages) != 1) pages = 0;
        std::fclose(f);
    }
    const size_t mapped = pages * size_t(sysconf(_SC_PAGESIZE));
    return mapped < r.rlim_cur ? size_t(r.rlim_cur) - mapped : 0;
}

}  // namespace grotto
