// Reference AO: cosine-weighted rays from an R2 low-discrepancy set, shifted per
// point (Cranley-Patterson rotation, so the estimate stays unbiased), traced by an
// exact voxel DDA that crosses empty bricks in one step.
#include "voxel/reference_ao.h"

#include "grotto/error.h"
#include "voxel/brick_table.h"
#include "voxel/ray_sampling.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

namespace grotto::voxel {

namespace {

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


// An object's voxels as a ray sees them: its brick table, the pose that places
// it, and a bounding sphere (world units) to skip it for points out of reach.
struct PlacedTable {
    BrickTable table;
    ObjectPose pose;
    glm::dvec3 origin, centre;
    double voxelSize, radius;
    PlacedTable(const PosedWorld& o)
        : table(*o.world), pose(o.pose), origin(o.world->origin()), voxelSize(o.world->voxelSize()) {
        const IndexBox b = o.world->bounds();
        const glm::dvec3 lo = origin + glm::dvec3(b.min) * voxelSize, hi = origin + glm::dvec3(b.max + 1) * voxelSize;
        centre = pose.toWorld(0.5 * (lo + hi));
        radius = 0.5 * glm::length(hi - lo);
    }
};

}  // namespace

ReferenceAo referenceAo(const World& world, std::span<const glm::dvec3> points, std::span<const glm::dvec3> normals,
                        const ReferenceAoSettings& s) {
    return referenceAo(BrickTable(world), world, {}, points, normals, s);
}

ReferenceAo referenceAo(const BrickTable& table, const World& world, std::span<const glm::dvec3> points,
                        std::span<const glm::dvec3> normals, const ReferenceAoSettings& s) {
    return referenceAo(table, world, {}, points, normals, s);
}

ReferenceAo referenceAo(const World& world, std::span<const PosedWorld> objects, std::span<const glm::dvec3> points,
                        std::span<const glm::dvec3> normals, const ReferenceAoSettings& s) {
    return referenceAo(BrickTable(world), world, objects, points, normals, s);
}

ReferenceAo referenceAo(const BrickTable& table, const World& world, std::span<const PosedWorld> objects,
                        std::span<const glm::dvec3> points,
                        std::span<const glm::dvec3> normals, const ReferenceAoSettings& s) {
    if (!(s.radius > 0.0 && std::isfinite(s.radius)))
        throw Error("radius", std::to_string(s.radius) + " is out of range", "accepted: > 0 world units");
    if (s.spp == 0) throw Error("spp", "0 rays per pixel", "accepted: 1 or more");
    if (points.size() != normals.size())
        throw Error::internal("referenceAo", "points and normals differ in count");
    std::vector<PlacedTable> placed;
    for (const PosedWorld& o : objects) placed.emplace_back(o);
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
            // The objects within reach, and the point in each one's voxel index space.
            struct Near { const PlacedTable* o; glm::dvec3 p; glm::dquat toLocal; double tMax; };
            std::vector<Near> near;
            for (const PlacedTable& o : placed) {
                const glm::dvec3 w = points[k] + n * (s.epsilon * vs);
                if (glm::length(w - o.centre) > o.radius + s.radius) continue;
                near.push_back({&o, (o.pose.toLocal(w) - o.origin) / o.voxelSize, glm::conjugate(o.pose.rotation),
                                s.radius / o.voxelSize});
            }
            glm::dvec3 t1, t2;
            tangents(n, t1, t2);
            // The per-point shift: u moves along [0, 1), the azimuth turns by an angle.
            const uint64_t h = splitmix64(s.seed ^ splitmix64(k));
            const double shift = unitInterval(h), turn = 2.0 * std::numbers::pi * unitInterval(splitmix64(h));
            const double ct = std::cos(turn), st = std::sin(turn);
            uint32_t open = 0;
            for (uint32_t i = 0; i < s.spp; ++i) {
                double u = dirs.u[i] + shift;
                if (u >= 1.0) u -= 1.0;
                const double r = std::sqrt(u), z = std::sqrt(1.0 - u);
                const double x = r * (dirs.cosPhi[i] * ct - dirs.sinPhi[i] * st);
                const double y = r * (dirs.sinPhi[i] * ct + dirs.cosPhi[i] * st);
                const glm::dvec3 d = t1 * x + t2 * y + n * z;
                bool hit = table.hitWithin(p, d, tMax);
                for (size_t j = 0; j < near.size() && !hit; ++j)
                    hit = near[j].o->table.hitWithin(near[j].p, near[j].toLocal * d, near[j].tMax);
                open += !hit;
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
