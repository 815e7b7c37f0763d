#pragma once
// What every CPU ray set of ours is drawn with: a 64-bit mixer for per-point
// seeds, its bits as a double in [0, 1), and two tangents completing a normal.
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>

namespace grotto::voxel {

inline uint64_t splitmix64(uint64_t x) {
    x += 0x9e3779b97f4a7c15ull;
    x = (x ^ (x >> 30)) * 0xbf58476d1ce4e5b9ull;
    x = (x ^ (x >> 27)) * 0x94d049bb133111ebull;
    return x ^ (x >> 31);
}

inline double unitInterval(uint64_t bits) { return double(bits >> 11) * 0x1.0p-53; }

// Point n of the R2 sequence (Roberts 2018), shifted (Cranley-Patterson), in
// [0, 1)^2. x - floor(x) is fmod(x, 1) exactly for x >= 0, at a fraction of its cost.
inline glm::dvec2 r2(uint64_t n, glm::dvec2 shift) {
    constexpr double g = 1.32471795724474602596;  // the plastic number
    const double u = 0.5 + double(n) / g + shift.x, v = 0.5 + double(n) / (g * g) + shift.y;
    return {u - std::floor(u), v - std::floor(v)};
}

// Point n of a second sequence in [0, 1)^2, shifted: where on a texel's square a
// sun ray starts. A Weyl sequence on sqrt 2 and sqrt 3, not R2 again, so that the
// place a ray starts from is not a function of its direction over the sun's disc.
inline glm::dvec2 texelSpread(uint64_t n, glm::dvec2 shift) {
    const double u = 0.5 + double(n) * 0.41421356237309505 + shift.x, v = 0.5 + double(n) * 0.7320508075688772 + shift.y;
    return {u - std::floor(u), v - std::floor(v)};
}

// Two unit tangents completing the unit normal n (Duff et al. 2017, branchless).
inline void tangents(glm::dvec3 n, glm::dvec3& t1, glm::dvec3& t2) {
    const double s = std::copysign(1.0, n.z), a = -1.0 / (s + n.z), b = n.x * n.y * a;
    t1 = {1.0 + s * n.x * n.x * a, s * b, -s * n.x};
    t2 = {b, s + n.y * n.y * a, -n.y};
}

// A cosine-weighted direction about the unit normal n from two numbers in [0, 1).
inline glm::dvec3 cosineAbout(glm::dvec3 n, double u, double v) {
    glm::dvec3 t1, t2;
    tangents(n, t1, t2);
    const double r = std::sqrt(u), phi = 2.0 * 3.14159265358979323846 * v;
    return t1 * (r * std::cos(phi)) + t2 * (r * std::sin(phi)) + n * std::sqrt(std::max(0.0, 1.0 - u));
}

}  // namespace grotto::voxel
