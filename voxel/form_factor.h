#pragma once
// The light a Lambertian receiver gets from a uniformly glowing polygon, in
// closed form (Lambert's polygon formula): the share of the receiver's cosine-
// weighted hemisphere the polygon covers, clipped to that hemisphere. Times the
// polygon's radiance it is the irradiance over pi, which is exact however near the
// polygon is, where a point sample of it would not be.
#include <glm/vec3.hpp>

#include <span>

namespace grotto::voxel {

// `corners` (any winding, planar, convex, at most 4) as seen from a receiver at
// `p` with unit normal `n`: the form factor, in [0, 1].
double polygonFormFactor(glm::dvec3 p, glm::dvec3 n, std::span<const glm::dvec3> corners);

}  // namespace grotto::voxel
