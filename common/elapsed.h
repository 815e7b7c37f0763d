#pragma once
// Milliseconds of wall time since `start`, for the benchmarks' tables.
#include <chrono>

namespace grotto {

inline double msSince(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace grotto
