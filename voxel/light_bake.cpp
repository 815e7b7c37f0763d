#include "voxel/light_bake.h"

#include "grotto/error.h"
#include "shaders/shared/quad.h"
#include "shaders/shared/sky.h"
#include "voxel/bounce_guide.h"
#include "voxel/brick_table.h"
#include "voxel/face_cache_lookup.h"
#include "voxel/form_factor.h"
#include "voxel/luminance.h"
#include "voxel/ray_sampling.h"
#include "voxel/work_memory.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/parallel_reduce.h>

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <numbers>
#include <numeric>
#include <optional>

namespace grotto::voxel {

namespace {

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
bool canLight(const Glow& g, glm::dvec3 lo, glm::dvec3 hi) {
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
        glm::dvec3 corner(f.cell), u(0.0), v(0.0);
        corner[int(gpu::faceAxis(f.dir))] += gpu::facePositive(f.dir) ? 1.0 : 0.0;
        u[int(gpu::faceUAxis(f.dir))] = 1.0;
        v[int(gpu::faceVAxis(f.dir))] = 1.0;
        glows_.push_back({corner, u, v, faceNormal(f.dir), corner + 0.5 * (u + v), radiance, luminance(radiance)});
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

}  // namespace

uint64_t lightBakeBytes(uint64_t texels, const LightBakeSettings& s) {
    // The hits (the base rays', and extraShare of them more for the noisy texels),
    // the drawn rays' hits and the faces they were drawn toward, the sky's sums,
    // then glow, direct light, light, the next pass's and what each texel sends
    // as float RGB, and the extra rays' counts and offsets.
    const double hits = s.rays * (1.0 + (s.relativeError > 0.0 && s.maxExtraRays > 0 ? s.extraShare : 0.0));
    return texels * (uint64_t(std::ceil(hits)) * sizeof(uint32_t) + s.guidedRays * sizeof(GuidedHit) +
                     sizeof(Drawn) + 6 * sizeof(double) + 5 * sizeof(glm::vec3) + 2 * sizeof(uint32_t));
}

void requireLightBakeFits(const World& world, uint64_t faces, uint32_t k, const LightBakeSettings& s) {
    if (const uint64_t need = lightBakeBytes(faces * k * k, s); need > budgetRoom(world))
        refuseOverBudget(world, "full light's bake of " + std::to_string(faces) + " faces needs " + mibText(need));
}

namespace {

// What a run of a texel's cosine rays saw of the sky.
struct SkySums {
    glm::dvec3 radiance{0.0};  // summed over the rays that left the world
    double squares = 0.0;      // their luminances squared, summed
    double horizon = 0.0, zenith = 0.0;
};

// Rays first .. first + n - 1 of a texel's sequence (R2 turned by `shift`) from
// `start` about `normal`: each one's hit texel written to `hits` (kMissed when it
// left the world), the sky summed.
SkySums traceTexelRays(const BrickTable& table, const LightScene& scene, const LightSources& lights, glm::dvec3 start,
                       glm::dvec3 normal, glm::dvec2 shift, uint32_t first, uint32_t n, uint32_t* hits) {
    SkySums sky;
    for (uint32_t ray = 0; ray < n; ++ray) {
        const glm::dvec2 u = r2(first + ray, shift);
        const glm::dvec3 d = cosineAbout(normal, u.x, u.y);
        const std::optional<BrickHit> hit = table.firstHit(start, d, std::numeric_limits<double>::infinity());
        hits[ray] = hit ? scene.texelAt(*hit, start + d * hit->t) : kMissed;
        if (hit) continue;
        const glm::dvec3 radiance(gpu::skyRadiance(float(d.y), glm::vec3(lights.skyZenith), glm::vec3(lights.skyHorizon)));
        sky.radiance += radiance;
        sky.squares += luminance(radiance) * luminance(radiance);
        const SkyWeights w = skyWeights(d.y);
        sky.horizon += w.horizon, sky.zenith += w.zenith;
    }
    return sky;
}

}  // namespace

LightBakeStats relightFaces(const BrickTable& table, const World& world, std::span<const ExposedFace> faces, uint32_t k,
                            const LightSources& lights, const LightBakeSettings& s, std::span<FaceTexel> texels,
                            std::span<const uint32_t> relit, const BakeProgress& progress) {
    const size_t perFace = size_t(k) * k, count = faces.size() * perFace, traced = relit.size() * perFace;
    if (texels.size() != count) throw Error::internal("relightFaces", "texels and faces differ in count");
    requireLightBakeFits(world, relit.size(), k, s);
    const LightScene scene(world, faces, k, texels, relit);
    const glm::dvec3 sunDirection = glm::normalize(lights.sunDirection);
    const uint32_t baseRays = std::max(s.rays, 1u);
    // The texel of the m-th texel relit; where its rays start; how they are turned.
    auto texelOf = [&](size_t m) { return size_t(relit[m / perFace]) * perFace + m % perFace; };
    auto startOf = [&](size_t m) {
        const ExposedFace& face = faces[relit[m / perFace]];
        const uint32_t i = uint32_t(m % perFace) % k, j = uint32_t(m % perFace) / k;
        return texelPoint(face, k, i, j) + faceNormal(face.dir) * s.epsilon;
    };
    auto seedOf = [&](size_t m) {
        const uint32_t i = uint32_t(m % perFace) % k, j = uint32_t(m % perFace) / k;
        return splitmix64(texelSeed(faces[relit[m / perFace]], i, j) ^ 0x6c69676874ull);  // not the AO's rays
    };
    auto shiftOf = [&](uint64_t h) { return glm::dvec2(unitInterval(h), unitInterval(splitmix64(h))); };

    // The base rays: each relit texel's glowing faces' light, its sky, and the
    // texels its cosine rays hit.
    std::vector<uint32_t> hits(traced * baseRays, kMissed);
    std::vector<SkySums> sky(traced);
    std::vector<glm::vec3> glow(traced);
    std::vector<uint64_t> rays(relit.size(), 0);
    tbb::parallel_for(tbb::blocked_range<size_t>(0, relit.size(), 16), [&](const tbb::blocked_range<size_t>& r) {
        for (size_t n = r.begin(); n < r.end(); ++n) {
            const ExposedFace& face = faces[relit[n]];
            const glm::dvec3 normal = faceNormal(face.dir);
            for (size_t m = n * perFace; m < (n + 1) * perFace; ++m) {
                const uint64_t h = seedOf(m);
                const glm::dvec3 start = startOf(m);
                sky[m] = traceTexelRays(table, scene, lights, start, normal, shiftOf(h), 0, baseRays, &hits[m * baseRays]);
                rays[n] += baseRays;
                glow[m] = glm::vec3(scene.glowLight(table, face.cell, face.dir, start - normal * s.epsilon, normal,
                                                    s.emitterRays, splitmix64(h ^ 3), s.epsilon, rays[n]));
                // The sky's weights as sums over the texel's own ray count.
                const size_t t = texelOf(m);
                const double scale = double(texels[t].samples) / baseRays;
                texels[t].skyHorizon = float(sky[m].horizon * scale), texels[t].skyZenith = float(sky[m].zenith * scale);
            }
        }
    });

    // What each texel sends back to the rays that hit it: its albedo times its
    // light and its sun. The texels not relit send what they hold throughout.
    std::vector<glm::vec3> sent(count);
    auto sends = [&](size_t t, glm::vec3 light) {
        const ExposedFace& face = faces[t / perFace];
        const double sun = std::max(glm::dot(faceNormal(face.dir), sunDirection), 0.0) * texels[t].sun();
        return glm::vec3(scene.albedo(t / perFace)) * (light + glm::vec3(lights.sun * sun));
    };
    tbb::parallel_for(tbb::blocked_range<size_t>(0, count, 4096), [&](const tbb::blocked_range<size_t>& r) {
        for (size_t t = r.begin(); t < r.end(); ++t) sent[t] = sends(t, texels[t].light);
    });

    // More rays for the texels whose light is still noisy (after the passes
    // below): their hits, texel m's at [extraStart[m], extraStart[m + 1]).
    std::vector<uint32_t> extraStart(traced + 1, 0), extraHits;
    auto raysOf = [&](size_t m) { return baseRays + (extraStart[m + 1] - extraStart[m]); };
    // The rays drawn toward bright faces (below), none until the first passes have run.
    const uint32_t guidedRays = s.guidedFaces > 0 ? s.guidedRays : 0;
    std::vector<GuidedHit> guided(traced * guidedRays, GuidedHit{kMissed, 0.0f});
    std::vector<Drawn> drawn(traced);
    std::vector<glm::vec3> direct(traced);
    auto setDirect = [&](size_t m) {
        direct[m] = glm::vec3(sky[m].radiance * (lights.skyIntensity / raysOf(m))) + glow[m];
    };
    for (size_t m = 0; m < traced; ++m) setDirect(m);

    // Bounce passes: light = direct + what the hits send back, from the pass before.
    std::vector<glm::vec3> light = direct, next(traced);
    LightBakeStats stats;
    if (progress) progress(0, s.maxPasses);
    // A texel's change counts against its own light, down to a floor far below
    // the mean: a room lit through a window converges too, not only the open
    // ground that holds most of the light.
    double mean = 0.0;
    for (const glm::vec3& d : direct) mean += luminance(glm::dvec3(d)) / double(std::max<size_t>(traced, 1));
    const double floor = std::max(mean, 1e-30) * 1e-4;
    auto bounce = [&](size_t m) {
        glm::vec3 back(0.0f);
        // kMissed, and the hits on faces drawn toward, have kHitOnDrawnFace set.
        for (const uint32_t* hit = &hits[m * baseRays]; hit != &hits[m * baseRays] + baseRays; ++hit)
            if (*hit < kHitOnDrawnFace) back += sent[*hit];
        for (uint32_t e = extraStart[m]; e < extraStart[m + 1]; ++e)
            if (extraHits[e] < kHitOnDrawnFace) back += sent[extraHits[e]];
        back /= float(raysOf(m));
        if (guidedRays == 0) return back;
        back += drawn[m].base(raysOf(m));
        for (const GuidedHit* g = &guided[m * guidedRays]; g != &guided[m * guidedRays] + guidedRays; ++g)
            if (g->reached()) back += g->weight * sent[g->texel];
        return back;
    };
    auto converge = [&] {
        for (uint32_t pass = 0; pass < s.maxPasses; ++pass) {
            tbb::parallel_for(tbb::blocked_range<size_t>(0, traced, 4096), [&](const tbb::blocked_range<size_t>& r) {
                for (size_t m = r.begin(); m < r.end(); ++m) sent[texelOf(m)] = sends(texelOf(m), light[m]);
            });
            const double change = tbb::parallel_reduce(
                tbb::blocked_range<size_t>(0, traced, 4096), 0.0,
                [&](const tbb::blocked_range<size_t>& r, double worst) {
                    for (size_t m = r.begin(); m < r.end(); ++m) {
                        next[m] = direct[m] + bounce(m);
                        const double grown = std::abs(luminance(glm::dvec3(next[m] - light[m])));
                        worst = std::max(worst, grown / std::max(luminance(glm::dvec3(next[m])), floor));
                    }
                    return worst;
                },
                [](double a, double b) { return std::max(a, b); });
            light.swap(next);
            ++stats.passes;
            stats.change = change;
            if (progress) progress(stats.passes, s.maxPasses);
            if (stats.change < s.tolerance) break;
        }
    };
    converge();

    // Rays drawn toward the faces that pass each region the most light, as the
    // converged light shows it (a sunlit patch, a lamp-lit wall;
    // voxel/bounce_guide.h); the cosine rays' hits on them then count only as a
    // control variate.
    std::optional<BounceGuide> guide;
    if (guidedRays > 0) {
        const BounceGuide::Settings gs{s.guidedFaces, s.guideProbeRays, s.guidedNearest};
        guide.emplace(faces, k, relit, sent, kMissed, gs, [&](glm::dvec3 start, glm::dvec3 dir) {
            const std::optional<BrickHit> hit = table.firstHit(start, dir, std::numeric_limits<double>::infinity());
            return hit ? scene.texelAt(*hit, start + dir * hit->t) : kMissed;
        });
        tbb::parallel_for(tbb::blocked_range<size_t>(0, relit.size(), 16), [&](const tbb::blocked_range<size_t>& r) {
            for (size_t n = r.begin(); n < r.end(); ++n) {
                const glm::dvec3 normal = faceNormal(faces[relit[n]].dir);
                for (size_t m = n * perFace; m < (n + 1) * perFace; ++m)
                    drawn[m] = guide->draw(table, m, startOf(m) - normal * s.epsilon, normal, s.epsilon,
                                           splitmix64(seedOf(m) ^ 5), {&hits[m * baseRays], baseRays},
                                           luminance(glm::dvec3(light[m] - direct[m])),
                                           {&guided[m * guidedRays], guidedRays});
                rays[n] += guidedRays * perFace;
            }
        });
    }

    // The standard error of each texel's light over its base rays, from what each
    // ray brought (the sky's radiance, or the hit's, or on a face drawn toward
    // its share of the control variate, and the drawn rays'); where it passes
    // s.relativeError of the light (or of a hundredth of the mean, where the light
    // is dimmer), enough rays more to bring it there, up to s.maxExtraRays, in
    // all no more than s.extraShare of the base rays (each texel's cut alike).
    const double dim = 0.01 * mean;
    std::vector<uint32_t> wanted(traced, 0);
    if (s.relativeError > 0.0 && s.maxExtraRays > 0)
        tbb::parallel_for(tbb::blocked_range<size_t>(0, traced, 1024), [&](const tbb::blocked_range<size_t>& r) {
            for (size_t m = r.begin(); m < r.end(); ++m) {
                double sum = luminance(sky[m].radiance) * lights.skyIntensity;
                double squares = sky[m].squares * lights.skyIntensity * lights.skyIntensity;
                for (const uint32_t* hit = &hits[m * baseRays]; hit != &hits[m * baseRays] + baseRays; ++hit) {
                    if (*hit == kMissed) continue;
                    const double l = *hit < kHitOnDrawnFace
                                         ? luminance(glm::dvec3(sent[*hit]))
                                         : drawn[m].beta * luminance(glm::dvec3(
                                                               guide->faceLight((*hit & ~kHitOnDrawnFace) / uint32_t(perFace))));
                    sum += l, squares += l * l;
                }
                const double average = sum / baseRays;
                double variance = std::max(squares / baseRays - average * average, 0.0) / baseRays;
                if (drawn[m].faces != 0 && guidedRays > 0) {
                    // The drawn rays' part: each ray's own estimate, times guidedRays:
                    // what it reached less beta times its face's mean light.
                    double drawnSum = 0.0, drawnSquares = 0.0;
                    for (const GuidedHit* g = &guided[m * guidedRays]; g != &guided[m * guidedRays] + guidedRays; ++g) {
                        if (!g->reached()) continue;
                        const double mean = drawn[m].beta * luminance(glm::dvec3(guide->faceLight(g->texel / uint32_t(perFace))));
                        const double v = g->weight * guidedRays * (luminance(glm::dvec3(sent[g->texel])) - mean);
                        drawnSum += v, drawnSquares += v * v;
                    }
                    const double drawnMean = drawnSum / guidedRays;
                    variance += std::max(drawnSquares / guidedRays - drawnMean * drawnMean, 0.0) / guidedRays;
                }
                const double error = std::sqrt(variance);
                const double target = s.relativeError * std::max(luminance(glm::dvec3(light[m])), dim);
                if (!(error > target)) continue;
                const double more = baseRays * ((error / target) * (error / target) - 1.0);
                wanted[m] = uint32_t(std::min(std::ceil(more / 32.0) * 32.0, double(s.maxExtraRays)));
            }
        });
    uint64_t extra = 0;
    for (uint32_t w : wanted) extra += w;
    if (extra > 0) {
        const double scale = std::min(1.0, s.extraShare * double(traced) * baseRays / double(extra));
        for (size_t m = 0; m < traced; ++m) extraStart[m + 1] = extraStart[m] + uint32_t(wanted[m] * scale);
        extraHits.assign(extraStart[traced], kMissed);
        stats.extraRays = extraStart[traced];
        tbb::parallel_for(tbb::blocked_range<size_t>(0, traced, 64), [&](const tbb::blocked_range<size_t>& r) {
            for (size_t m = r.begin(); m < r.end(); ++m) {
                const uint32_t n = extraStart[m + 1] - extraStart[m];
                if (n == 0) continue;
                const SkySums more = traceTexelRays(table, scene, lights, startOf(m), faceNormal(faces[relit[m / perFace]].dir),
                                                    shiftOf(seedOf(m)), baseRays, n, &extraHits[extraStart[m]]);
                if (guide) guide->takeIn(m, drawn[m], {&extraHits[extraStart[m]], n});
                sky[m].radiance += more.radiance;
                setDirect(m);
            }
        });
    }
    if (extra > 0 || guidedRays > 0) converge();
    for (uint64_t n : rays) stats.rays += n;
    stats.rays += stats.extraRays;
    for (size_t m = 0; m < traced; ++m) texels[texelOf(m)].light = light[m];
    return stats;
}

std::vector<uint32_t> facesSeeingChange(const BrickTable& table, const World& world, std::span<const ExposedFace> faces,
                                        uint32_t k, std::span<const FaceTexel> texels, std::span<const glm::vec3> change,
                                        std::span<const double> threshold, std::span<const uint8_t> skip,
                                        uint32_t probeRays) {
    const size_t perFace = size_t(k) * k;
    if (texels.size() != faces.size() * perFace || change.size() != texels.size() || skip.size() != faces.size() ||
        threshold.size() != faces.size())
        throw Error::internal("facesSeeingChange", "texels, changes and faces differ in count");
    const LightScene scene(world, faces, k, texels, {});
    std::vector<uint8_t> seeing(faces.size(), 0);
    tbb::parallel_for(tbb::blocked_range<size_t>(0, faces.size(), 64), [&](const tbb::blocked_range<size_t>& r) {
        for (size_t f = r.begin(); f < r.end(); ++f) {
            if (skip[f]) continue;
            const ExposedFace& face = faces[f];
            const glm::dvec3 n = faceNormal(face.dir), start = texelPoint(face, 1, 0, 0) + n * 1e-4;
            const uint64_t h = splitmix64(texelSeed(face, 0, 0) ^ 0x70726f6265ull);
            const glm::dvec2 shift(unitInterval(h), unitInterval(splitmix64(h)));
            glm::dvec3 sent(0.0);
            for (uint32_t ray = 0; ray < probeRays; ++ray) {
                const glm::dvec2 u = r2(ray, shift);
                const glm::dvec3 d = cosineAbout(n, u.x, u.y);
                const std::optional<BrickHit> hit = table.firstHit(start, d, std::numeric_limits<double>::infinity());
                if (!hit) continue;
                const uint32_t t = scene.texelAt(*hit, start + d * hit->t);
                if (t != kMissed) sent += glm::dvec3(change[t]);
            }
            seeing[f] = std::abs(luminance(sent)) / std::max(probeRays, 1u) > threshold[f];
        }
    });
    std::vector<uint32_t> list;
    for (size_t f = 0; f < faces.size(); ++f)
        if (seeing[f]) list.push_back(uint32_t(f));
    return list;
}

LightBakeStats bakeLight(const BrickTable& table, const World& world, std::span<const ExposedFace> faces, uint32_t k,
                         const LightSources& lights, const LightBakeSettings& s, std::span<FaceTexel> texels,
                         const BakeProgress& progress) {
    std::vector<uint32_t> every(faces.size());
    std::iota(every.begin(), every.end(), 0u);
    return relightFaces(table, world, faces, k, lights, s, texels, every, progress);
}

}  // namespace grotto::voxel
