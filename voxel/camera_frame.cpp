#include "voxel/camera_frame.h"

#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

namespace grotto::voxel {

glm::dmat3 lookAtBasis(glm::dvec3 position, glm::dvec3 target) {
    const glm::dvec3 back = glm::normalize(position - target);
    // Straight up or down: any horizontal right vector will do.
    glm::dvec3 up(0.0, 1.0, 0.0);
    if (std::abs(glm::dot(back, up)) > 0.999999) up = glm::dvec3(0.0, 0.0, -1.0);
    const glm::dvec3 right = glm::normalize(glm::cross(up, back));
    return glm::dmat3(right, glm::cross(back, right), back);
}

CameraDesc frameBox(glm::dvec3 lo, glm::dvec3 hi, double aspect) {
    CameraDesc c;
    const glm::dvec3 centre = 0.5 * (lo + hi);
    const glm::dmat3 axes = lookAtBasis(centre + glm::dvec3(0.8, 0.7, 1.0), centre);
    const glm::dvec3 right = axes[0], up = axes[1], forward = -axes[2];
    // In the camera's axes a corner k at (x, y, depth d) is in view, within the
    // margin, when |x - cx| <= t (d - cd) for the camera at (cx, cy, cd) and t the
    // tangent of the narrowed half angle (likewise y). Each axis bounds
    // cx - t cd from below and cx + t cd from above; both met exactly put the
    // camera as near as that axis allows. The nearer of the two axes' depths
    // would cut the other axis, so the camera takes the farther one.
    const double ty = std::tan(glm::radians(c.fovDegrees) * 0.5) * kFramedFill;
    const glm::dvec2 t(ty * aspect, ty);
    constexpr double inf = std::numeric_limits<double>::infinity();
    glm::dvec2 corner[8];
    double depth[8];
    glm::dvec2 below(-inf), above(inf);  // per axis (x, y): the largest lower bound, the smallest upper
    for (int k = 0; k < 8; ++k) {
        const glm::dvec3 p((k & 1) ? hi.x : lo.x, (k & 2) ? hi.y : lo.y, (k & 4) ? hi.z : lo.z);
        corner[k] = glm::dvec2(glm::dot(p, right), glm::dot(p, up));
        depth[k] = glm::dot(p, forward);
        below = glm::max(below, corner[k] - t * depth[k]);
        above = glm::min(above, corner[k] + t * depth[k]);
    }
    const double along = std::min((above.x - below.x) / (2.0 * t.x), (above.y - below.y) / (2.0 * t.y));
    // At that depth each axis leaves the camera an interval to slide in (a point
    // on the binding axis); within it, the place where the corners' projections
    // reach as far to one side as to the other centres the box in the image.
    glm::dvec2 across;
    for (int a = 0; a < 2; ++a) {
        double from = below[a] + t[a] * along, to = above[a] - t[a] * along;
        for (int step = 0; step < 64; ++step) {  // bisection: the sum below falls as the camera slides up
            const double at = 0.5 * (from + to);
            double most = -inf, least = inf;
            for (int k = 0; k < 8; ++k) {
                const double projected = (corner[k][a] - at) / (depth[k] - along);
                most = std::max(most, projected), least = std::min(least, projected);
            }
            (most + least > 0.0 ? from : to) = at;
        }
        across[a] = 0.5 * (from + to);
    }
    c.position = right * across.x + up * across.y + forward * along;
    c.target = c.position + forward * std::max(glm::dot(centre - c.position, forward), 1e-9);
    // As far as the bounding sphere would fill the height: the same near plane for every aspect.
    const double sphereDistance = 0.5 * glm::length(hi - lo) / std::sin(glm::radians(c.fovDegrees) * 0.5);
    c.nearPlane = std::clamp(sphereDistance * 1e-3, 1e-4, 10.0);
    return c;
}

}  // namespace grotto::voxel
