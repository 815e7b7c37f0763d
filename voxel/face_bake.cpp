#include "voxel/face_bake.h"

#include "grotto/error.h"
#include "voxel/brick_table.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

namespace grotto::voxel {

namespace {

uint64_t splitmix64(uint64_t x) {
    x += 0x9e3779b97f4a7c15ull;
    x = (x ^ (x >> 30)) * 0xbf58476d1ce4e5b9ull;
    x = (x ^ (x >> 27)) * 0x94d049bb133111ebull;
    return x ^ (x >> 31);
}
double unit(uint64_t bits) { return double(bits >> 11) * 0x1.0p-53; }  // [0, 1)

// Point n of the R2 sequence (Roberts 2018), turned by (shift, turn): a
// cosine-weighted direction about +z, and a uniform one in a cone about +z.
constexpr double kPlastic = 1.32471795724474602596;
glm::dvec2 r2(uint64_t n, glm::dvec2 shift) {
    return {std::fmod(0.5 + double(n) / kPlastic + shift.x, 1.0),
            std::fmod(0.5 + double(n) / (kPlastic * kPlastic) + shift.y, 1.0)};
}
glm::dvec3 cosineDirection(glm::dvec2 u) {
    const double r = std::sqrt(u.x), phi = 2.0 * std::numbers::pi * u.y;
    return {r * std::cos(phi), r * std::sin(phi), std::sqrt(1.0 - u.x)};
}
glm::dvec3 coneDirection(glm::dvec2 u, double cosHalf) {
    const double z = 1.0 - u.x * (1.0 - cosHalf), r = std::sqrt(std::max(0.0, 1.0 - z * z));
    const double phi = 2.0 * std::numbers::pi * u.y;
    return {r * std::cos(phi), r * std::sin(phi), z};
}

// Two unit tangents completing n (Duff et al. 2017).
void tangents(glm::dvec3 n, glm::dvec3& t1, glm::dvec3& t2) {
    const double s = std::copysign(1.0, n.z), a = -1.0 / (s + n.z), b = n.x * n.y * a;
    t1 = {1.0 + s * n.x * n.x * a, s * b, -s * n.x};
    t2 = {b, s + n.y * n.y * a, -n.y};
}

// Where a ray from p along d leaves the box [lo, hi) (voxel units); 0 when it
// starts outside and never enters.
double exitDistance(glm::dvec3 p, glm::dvec3 d, glm::dvec3 lo, glm::dvec3 hi) {
    double t = std::numeric_limits<double>::infinity();
    for (int a = 0; a < 3; ++a)
        if (d[a] > 0.0) t = std::min(t, (hi[a] - p[a]) / d[a]);
        else if (d[a] < 0.0) t = std::min(t, (lo[a] - p[a]) / d[a]);
    return std::max(t, 0.0);
}

uint64_t texelSeed(const ExposedFace& f, uint32_t i, uint32_t j) {
    uint64_t h = splitmix64(uint64_t(uint32_t(f.cell.x)));
    h = splitmix64(h ^ uint64_t(uint32_t(f.cell.y)));
    h = splitmix64(h ^ uint64_t(uint32_t(f.cell.z)));
    return splitmix64(h ^ (uint64_t(f.dir) << 32 | uint64_t(i) << 16 | j));
}

}  // namespace

void bakeFaces(const BrickTable& table, const World& world, std::span<const ExposedFace> faces,
               const FaceBakeSettings& s, std::span<FaceTexel> texels) {
    if (!(s.radius > 0.0 && std::isfinite(s.radius)))
        throw Error("radius", std::to_string(s.radius) + " is out of range", "accepted: > 0 world units");
    if (s.texelsPerSide == 0) throw Error("texels per side", "0", "accepted: 1 or more");
    const uint32_t k = s.texelsPerSide, perFace = k * k;
    if (texels.size() != faces.size() * perFace)
        throw Error::internal("bakeFaces", "texels and faces differ in count");
    const double tAo = s.radius / world.voxelSize();
    const IndexBox bounds = world.bounds();
    const glm::dvec3 lo(bounds.min), hi(glm::dvec3(bounds.max) + 1.0);
    const glm::dvec3 sun = glm::normalize(s.sunDirection);
    const bool pointSun = !(s.sunAngleDegrees > 0.0);
    const uint32_t sunRays = pointSun ? std::min(s.sunRays, 1u) : s.sunRays;
    const double cosHalf = std::cos(0.5 * s.sunAngleDegrees * std::numbers::pi / 180.0);
    glm::dvec3 s1, s2;
    tangents(sun, s1, s2);
    // Does a ray from p along d leave the world without entering a solid voxel?
    auto leaves = [&](glm::dvec3 p, glm::dvec3 d) { return !table.hitWithin(p, d, exitDistance(p, d, lo, hi)); };

    tbb::parallel_for(tbb::blocked_range<size_t>(0, faces.size(), 64), [&](const tbb::blocked_range<size_t>& r) {
        for (size_t f = r.begin(); f < r.end(); ++f) {
            const ExposedFace& face = faces[f];
            const glm::dvec3 n = faceNormal(face.dir);
            glm::dvec3 t1, t2;
            tangents(n, t1, t2);
            for (uint32_t j = 0; j < k; ++j)
                for (uint32_t i = 0; i < k; ++i) {
                    FaceTexel& t = texels[f * perFace + j * k + i];
                    const glm::dvec3 p = texelPoint(face, k, i, j) + n * s.epsilon;
                    const uint64_t h = texelSeed(face, i, j);
                    const glm::dvec2 shift(unit(h), unit(splitmix64(h)));
                    double horizon = 0.0, zenith = 0.0;
                    for (uint32_t ray = 0; ray < s.rays; ++ray) {
                        const glm::dvec3 l = cosineDirection(r2(uint64_t(t.samples) + ray, shift));
                        const glm::dvec3 d = t1 * l.x + t2 * l.y + n * l.z;
                        if (table.hitWithin(p, d, tAo)) continue;  // within R: neither AO nor sky
                        ++t.open;
                        if (!leaves(p, d)) continue;
                        const SkyWeights w = skyWeights(d.y);
                        horizon += w.horizon, zenith += w.zenith;
                    }
                    t.samples += s.rays;
                    t.skyHorizon += float(horizon), t.skyZenith += float(zenith);
                    const glm::dvec2 sunShift(unit(splitmix64(h ^ 1)), unit(splitmix64(h ^ 2)));
                    for (uint32_t ray = 0; ray < sunRays; ++ray) {
                        glm::dvec3 d = sun;
                        if (!pointSun) {
                            const glm::dvec3 c = coneDirection(r2(uint64_t(t.sunSamples) + ray, sunShift), cosHalf);
                            d = s1 * c.x + s2 * c.y + sun * c.z;
                        }
                        if (glm::dot(d, n) > 0.0 && leaves(p, d)) ++t.sunOpen;
                    }
                    t.sunSamples += sunRays;
                }
        }
    });
}

}  // namespace grotto::voxel
