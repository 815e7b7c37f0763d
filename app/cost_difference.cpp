#include "app/cost_difference.h"

#include "app/options.h"

#include <cmath>
#include <cstdio>

namespace grotto::app {

CostDifference costDifference(const std::vector<double>& d) {
    const double middle = median(d);
    std::vector<double> deviation;
    for (double v : d) deviation.push_back(std::abs(v - middle));
    CostDifference c;
    // The median's standard error for normal noise: 1.4826 MAD is the spread of one
    // frame, and a median of n frames scatters 1.2533 / sqrt(n) times that.
    c.noiseMs = d.empty() ? 0.0 : 1.4826 * 1.2533 * median(deviation) / std::sqrt(double(d.size()));
    c.belowNoise = !(middle > c.noiseMs);
    c.ms = c.belowNoise ? 0.0 : middle;
    return c;
}

std::string formatCost(const CostDifference& c) {
    char text[64];
    if (c.belowNoise)
        std::snprintf(text, sizeof text, "< noise (\u00b1%.2f ms)", c.noiseMs);
    else
        std::snprintf(text, sizeof text, "%.2f ms", c.ms);
    return text;
}

}  // namespace grotto::app
