// Path tracing through the exact voxels: from each point, a cosine-weighted
// direction per bounce (the first from the reference AO's stratified R2 set,
// shifted per point). At every face on the way, next-event estimation: a shadow
// ray toward a point of the sun's disc, and one toward a point of a glowing face
// drawn by its power. Escaping rays see the sky alone and rays meeting a glowing
// face do not take its emission, so neither light is counted twice. Double
// precision throughout.
#include "voxel/path_trace.h"

#include "grotto/error.h"
#include "shaders/shared/sky.h"
#include "shaders/shared/quad.h"
#include "voxel/brick_table.h"
#include "voxel/daylight.h"
#include "voxel/face_cache.h"
#include "voxel/luminance.h"
#include "voxel/ray_sampling.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <optional>

namespace grotto::voxel {

LightSources lightSources(const Lighting& lighting) {
    const Lighting l = lightingInEffect(lighting);
    LightSources s;
    s.skyZenith = glm::dvec3(l.skyZenith);
    s.skyHorizon = glm::dvec3(l.skyHorizon);
    s.skyIntensity = l.ambientIntensity;
    s.sunDirection = glm::normalize(glm::dvec3(l.sunDirection));
    s.sun = glm::dvec3(l.sunColor) * double(l.sunIntensity);
    s.sunAngleDegrees = l.sunAngle;
    if (lighting.sunFrom == SunSource::Day) s.day = sunPathOf(lighting);
    return s;
}

namespace {

constexpr double kUnbounded = std::numeric_limits<double>::infinity();
// Bounces every path makes before Russian roulette may end it.
constexpr uint32_t kBouncesBeforeRoulette = 3;

// A face's light response: what it reflects and what it gives off.
struct FaceLight {
    glm::dvec3 albedo{0.0}, emission{0.0};
};

// Indexed by material id (id 0, empty, and ids past the palette reflect nothing).
std::vector<FaceLight> faceLights(const World& world) {
    std::vector<FaceLight> out(1);
    for (const Material& m : world.desc().materials) out.push_back({glm::dvec3(m.albedo), glm::dvec3(m.emission())});
    return out;
}

// One grid of voxels as rays see it: the world's (identity pose) or an object's.
struct Placed {
    const World* world;
    BrickTable table;
    std::vector<FaceLight> lights;
    glm::dvec3 origin;
    double voxelSize;
    std::optional<ObjectPose> pose;  // none: the world itself

    Placed(const World& w, std::optional<ObjectPose> p)
        : world(&w), table(w), lights(faceLights(w)), origin(w.origin()), voxelSize(w.voxelSize()), pose(p) {}

    glm::dvec3 toIndex(glm::dvec3 p) const { return ((pose ? pose->toLocal(p) : p) - origin) / voxelSize; }
    glm::dvec3 toLocalDirection(glm::dvec3 d) const { return pose ? glm::conjugate(pose->rotation) * d : d; }
    glm::dvec3 toWorldDirection(glm::dvec3 d) const { return pose ? pose->rotation * d : d; }
    const FaceLight& light(glm::ivec3 voxel) const {
        const int id = world->material(voxel);
        return size_t(id) < lights.size() ? lights[size_t(id)] : lights[0];
    }
};

// A glowing face as a light: a square of one voxel, in world units.
struct EmitterFace {
    glm::dvec3 corner, u, v, normal;  // corner + s u + t v for s, t in [0, 1]; outward unit normal
    glm::dvec3 radiance;
    double area;
};

struct Hit {
    double t;             // world units
    glm::dvec3 normal;    // world axes
    const FaceLight* light;
};

class Scene {
public:
    Scene(const World& world, std::span<const PosedWorld> objects) {
        grids_.emplace_back(world, std::nullopt);
        for (const PosedWorld& o : objects) grids_.emplace_back(*o.world, o.pose);
        for (const Placed& g : grids_) addEmitters(g);
    }
    // A glowing face drawn in proportion to its power (luminance x area), and
    // the density of that draw per unit area at any of its points.
    const EmitterFace* drawEmitter(double r, double& areaDensity) const {
        if (emitters_.empty()) return nullptr;
        const size_t k = size_t(std::upper_bound(cumulative_.begin(), cumulative_.end(), r * cumulative_.back()) -
                                cumulative_.begin());
        const EmitterFace& e = emitters_[std::min(k, emitters_.size() - 1)];
        areaDensity = luminance(e.radiance) / cumulative_.back();  // (power / total) / area
        return &e;
    }
    // The nearest face a ray from `p` (world units, on a face of normal `n`) meets.
    std::optional<Hit> nearest(glm::dvec3 p, glm::dvec3 n, glm::dvec3 d, double epsilon) const {
        std::optional<Hit> best;
        for (const Placed& g : grids_) {
            const glm::dvec3 start = g.toIndex(p + n * (epsilon * g.voxelSize));
            const double tMax = best ? best->t / g.voxelSize : kUnbounded;
            const std::optional<BrickHit> h = g.table.firstHit(start, g.toLocalDirection(d), tMax);
            if (h && (!best || h->t * g.voxelSize < best->t))
                best = Hit{h->t * g.voxelSize, g.toWorldDirection(faceNormal(uint8_t(h->face))), &g.light(h->voxel)};
        }
        return best;
    }
    // A glowing face's density under drawEmitter, per unit area.
    double emitterDensity(glm::dvec3 radiance) const {
        return cumulative_.empty() ? 0.0 : luminance(radiance) / cumulative_.back();
    }
    double voxelSize() const { return grids_.front().voxelSize; }
    // Does a solid voxel stop the ray before `distance` (world units; unbounded by default)?
    bool blocked(glm::dvec3 p, glm::dvec3 n, glm::dvec3 d, double epsilon, double distance = kUnbounded) const {
        for (const Placed& g : grids_)
            if (g.table.hitWithin(g.toIndex(p + n * (epsilon * g.voxelSize)), g.toLocalDirection(d),
                                  distance / g.voxelSize))
                return true;
        return false;
    }
    // The face a point lies on: the voxel behind it, half a voxel in.
    const FaceLight& surface(uint32_t owner, glm::dvec3 p, glm::dvec3 n) const {
        const Placed& g = grids_.at(owner);
        const glm::dvec3 behind = g.toIndex(p) - g.toLocalDirection(n) * 0.5;
        return g.light(glm::ivec3(glm::floor(behind)));
    }
    size_t grids() const { return grids_.size(); }

private:
    void addEmitters(const Placed& g) {
        if (std::none_of(g.lights.begin(), g.lights.end(), [](const FaceLight& l) { return l.emission != glm::dvec3(0.0); }))
            return;
        for (const ExposedFace& f : exposedFaces(g.table, *g.world)) {
            const glm::dvec3 radiance = g.light(f.cell).emission;
            if (luminance(radiance) <= 0.0) continue;
            // The face's corner and edges in index units, then placed as the grid is.
            glm::dvec3 corner(f.cell), u(0.0), v(0.0);
            corner[int(gpu::faceAxis(f.dir))] += gpu::facePositive(f.dir) ? 1.0 : 0.0;
            u[int(gpu::faceUAxis(f.dir))] = 1.0;
            v[int(gpu::faceVAxis(f.dir))] = 1.0;
            const glm::dvec3 local = g.origin + corner * g.voxelSize;
            EmitterFace e{g.pose ? g.pose->toWorld(local) : local, g.toWorldDirection(u * g.voxelSize),
                          g.toWorldDirection(v * g.voxelSize), g.toWorldDirection(faceNormal(f.dir)), radiance,
                          g.voxelSize * g.voxelSize};
            emitters_.push_back(e);
            cumulative_.push_back((cumulative_.empty() ? 0.0 : cumulative_.back()) + luminance(radiance) * e.area);
        }
    }

    std::vector<Placed> grids_;
    std::vector<EmitterFace> emitters_;
    std::vector<double> cumulative_;  // the emitters' powers (luminance x area), summed in order
};

// Uniform numbers from a counter: one stream per path, independent of threads.
class Random {
public:
    explicit Random(uint64_t seed) : state_(seed) {}
    double next() { return unitInterval(splitmix64(state_++)); }

private:
    uint64_t state_;
};

glm::dvec3 skyRadiance(const LightSources& l, glm::dvec3 d) {
    const glm::vec3 s = gpu::skyRadiance(float(d.y), glm::vec3(l.skyZenith), glm::vec3(l.skyHorizon));
    return glm::dvec3(s) * l.skyIntensity;
}

class Transport {
public:
    Transport(const Scene& scene, const LightSources& lights, const PathTraceSettings& s)
        : scene_(scene), lights_(lights), s_(s), sunOn_(glm::dot(lights.sun, glm::dvec3(1.0)) > 0.0),
          cosSunEdge_(std::cos(0.5 * double(lights.sunAngleDegrees) * std::numbers::pi / 180.0)) {
        tangents(lights.sunDirection, sunT1_, sunT2_);
    }

    // One path's estimate of the light leaving a face at p (normal n, response
    // `face`) toward the viewer; `first` is its first direction's two numbers.
    glm::dvec3 path(glm::dvec3 p, glm::dvec3 n, const FaceLight& face, double u, double v, Random& rng,
                    uint64_t& rays) const {
        glm::dvec3 radiance = face.emission, weight = face.albedo;
        for (uint32_t bounce = 0;; ++bounce) {
            if (weight == glm::dvec3(0.0)) break;
            radiance += weight * (sunLight(p, n, rng, rays) + emitterLight(p, n, rng, rays));
            const glm::dvec3 d = cosineAbout(n, u, v);
            ++rays;
            const std::optional<Hit> hit = scene_.nearest(p, n, d, s_.epsilon);
            if (!hit) {
                radiance += weight * skyRadiance(lights_, d);
                break;
            }
            if (hit->light->emission != glm::dvec3(0.0))
                radiance += weight * hit->light->emission * hitWeight(n, d, *hit);
            if (bounce >= s_.maxBounces) break;
            weight *= hit->light->albedo;
            if (bounce + 1 >= kBouncesBeforeRoulette) {
                // Survive in proportion to what the path can still carry; the
                // survivors carry the rest, so the expected value is unchanged.
                const double keep = std::min(0.95, std::max({weight.r, weight.g, weight.b}));
                if (rng.next() >= keep) break;
                weight /= keep;
            }
            p += d * hit->t;
            n = hit->normal;
            u = rng.next(), v = rng.next();
        }
        return radiance;
    }

private:
    // The sun's light on a face (radiance a white face sends back): toward a point
    // drawn uniformly from its disc, times the cosine, where nothing blocks it.
    glm::dvec3 sunLight(glm::dvec3 p, glm::dvec3 n, Random& rng, uint64_t& rays) const {
        if (!sunOn_) return glm::dvec3(0.0);
        glm::dvec3 d = lights_.sunDirection;
        if (cosSunEdge_ < 1.0) {
            const double c = 1.0 - rng.next() * (1.0 - cosSunEdge_), sn = std::sqrt(std::max(0.0, 1.0 - c * c));
            const double phi = 2.0 * std::numbers::pi * rng.next();
            d = sunT1_ * (sn * std::cos(phi)) + sunT2_ * (sn * std::sin(phi)) + lights_.sunDirection * c;
        }
        const double cosine = glm::dot(d, n);
        if (cosine <= 0.0) return glm::dvec3(0.0);
        ++rays;
        return scene_.blocked(p, n, d, s_.epsilon) ? glm::dvec3(0.0) : lights_.sun * cosine;
    }

    // The glowing faces' light on a face (irradiance / pi): one point drawn on a
    // face drawn by power, weighed by the cosines at both ends over the squared
    // distance, where nothing stands between.
    glm::dvec3 emitterLight(glm::dvec3 p, glm::dvec3 n, Random& rng, uint64_t& rays) const {
        double density = 0.0;
        const EmitterFace* e = scene_.drawEmitter(rng.next(), density);
        if (!e) return glm::dvec3(0.0);
        const glm::dvec3 q = e->corner + e->u * rng.next() + e->v * rng.next();
        // From the ray's start (off the face), so the glowing voxel is entered at `distance`.
        const glm::dvec3 start = p + n * (s_.epsilon * scene_.voxelSize());
        const glm::dvec3 toLight = q - start;
        const double distance = glm::length(toLight);
        if (!(distance > 0.0)) return glm::dvec3(0.0);
        const glm::dvec3 d = toLight / distance;
        const double cosHere = glm::dot(n, d), cosThere = -glm::dot(e->normal, d);
        if (cosHere <= 0.0 || cosThere <= 0.0) return glm::dvec3(0.0);
        ++rays;
        // Stop a hair short of the glowing voxel itself.
        if (scene_.blocked(start, n, d, 0.0, distance * (1.0 - 1e-9) - 1e-7 * scene_.voxelSize()))
            return glm::dvec3(0.0);
        const double light = density * distance * distance / cosThere, cosine = cosHere / std::numbers::pi;
        return e->radiance * (cosHere * cosThere / (std::numbers::pi * distance * distance * density)) *
               powerHeuristic(light, cosine);
    }

    // The share a cosine ray's meeting with a glowing face keeps: the draw above
    // could have found the same point, and the two are weighed by the power
    // heuristic (Veach), so neither a small nearby face nor a large far one is noisy.
    double hitWeight(glm::dvec3 n, glm::dvec3 d, const Hit& hit) const {
        const double cosThere = -glm::dot(hit.normal, d);
        if (cosThere <= 0.0) return 0.0;
        const double light = scene_.emitterDensity(hit.light->emission) * hit.t * hit.t / cosThere;
        return powerHeuristic(glm::dot(n, d) / std::numbers::pi, light);
    }
    // Densities per solid angle of the strategy taken and of the other one.
    static double powerHeuristic(double taken, double other) {
        return taken * taken / (taken * taken + other * other);
    }

    const Scene& scene_;
    const LightSources& lights_;
    const PathTraceSettings& s_;
    bool sunOn_;
    double cosSunEdge_;
    glm::dvec3 sunT1_, sunT2_;
};

}  // namespace

PathTraced pathTrace(const World& world, std::span<const PosedWorld> objects, std::span<const glm::dvec3> points,
                     std::span<const glm::dvec3> normals, std::span<const uint32_t> owners,
                     const LightSources& lights, const PathTraceSettings& s) {
    if (s.spp == 0) throw Error("spp", "0 paths per pixel", "accepted: 1 or more");
    if (points.size() != normals.size() || (!owners.empty() && owners.size() != points.size()))
        throw Error::internal("pathTrace", "points, normals and owners differ in count");
    const Scene scene(world, objects);
    const Transport transport(scene, lights, s);
    PathTraced out;
    out.radiance.resize(points.size());
    out.stderror.resize(points.size());
    std::vector<uint64_t> rays(points.size(), 0);
    tbb::parallel_for(tbb::blocked_range<size_t>(0, points.size(), 8), [&](const tbb::blocked_range<size_t>& r) {
        for (size_t k = r.begin(); k < r.end(); ++k) {
            const uint32_t owner = owners.empty() ? 0 : owners[k];
            if (owner >= scene.grids()) throw Error::internal("pathTrace", "a point's owner is not an object");
            const double len = glm::length(normals[k]);
            if (!(len > 0.0) || !std::isfinite(len) || !std::isfinite(points[k].x + points[k].y + points[k].z))
                throw Error("pathTrace", "point " + std::to_string(k) + " has a non-finite position or zero normal");
            const glm::dvec3 n = normals[k] / len;
            const FaceLight& face = scene.surface(owner, points[k], n);
            const uint64_t h = splitmix64(s.seed ^ splitmix64(k));
            const double shiftU = unitInterval(h), shiftV = unitInterval(splitmix64(h));
            glm::dvec3 sum(0.0), sumSquares(0.0);
            for (uint32_t i = 0; i < s.spp; ++i) {
                Random rng(splitmix64(h + i));
                const glm::dvec2 first = r2(i, {shiftU, shiftV});
                const double u = first.x, v = first.y;
                const glm::dvec3 L = transport.path(points[k], n, face, u, v, rng, rays[k]);
                sum += L;
                sumSquares += L * L;
            }
            const glm::dvec3 mean = sum / double(s.spp);
            const glm::dvec3 variance =
                s.spp > 1 ? glm::max(sumSquares / double(s.spp) - mean * mean, 0.0) * (double(s.spp) / (s.spp - 1))
                          : glm::dvec3(0.0);
            out.radiance[k] = glm::vec3(mean);
            out.stderror[k] = glm::vec3(glm::sqrt(variance / double(s.spp)));
        }
    });
    for (uint64_t n : rays) out.rays += n;
    return out;
}

}  // namespace grotto::voxel
