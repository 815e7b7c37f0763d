#pragma once
// The world as the full-light bake sees it (voxel/light_bake.h): each face's
// albedo, the texel a ray's hit lands on, and the glowing faces as lights, each
// region (the faces looking one way in one 8^3 brick) listing those that can
// reach it, strongest first, for a texel to take in closed form and sample with
// shadow rays. For light_bake.cpp alone.
#include "shaders/shared/quad.h"
#include "voxel/brick_table.h"
#include "voxel/face_cache_lookup.h"
#include "voxel/face_square.h"
#include "voxel/form_factor.h"
#include "voxel/luminance.h"
#include "voxel/ray_sampling.h"
#include "voxel/world.h"

#include <tbb/parallel_for.h>

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <numbers>
#include <span>
#include <tuple>
#include <vector>

namespace grotto::voxel {

constexpr uint32_t kMissed = UINT32_MAX;  // a ray that left the world
// The glowing faces a region lists, strongest first; any others it can see are
// drawn by power from the whole world, with this many shadow rays.
constexpr size_t kRegionLights = 128;
constexpr uint32_t kFarEmitterRays = 4;

// A glowing face as a light, in voxel index units.
struct Glow {
    glm::dvec3 corner, u, v, normal, centre;
    glm::dvec3 radiance;
    double luminance;
};

// Can a glowing face light any point of the box [lo, hi]? Not when the whole box
// lies behind (or on) its plane.
inline bool canLight(const Glow& g, glm::dvec3 lo, glm::dvec3 hi) {
    double best = -std::numeric_limits<double>::infinity();
    for (int c = 0; c < 8; ++c) {
        const glm::dvec3 q((c & 1) ? hi.x : lo.x, (c & 2) ? hi.y : lo.y, (c & 4) ? hi.z : lo.z);
        best = std::max(best, glm::dot(q - g.corner, g.normal));
    }
    return best > 0.0;
}

// The lights and the world's faces as the bake sees them.
class LightScene {
public:
    // Lists the glowing faces for the regions of the faces `relit`.
    LightScene(const World& world, std::span<const ExposedFace> faces, uint32_t k, std::span<const FaceTexel> texels,
               std::span<const uint32_t> relit)
        : faces_(faces), lookup_(faces, texels, k), k_(k) {
        albedo_.push_back(glm::dvec3(0.0));
        emission_.push_back(glm::dvec3(0.0));
        for (const Material& m : world.desc().materials) {
            albedo_.push_back(glm::dvec3(m.albedo));
            emission_.push_back(glm::dvec3(m.emission()));
        }
        faceMaterial_.resize(faces.size());
        for (size_t f = 0; f < faces.size(); ++f) {
            const int id = world.material(faces[f].cell);
            faceMaterial_[f] = size_t(id) < albedo_.size() ? uint16_t(id) : 0;
            if (luminance(emission_[faceMaterial_[f]]) > 0.0) addGlow(faces[f], emission_[faceMaterial_[f]]);
        }
        for (const Glow& g : glows_) cumulative_.push_back((cumulative_.empty() ? 0.0 : cumulative_.back()) + g.luminance);
        listRegions(relit);
    }

    glm::dvec3 albedo(size_t face) const { return albedo_[faceMaterial_[face]]; }
    // The texel a ray's hit lands on, or kMissed when no listed face is there.
    uint32_t texelAt(const BrickHit& hit, glm::dvec3 point) const {
        const int64_t f = lookup_.find({hit.voxel, uint8_t(hit.face)});
        if (f < 0) return kMissed;
        const int ua = int(gpu::faceUAxis(uint32_t(hit.face))), va = int(gpu::faceVAxis(uint32_t(hit.face)));
        auto index = [&](int axis) {
            const double s = (point[axis] - hit.voxel[axis]) * k_;
            return uint32_t(std::clamp(int(std::floor(s)), 0, int(k_) - 1));
        };
        return uint32_t(f) * k_ * k_ + index(va) * k_ + index(ua);
    }

    // Irradiance over pi at p (normal n, in the region of `cell`) from the glowing
    // faces, with the rays it cast added to `rays`.
    glm::dvec3 glowLight(const BrickTable& table, glm::ivec3 cell, uint8_t dir, glm::dvec3 p, glm::dvec3 n, uint32_t shadowRays,
                         uint64_t seed, double epsilon, uint64_t& rays) const {
        if (glows_.empty()) return glm::dvec3(0.0);
        const auto region = regions_.find(regionOf(cell, dir));
        if (region == regions_.end()) return glm::dvec3(0.0);
        const Region& r = region->second;
        const glm::dvec3 start = p + n * epsilon;
        // The listed faces, each in closed form, its shadow rays drawn by that light.
        double formFactors[kRegionLights], total = 0.0;
        for (size_t i = 0; i < r.listed.size(); ++i) {
            const Glow& g = glows_[r.listed[i]];
            const double side = glm::dot(start - g.corner, g.normal);
            const glm::dvec3 corners[4] = {g.corner, g.corner + g.u, g.corner + g.u + g.v, g.corner + g.v};
            formFactors[i] = side > 0.0 ? polygonFormFactor(start, n, corners) * g.luminance : 0.0;
            total += formFactors[i];
        }
        glm::dvec3 light(0.0);
        uint64_t state = seed;
        auto next = [&] { return unitInterval(splitmix64(state++)); };
        if (total > 0.0) {
            // Stratified over the lights' shares: each ray carries total / shadowRays.
            size_t at = 0;
            double below = 0.0;
            for (uint32_t s = 0; s < shadowRays; ++s) {
                const double target = (s + next()) / shadowRays * total;
                while (at + 1 < r.listed.size() && below + formFactors[at] <= target) below += formFactors[at++];
                const Glow& g = glows_[r.listed[at]];
                if (visible(table, start, g, next(), next(), rays)) light += g.radiance / g.luminance;
            }
            light *= total / shadowRays;
        }
        // The faces the region does not list, drawn by power over the whole world.
        if (r.truncated)
            for (uint32_t s = 0; s < kFarEmitterRays; ++s) {
                const double pick = next() * cumulative_.back();
                const size_t e = std::min(size_t(std::upper_bound(cumulative_.begin(), cumulative_.end(), pick) -
                                                 cumulative_.begin()), glows_.size() - 1);
                if (std::binary_search(r.sortedListed.begin(), r.sortedListed.end(), uint32_t(e))) continue;
                light += pointLight(table, start, n, glows_[e], next(), next(), rays) *
                         (cumulative_.back() / glows_[e].luminance / kFarEmitterRays);
            }
        return light;
    }

private:
    struct Region {
        glm::dvec3 lo{std::numeric_limits<double>::infinity()}, hi{-std::numeric_limits<double>::infinity()};
        std::vector<uint32_t> listed, sortedListed;  // glows, by strength, and by index
        bool truncated = false;
    };
    // A region: the faces looking one way in one 8^3 brick (x, y, z, direction).
    static glm::ivec4 regionOf(glm::ivec3 cell, uint8_t dir) { return {cell.x >> 3, cell.y >> 3, cell.z >> 3, dir}; }
    struct Less {
        bool operator()(glm::ivec4 a, glm::ivec4 b) const {
            return std::tie(a.x, a.y, a.z, a.w) < std::tie(b.x, b.y, b.z, b.w);
        }
    };

    void addGlow(const ExposedFace& f, glm::dvec3 radiance) {
        const FaceSquare q = squareOf(f);
        glows_.push_back({q.corner, q.u, q.v, q.normal, q.centre(), radiance, luminance(radiance)});
    }

    // Each region holding a face of `relit` lists the glowing faces that can reach
    // it, the strongest by power over the squared distance to the region (a bound).
    void listRegions(std::span<const uint32_t> relit) {
        if (glows_.empty()) return;
        for (const uint32_t index : relit) {
            const ExposedFace& f = faces_[index];
            Region& r = regions_[regionOf(f.cell, f.dir)];
            // The face's square on its plane.
            glm::dvec3 lo = texelPoint(f, 1, 0, 0), hi = lo;
            const int ua = int(gpu::faceUAxis(f.dir)), va = int(gpu::faceVAxis(f.dir));
            lo[ua] -= 0.5, lo[va] -= 0.5, hi[ua] += 0.5, hi[va] += 0.5;
            r.lo = glm::min(r.lo, lo), r.hi = glm::max(r.hi, hi);
        }
        std::vector<std::pair<glm::ivec4, Region*>> all;
        for (auto& [key, region] : regions_) all.emplace_back(key, &region);
        tbb::parallel_for(size_t(0), all.size(), [&](size_t i) {
            Region& r = *all[i].second;
            const glm::dvec3 lo = r.lo, hi = r.hi, n = faceNormal(uint8_t(all[i].first.w));
            std::vector<std::pair<double, uint32_t>> reach;
            for (uint32_t e = 0; e < glows_.size(); ++e) {
                const Glow& g = glows_[e];
                // It must face some receiver, and some receiver must face some of it.
                if (!canLight(g, lo, hi)) continue;
                const double ahead = std::max({glm::dot(g.corner, n), glm::dot(g.corner + g.u, n),
                                               glm::dot(g.corner + g.v, n), glm::dot(g.corner + g.u + g.v, n)});
                if (ahead <= std::min(glm::dot(lo, n), glm::dot(hi, n))) continue;
                const glm::dvec3 nearest = glm::clamp(g.centre, lo, hi);
                const double d = std::max(glm::length(g.centre - nearest), 0.5);
                reach.emplace_back(g.luminance / (d * d), e);
            }
            r.truncated = reach.size() > kRegionLights;
            const size_t keep = std::min(reach.size(), kRegionLights);
            std::partial_sort(reach.begin(), reach.begin() + ptrdiff_t(keep), reach.end(),
                              [](const auto& a, const auto& b) { return a.first > b.first; });
            for (size_t k = 0; k < keep; ++k) r.listed.push_back(reach[k].second);
            r.sortedListed = r.listed;
            std::sort(r.sortedListed.begin(), r.sortedListed.end());
        });
    }

    // Whether a uniformly drawn point (s, t) of the glowing face is in sight from `start`.
    static bool visible(const BrickTable& table, glm::dvec3 start, const Glow& g, double s, double t, uint64_t& rays) {
        const glm::dvec3 toLight = g.corner + g.u * s + g.v * t - start;
        const double distance = glm::length(toLight);
        if (!(distance > 0.0)) return false;
        ++rays;
        // Stop a hair short of the glowing voxel itself.
        return !table.hitWithin(start, toLight / distance, distance * (1.0 - 1e-9) - 1e-7);
    }
    // One point drawn uniformly on the face: its light over pi, per unit area.
    static glm::dvec3 pointLight(const BrickTable& table, glm::dvec3 start, glm::dvec3 n, const Glow& g, double s,
                                 double t, uint64_t& rays) {
        const glm::dvec3 toLight = g.corner + g.u * s + g.v * t - start;
        const double d2 = glm::dot(toLight, toLight);
        if (!(d2 > 0.0)) return glm::dvec3(0.0);
        const glm::dvec3 d = toLight / std::sqrt(d2);
        const double cosHere = glm::dot(n, d), cosThere = -glm::dot(g.normal, d);
        if (cosHere <= 0.0 || cosThere <= 0.0) return glm::dvec3(0.0);
        if (!visible(table, start, g, s, t, rays)) return glm::dvec3(0.0);
        return g.radiance * (cosHere * cosThere / (std::numbers::pi * d2));
    }

    std::span<const ExposedFace> faces_;
    FaceCacheLookup lookup_;
    uint32_t k_;
    std::vector<glm::dvec3> albedo_, emission_;
    std::vector<uint16_t> faceMaterial_;
    std::vector<Glow> glows_;
    std::vector<double> cumulative_;  // the glows' luminances, summed in order
    std::map<glm::ivec4, Region, Less> regions_;  // with their receivers' bounds
};

}  // namespace grotto::voxel
