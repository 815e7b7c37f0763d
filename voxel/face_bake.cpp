#include "voxel/face_bake.h"

#include "grotto/error.h"
#include "shaders/shared/quad.h"
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

// A point of R2 (ray_sampling.h) as a cosine-weighted direction about +z, or a
// uniform one in a cone about +z.
glm::dvec3 cosineDirection(glm::dvec2 u) {
    const double r = std::sqrt(u.x), phi = 2.0 * std::numbers::pi * u.y;
    return {r * std::cos(phi), r * std::sin(phi), std::sqrt(1.0 - u.x)};
}
glm::dvec3 coneDirection(glm::dvec2 u, double cosHalf) {
    const double z = 1.0 - u.x * (1.0 - cosHalf), r = std::sqrt(std::max(0.0, 1.0 - z * z));
    const double phi = 2.0 * std::numbers::pi * u.y;
    return {r * std::cos(phi), r * std::sin(phi), z};
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

// One texel's (or point's) rays, for a bake's settings over one world.
class TexelTracer {
public:
    TexelTracer(const BrickTable& table, const World& world, const FaceBakeSettings& s)
        : table_(table), s_(s), tAo_(s.radius / world.voxelSize()), sun_(glm::normalize(s.sunDirection)),
          pointSun_(!(s.sunAngleDegrees > 0.0)), sunRays_(sunRaysPerTexel(s)),
          cosHalf_(std::cos(0.5 * s.sunAngleDegrees * std::numbers::pi / 180.0)) {
        if (!(s.radius > 0.0 && std::isfinite(s.radius)))
            throw Error("radius", std::to_string(s.radius) + " is out of range", "accepted: > 0 world units");
        const IndexBox bounds = world.bounds();
        lo_ = glm::dvec3(bounds.min), hi_ = glm::dvec3(bounds.max) + 1.0;
        tangents(sun_, s1_, s2_);
        if (daySunPositions(s)) day_ = daySunDirections(*s.day);
    }

    // Adds the settings' rays to `t` from p (voxel units, on a face plane) with the
    // axis normal n, its sequences turned by the hash h. The sun's rays start all
    // over the texel's square, whose sides are `u` and `v` about p (zero: the point
    // alone), so a texel an edge of sunlight crosses reads part lit, however thin
    // the light, and the frame traces the sun there per pixel.
    void trace(FaceTexel& t, glm::dvec3 p, glm::dvec3 n, uint64_t h, glm::dvec3 u = {}, glm::dvec3 v = {}) const {
        glm::dvec3 t1, t2;
        tangents(n, t1, t2);
        p += n * s_.epsilon;
        const glm::dvec2 shift(unitInterval(h), unitInterval(splitmix64(h)));
        double horizon = 0.0, zenith = 0.0;
        for (uint32_t ray = 0; ray < s_.rays; ++ray) {
            const glm::dvec3 l = cosineDirection(r2(uint64_t(t.samples) + ray, shift));
            const glm::dvec3 d = t1 * l.x + t2 * l.y + n * l.z;
            if (table_.hitWithin(p, d, tAo_)) continue;  // within R: neither AO nor sky
            ++t.open;
            // With full light its own rays, twice as many, give the sky (light_bake.h).
            if (!s_.light || s_.fullLight || !leaves(p, d)) continue;
            const SkyWeights w = skyWeights(d.y);
            horizon += w.horizon, zenith += w.zenith;
        }
        t.samples += s_.rays;
        t.skyHorizon += float(horizon), t.skyZenith += float(zenith);
        const glm::dvec2 sunShift(unitInterval(splitmix64(h ^ 1)), unitInterval(splitmix64(h ^ 2)));
        const glm::dvec2 spreadShift(unitInterval(splitmix64(h ^ 3)), unitInterval(splitmix64(h ^ 4)));
        for (uint32_t ray = 0; ray < sunRays_; ++ray) {
            glm::dvec3 d = sun_;
            const uint64_t index = uint64_t(t.sunSamples) + ray;
            if (!pointSun_) {
                const glm::dvec3 c = coneDirection(r2(index, sunShift), cosHalf_);
                d = s1_ * c.x + s2_ * c.y + sun_ * c.z;
            }
            const glm::dvec2 a = texelSpread(index, spreadShift) - 0.5;
            if (glm::dot(d, n) > 0.0 && leaves(p + u * a.x + v * a.y, d)) ++t.sunOpen;
        }
        t.sunSamples += sunRays_;
        // The day's positions, once, from the centre: the frame traces wherever
        // neighbouring texels or positions disagree, so one ray each suffices.
        if (t.dayPositions == day_.size()) return;
        t.daySun = 0;
        for (size_t m = 0; m < day_.size(); ++m)
            if (glm::dot(day_[m], n) > 0.0 && leaves(p, day_[m])) t.daySun |= 1u << m;
        t.dayPositions = uint32_t(day_.size());
    }

private:
    // Does a ray from p along d leave the world without entering a solid voxel?
    bool leaves(glm::dvec3 p, glm::dvec3 d) const { return !table_.hitWithin(p, d, exitDistance(p, d, lo_, hi_)); }

    const BrickTable& table_;
    const FaceBakeSettings& s_;
    double tAo_;
    glm::dvec3 sun_, s1_, s2_, lo_, hi_;
    std::vector<glm::dvec3> day_;  // toward the sun at the day's positions
    bool pointSun_;
    uint32_t sunRays_;
    double cosHalf_;
};

}  // namespace

uint64_t texelSeed(const ExposedFace& f, uint32_t i, uint32_t j) {
    uint64_t h = splitmix64(uint64_t(uint32_t(f.cell.x)));
    h = splitmix64(h ^ uint64_t(uint32_t(f.cell.y)));
    h = splitmix64(h ^ uint64_t(uint32_t(f.cell.z)));
    return splitmix64(h ^ (uint64_t(f.dir) << 32 | uint64_t(i) << 16 | j));
}

void bakeFaces(const BrickTable& table, const World& world, std::span<const ExposedFace> faces,
               const FaceBakeSettings& s, std::span<FaceTexel> texels) {
    if (s.texelsPerSide == 0) throw Error("texels per side", "0", "accepted: 1 or more");
    const TexelTracer tracer(table, world, s);
    const uint32_t k = s.texelsPerSide, perFace = k * k;
    if (texels.size() != faces.size() * perFace)
        throw Error::internal("bakeFaces", "texels and faces differ in count");
    tbb::parallel_for(tbb::blocked_range<size_t>(0, faces.size(), 64), [&](const tbb::blocked_range<size_t>& r) {
        for (size_t f = r.begin(); f < r.end(); ++f) {
            const ExposedFace& face = faces[f];
            glm::dvec3 u(0.0), v(0.0);  // the texel's sides (texelPoint's axes)
            u[int(gpu::faceUAxis(face.dir))] = 1.0 / k, v[int(gpu::faceVAxis(face.dir))] = 1.0 / k;
            for (uint32_t j = 0; j < k; ++j)
                for (uint32_t i = 0; i < k; ++i)
                    tracer.trace(texels[f * perFace + j * k + i], texelPoint(face, k, i, j), faceNormal(face.dir),
                                 texelSeed(face, i, j), u, v);
        }
    });
}

int bakeSteps(size_t faces) { return int(std::clamp<size_t>(faces, 1, 100)); }

void bakeFacesInSteps(const BrickTable& table, const World& world, std::span<const ExposedFace> faces,
                      const FaceBakeSettings& s, std::span<FaceTexel> texels, const BakeProgress& progress) {
    const size_t count = faces.size(), perFace = size_t(s.texelsPerSide) * s.texelsPerSide;
    if (texels.size() != count * perFace) throw Error::internal("bakeFacesInSteps", "texels and faces differ in count");
    if (progress) progress(0, count);
    const int steps = bakeSteps(count);
    for (int step = 0; step < steps; ++step) {
        const size_t a = count * size_t(step) / size_t(steps), b = count * size_t(step + 1) / size_t(steps);
        bakeFaces(table, world, faces.subspan(a, b - a), s, texels.subspan(a * perFace, (b - a) * perFace));
        if (progress) progress(b, count);
    }
}

std::vector<FaceTexel> tracePoints(const BrickTable& table, const World& world, std::span<const glm::dvec3> points,
                                   std::span<const uint8_t> dirs, const FaceBakeSettings& s, uint64_t seed) {
    if (points.size() != dirs.size()) throw Error::internal("tracePoints", "points and directions differ in count");
    const TexelTracer tracer(table, world, s);
    std::vector<FaceTexel> out(points.size());
    tbb::parallel_for(tbb::blocked_range<size_t>(0, points.size(), 64), [&](const tbb::blocked_range<size_t>& r) {
        for (size_t k = r.begin(); k < r.end(); ++k)
            tracer.trace(out[k], points[k], faceNormal(dirs[k]), splitmix64(seed ^ splitmix64(k)));
    });
    return out;
}

}  // namespace grotto::voxel
