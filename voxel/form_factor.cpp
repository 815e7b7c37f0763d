#include "voxel/form_factor.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace grotto::voxel {

double polygonFormFactor(glm::dvec3 p, glm::dvec3 n, std::span<const glm::dvec3> corners) {
    // Relative to p, clipped to the half-space in front of the receiver (one plane
    // of Sutherland-Hodgman): a square crossing it becomes at most a pentagon.
    glm::dvec3 v[8];
    int count = 0;
    const size_t m = corners.size();
    for (size_t i = 0; i < m; ++i) {
        const glm::dvec3 a = corners[i] - p, b = corners[(i + 1) % m] - p;
        const double da = glm::dot(a, n), db = glm::dot(b, n);
        if (da >= 0.0) v[count++] = a;
        if ((da >= 0.0) != (db >= 0.0)) v[count++] = a + (b - a) * (da / (da - db));
    }
    if (count < 3) return 0.0;
    double sum = 0.0;
    for (int i = 0; i < count; ++i) {
        const glm::dvec3 a = v[i], b = v[(i + 1) % count];
        const double la = glm::length(a), lb = glm::length(b);
        if (!(la > 0.0 && lb > 0.0)) return 0.0;  // the receiver on a corner: no finite answer to give
        const glm::dvec3 c = glm::cross(a, b);
        const double lc = glm::length(c);
        if (!(lc > 0.0)) continue;  // a degenerate edge adds nothing
        const double angle = std::atan2(lc, glm::dot(a, b));
        sum += angle * glm::dot(n, c) / lc;
    }
    return std::clamp(std::abs(sum) / (2.0 * std::numbers::pi), 0.0, 1.0);
}

}  // namespace grotto::voxel
