#pragma once
// A cost measured as the difference of two renders' wall times (app/ao_cost.h,
// app/ao_measure.h): the median of the per-frame differences, with its standard
// error (from their median absolute deviation) as its noise. A median no larger
// than the noise cannot be told from zero, so it is reported as "< noise (±x ms)"
// in text and as 0 beside the noise figure in JSON and CSV: never as a negative cost.
#include <string>
#include <vector>

namespace grotto::app {

struct CostDifference {
    double ms = 0.0;          // the median difference, 0 when below the noise
    double noiseMs = 0.0;     // the median's standard error (0 from a single frame)
    bool belowNoise = false;  // the median was not above the noise (a negative one included)
};

CostDifference costDifference(const std::vector<double>& differencesMs);

// "1.23 ms", or "< noise (±0.40 ms)".
std::string formatCost(const CostDifference& cost);

}  // namespace grotto::app
