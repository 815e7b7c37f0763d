// Reference AO: cosine-weighted rays from an R2 low-discrepancy set, shifted per
// point (Cranley-Patterson rotation, so the estimate stays unbiased), traced by an
// exact voxel DDA that crosses empty bricks in one step.
#include "voxel/reference_ao.h"

#include "common/error.h"
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

constexpr double kInf = std::numeric_limits<double>::infinity();

// Does the ray from p (index units) along unit d enter a solid voxel at t <= tMax?
// The start cell counts as open: it is the empty cell in front of a visible face,
// and at concave edges rounding may put p a hair inside the neighbouring voxel.
bool occluded(const BrickTable& table, glm::dvec3 p, glm::dvec3 d, double tMax) {
    glm::ivec3 cell(std::floor(p.x), std::floor(p.y), std::floor(p.z)), step;
    glm::dvec3 tNext, tDelta;
    for (int i = 0; i < 3; ++i) {
        if (d[i] > 0) {
            step[i] = 1, tDelta[i] = 1.0 / d[i], tNext[i] = (cell[i] + 1 - p[i]) * tDelta[i];
        } else if (d[i] < 0) {
            step[i] = -1, tDelta[i] = -1.0 / d[i], tNext[i] = (p[i] - cell[i]) * tDelta[i];
        } else {
            step[i] = 0, tDelta[i] = kInf, tNext[i] = kInf;
        }
    }
    glm::ivec3 brick = cell >> 3;
    uint32_t b = table.find(brick);
    bool first = true;
    while (true) {
        if (b == 0) {
            // An empty brick: move every axis to where the ray leaves it, at once.
            glm::ivec3 steps;
            glm::dvec3 tLeave;
            for (int i = 0; i < 3; ++i) {
                steps[i] = step[i] > 0 ? brick[i] * 8 + 8 - cell[i] : cell[i] - brick[i] * 8 + 1;
                tLeave[i] = step[i] == 0 ? kInf : tNext[i] + (steps[i] - 1) * tDelta[i];
            }
            const int e = tLeave.x < tLeave.y ? (tLeave.x < tLeave.z ? 0 : 2) : (tLeave.y < tLeave.z ? 1 : 2);
            const double tE = tLeave[e];
            if (tE > tMax) return false;
            for (int i = 0; i < 3; ++i) {
                if (i == e || step[i] == 0 || tNext[i] >= tE) continue;
                // Crossings of axis i strictly before tE, staying inside this brick.
                const double k = std::clamp(std::ceil((tE - tNext[i]) / tDelta[i]), 0.0, double(steps[i] - 1));
                cell[i] += step[i] * int(k);
                tNext[i] += k * tDelta[i];
            }
            cell[e] += step[e] * steps[e];
            tNext[e] = tE + tDelta[e];
            brick[e] += step[e];
            b = table.find(brick);
            first = false;
            continue;
        }
        if (!first && table.solid(b, cell)) return true;
        first = false;
        const int a = tNext.x < tNext.y ? (tNext.x < tNext.z ? 0 : 2) : (tNext.y < tNext.z ? 1 : 2);
        if (tNext[a] > tMax) return false;
        cell[a] += step[a];
        tNext[a] += tDelta[a];
        if ((cell[a] & 7) == (step[a] > 0 ? 0 : 7)) {
            brick[a] += step[a];
            b = table.find(brick);
        }
    }
}

uint64_t splitmix64(uint64_t x) {
    x += 0x9e3779b97f4a7c15ull;
    x = (x ^ (x >> 30)) * 0xbf58476d1ce4e5b9ull;
    x = (x ^ (x >> 27)) * 0x94d049bb133111ebull;
    return x ^ (x >> 31);
}
double unit(uint64_t bits) { return double(bits >> 11) * 0x1.0p-53; }  // [0, 1)

// The first N points of the R2 sequence (Roberts 2018), as the cosine-weighted
// radius-squared u and the azimuth's cosine and sine.
struct Directions {
    std::vector<double> u, cosPhi, sinPhi;
    explicit Directions(uint32_t n) : u(n), cosPhi(n), sinPhi(n) {
        const double g = 1.32471795724474602596;  // the plastic number
        for (uint32_t i = 0; i < n; ++i) {
            u[i] = std::fmod(0.5 + i / g, 1.0);
            const double phi = 2.0 * std::numbers::pi * std::fmod(0.5 + i / (g * g), 1.0);
            cosPhi[i] = std::cos(phi), sinPhi[i] = std::sin(phi);
        }
    }
};

// Two unit tangents completing n (Duff et al. 2017, branchless).
void tangents(glm::dvec3 n, glm::dvec3& t1, glm::dvec3& t2) {
    const double s = std::copysign(1.0, n.z), a = -1.0 / (s + n.z), b = n.x * n.y * a;
    t1 = {1.0 + s * n.x * n.x * a, s * b, -s * n.x};
    t2 = {b, s + n.y * n.y * a, -n.y};
}

}  // namespace

ReferenceAo referenceAo(const World& world, std::span<const glm::dvec3> points, std::span<const glm::dvec3> normals,
                        const ReferenceAoSettings& s) {
    if (!(s.radius > 0.0 && std::isfinite(s.radius)))
        throw Error("radius", std::to_string(s.radius) + " is out of range", "accepted: > 0 world units");
    if (s.spp == 0) throw Error("spp", "0 rays per pixel", "accepted: 1 or more");
    if (points.size() != normals.size())
        throw Error::internal("referenceAo", "points and normals differ in count");
    const BrickTable table(world);
    const Directions dirs(s.spp);
    const double vs = world.voxelSize(), tMax = s.radius / vs;
    const glm::dvec3 origin = world.origin();
    ReferenceAo out;
    out.visibility.resize(points.size());
    out.stderror.resize(points.size());
    tbb::parallel_for(tbb::blocked_range<size_t>(0, points.size(), 16), [&](const tbb::blocked_range<size_t>& r) {
        for (size_t k = r.begin(); k < r.end(); ++k) {
            const double len = glm::length(normals[k]);
            if (!(len > 0.0) || !std::isfinite(len) || !std::isfinite(points[k].x + points[k].y + points[k].z))
                throw Error("referenceAo", "point " + std::to_string(k) + " has a non-finite position or zero normal");
            const glm::dvec3 n = normals[k] / len;
            const glm::dvec3 p = (points[k] - origin) / vs + n * s.epsilon;
            glm::dvec3 t1, t2;
            tangents(n, t1, t2);
            // The per-point shift: u moves along [0, 1), the azimuth turns by an angle.
            const uint64_t h = splitmix64(s.seed ^ splitmix64(k));
            const double shift = unit(h), turn = 2.0 * std::numbers::pi * unit(splitmix64(h));
            const double ct = std::cos(turn), st = std::sin(turn);
            uint32_t open = 0;
            for (uint32_t i = 0; i < s.spp; ++i) {
                double u = dirs.u[i] + shift;
                if (u >= 1.0) u -= 1.0;
                const double r = std::sqrt(u), z = std::sqrt(1.0 - u);
                const double x = r * (dirs.cosPhi[i] * ct - dirs.sinPhi[i] * st);
                const double y = r * (dirs.sinPhi[i] * ct + dirs.cosPhi[i] * st);
                open += !occluded(table, p, t1 * x + t2 * y + n * z, tMax);
            }
            const double v = double(open) / s.spp;
            out.visibility[k] = float(v);
            out.stderror[k] = float(std::sqrt(v * (1.0 - v) / s.spp));
        }
    });
    out.rays = uint64_t(points.size()) * s.spp;
    return out;
}

}  // namespace grotto::voxel
