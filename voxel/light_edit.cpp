#include "voxel/light_edit.h"

#include "voxel/light_bake.h"
#include "voxel/luminance.h"
#include "voxel/path_trace.h"
#include "voxel/world.h"

#include <tbb/parallel_for.h>

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace grotto::voxel {

std::vector<GlowingFace> glowingFaces(const World& world, std::span<const ExposedFace> faces) {
    const std::vector<Material>& materials = world.desc().materials;
    std::vector<GlowingFace> glowing;
    for (const ExposedFace& f : faces) {
        const int id = world.material(f.cell);
        if (id < 1 || size_t(id) > materials.size()) continue;
        const glm::dvec3 radiance(materials[size_t(id) - 1].emission());
        if (luminance(radiance) > 0.0) glowing.push_back({f, radiance});
    }
    return glowing;
}

namespace {

glm::dvec3 centreOf(const ExposedFace& f) { return texelPoint(f, 1, 0, 0); }

// The most light over pi the glowing face g can give any point of face f: 0 when
// no point of either is in front of the other.
double lightBound(const GlowingFace& g, const ExposedFace& f) {
    const glm::dvec3 between = centreOf(f) - centreOf(g.face);
    // A face's points lie within half a voxel of its centre along any axis.
    if (glm::dot(between, faceNormal(g.face.dir)) <= -0.5 || glm::dot(-between, faceNormal(f.dir)) <= -0.5) return 0.0;
    const double d = std::max(glm::length(between) - std::sqrt(2.0), 0.5);  // nearest points: less two half-diagonals
    return luminance(g.radiance) / (std::numbers::pi * d * d);
}

// Can a ray between some point of g and some point of f pass through the box?
// Tested on the centres' segment against the box grown by the faces' reach.
bool crosses(const GlowingFace& g, const ExposedFace& f, const IndexBox& box) {
    const glm::dvec3 a = centreOf(g.face), b = centreOf(f);
    const glm::dvec3 lo = glm::dvec3(box.min) - 1.0, hi = glm::dvec3(box.max) + 2.0;
    double enter = 0.0, leave = 1.0;
    for (int axis = 0; axis < 3; ++axis) {
        const double d = b[axis] - a[axis];
        if (std::abs(d) < 1e-12) {
            if (a[axis] < lo[axis] || a[axis] > hi[axis]) return false;
            continue;
        }
        double t0 = (lo[axis] - a[axis]) / d, t1 = (hi[axis] - a[axis]) / d;
        if (t0 > t1) std::swap(t0, t1);
        enter = std::max(enter, t0), leave = std::min(leave, t1);
        if (enter > leave) return false;
    }
    return true;
}

// The glowing faces in one list and not the other, or in both with another colour.
std::vector<GlowingFace> differences(std::span<const GlowingFace> a, std::span<const GlowingFace> b) {
    std::vector<GlowingFace> out;
    size_t i = 0, j = 0;
    while (i < a.size() || j < b.size()) {
        if (j == b.size() || (i < a.size() && a[i].face < b[j].face)) out.push_back(a[i++]);
        else if (i == a.size() || b[j].face < a[i].face) out.push_back(b[j++]);
        else {
            if (a[i].radiance != b[j].radiance) out.push_back({a[i].face, glm::abs(a[i].radiance - b[j].radiance)});
            ++i, ++j;
        }
    }
    return out;
}

// The faces to light again at once: those the edit's rays reach (Stale, SkyNear),
// and those a glowing face that moved, or one whose light crosses the edited
// box, could change by more than their threshold.
std::vector<uint32_t> facesToRelight(std::span<const ExposedFace> faces, std::span<const double> threshold,
                                     std::span<const FaceReach> reach, const IndexBox& changed,
                                     std::span<const GlowingFace> before, std::span<const GlowingFace> after) {
    const std::vector<GlowingFace> moved = differences(before, after);
    std::vector<uint8_t> relit(faces.size(), 0);
    tbb::parallel_for(size_t(0), faces.size(), [&](size_t f) {
        if (reach[f] == FaceReach::Stale || reach[f] == FaceReach::SkyNear) {
            relit[f] = 1;
            return;
        }
        for (const GlowingFace& g : moved)
            if (lightBound(g, faces[f]) > threshold[f]) {
                relit[f] = 1;
                return;
            }
        for (const GlowingFace& g : after)
            if (lightBound(g, faces[f]) > threshold[f] && crosses(g, faces[f], changed)) {
                relit[f] = 1;
                return;
            }
    });
    std::vector<uint32_t> list;
    for (size_t f = 0; f < faces.size(); ++f)
        if (relit[f]) list.push_back(uint32_t(f));
    return list;
}



// What a texel sends back but for its glow, by the world's materials and sun;
// over the day, with its face's day words (k x k texels a face).
class Sender {
public:
    Sender(const World& world, uint32_t k, std::span<const glm::vec3> dayLight)
        : world_(world), lights_(lightSources(world.desc().lighting)), toSun_(glm::normalize(lights_.sunDirection)),
          perFace_(size_t(k) * k), dayLight_(lights_.day ? dayLight : std::span<const glm::vec3>()) {
        if (!dayLight_.empty()) {
            const std::vector<glm::dvec3> toSun = daySunDirections(*lights_.day);
            for (uint32_t b = 0; b < kDayBouncePositions; ++b) bounceSun_.push_back(toSun[dayBouncePosition(b)]);
        }
    }
    const LightSources& lights() const { return lights_; }
    // The light texel t (of face `f`) receives but for the sun's direct beam:
    // its light and, over the day, its face's words with their sources, the
    // sun spread over its positions (as the bake judges the light).
    glm::vec3 received(size_t t, const ExposedFace& f, const FaceTexel& x) const {
        if (dayLight_.empty()) return x.light;
        const glm::vec3* words = &dayLight_[t / perFace_ * kDayLightWords];
        const float samples = float(std::max(x.samples, 1u));
        glm::vec3 light = x.light + words[0] + x.skyZenith / samples + words[1] + x.skyHorizon / samples;
        for (uint32_t b = 0; b < kDayBouncePositions; ++b) {
            const bool lit = (x.daySun >> dayBouncePosition(b)) & 1u;
            const float sun = lit ? float(std::max(glm::dot(faceNormal(f.dir), bounceSun_[b]), 0.0)) : 0.0f;
            light += (words[2 + b] + sun) / float(kDayBouncePositions);
        }
        return light;
    }
    glm::vec3 operator()(size_t t, const ExposedFace& f, const FaceTexel& x) const {
        const std::vector<Material>& materials = world_.desc().materials;
        const int id = world_.material(f.cell);
        const glm::vec3 albedo = id >= 1 && size_t(id) <= materials.size() ? materials[size_t(id) - 1].albedo : glm::vec3(0.0f);
        if (!dayLight_.empty()) return albedo * received(t, f, x);
        const double sun = std::max(glm::dot(faceNormal(f.dir), toSun_), 0.0) * x.sun();
        return albedo * (x.light + glm::vec3(lights_.sun * sun));
    }

private:
    const World& world_;
    LightSources lights_;
    glm::dvec3 toSun_;
    size_t perFace_;
    std::span<const glm::vec3> dayLight_;
    std::vector<glm::dvec3> bounceSun_;  // toward the sun at each bounce position
};

}  // namespace

std::vector<glm::vec3> sentLight(const World& world, std::span<const ExposedFace> faces,
                                 std::span<const FaceTexel> texels, uint32_t k, std::span<const glm::vec3> dayLight) {
    const Sender sends(world, k, dayLight);
    const size_t perFace = size_t(k) * k;
    std::vector<glm::vec3> sent(texels.size());
    for (size_t t = 0; t < texels.size(); ++t) sent[t] = sends(t, faces[t / perFace], texels[t]);
    return sent;
}

std::vector<glm::vec3> carriedDayLight(std::span<const ExposedFace> before, std::span<const ExposedFace> after,
                                       std::span<const glm::vec3> dayLight) {
    std::vector<glm::vec3> carried(after.size() * kDayLightWords, glm::vec3(0.0f));
    for (size_t f = 0; f < after.size(); ++f) {
        const auto it = std::lower_bound(before.begin(), before.end(), after[f]);
        if (it == before.end() || !(*it == after[f])) continue;
        std::copy_n(dayLight.begin() + (it - before.begin()) * kDayLightWords, kDayLightWords,
                    carried.begin() + ptrdiff_t(f * kDayLightWords));
    }
    return carried;
}

RelightStats relightAfterEdit(const BrickTable& table, const World& world, std::span<const ExposedFace> faces,
                              uint32_t k, std::span<FaceTexel> texels, std::span<const FaceReach> reach,
                              const IndexBox& changed, std::span<const ExposedFace> before,
                              std::span<const glm::vec3> sentBefore, std::span<const GlowingFace> glowingBefore,
                              std::span<glm::vec3> dayLight) {
    const size_t perFace = size_t(k) * k;
    const Sender sends(world, k, dayLight);
    const LightSources& lights = sends.lights();
    auto glowOf = [](std::span<const GlowingFace> glowing, const ExposedFace& f) {
        const auto it = std::lower_bound(glowing.begin(), glowing.end(), f,
                                         [](const GlowingFace& g, const ExposedFace& x) { return g.face < x; });
        return it != glowing.end() && it->face == f ? glm::vec3(it->radiance) : glm::vec3(0.0f);
    };
    const std::vector<GlowingFace> glowingNow = glowingFaces(world, faces);
    // What each texel sent before the edit (nothing for a face it made) and its glow now against then.
    std::vector<glm::vec3> was(texels.size(), glm::vec3(0.0f));
    for (size_t f = 0; f < faces.size(); ++f) {
        const glm::vec3 glow = glowOf(glowingNow, faces[f]) - glowOf(glowingBefore, faces[f]);
        const auto it = std::lower_bound(before.begin(), before.end(), faces[f]);
        const bool existed = it != before.end() && *it == faces[f];
        for (size_t t = 0; t < perFace; ++t)
            was[f * perFace + t] = (existed ? sentBefore[size_t(it - before.begin()) * perFace + t] : glm::vec3(0.0f)) - glow;
    }
    // A face's light may be left off by kRelightShare of the larger of its mean
    // light and the world's.
    std::vector<double> threshold(faces.size(), 0.0);
    double mean = 0.0;
    for (size_t f = 0; f < faces.size(); ++f) {
        for (size_t t = f * perFace; t < (f + 1) * perFace; ++t)
            threshold[f] += luminance(glm::dvec3(sends.received(t, faces[f], texels[t])));
        threshold[f] /= double(perFace);
        mean += threshold[f] / double(faces.size());
    }
    for (double& t : threshold) t = kRelightShare * std::max(t, mean);

    RelightStats stats;
    std::vector<uint8_t> relit(faces.size(), 0);
    std::vector<uint32_t> round = facesToRelight(faces, threshold, reach, changed, glowingBefore, glowingNow);
    // The change of what each face lit again sends, its glow's included: what
    // the faces that see it receive changed by.
    std::vector<glm::vec3> change(texels.size(), glm::vec3(0.0f));
    while (!round.empty()) {
        relightFaces(table, world, faces, k, lights, {}, texels, round, {}, dayLight);
        stats.faces += round.size();
        for (const uint32_t f : round) {
            relit[f] = 1;
            for (size_t t = f * perFace; t < (f + 1) * perFace; ++t) change[t] = sends(t, faces[f], texels[t]) - was[t];
        }
        if (stats.rounds == kRelightRounds) break;
        round = facesSeeingChange(table, world, faces, k, texels, change, threshold, relit, kProbeRays);
        stats.rounds += !round.empty();
    }
    return stats;
}

}  // namespace grotto::voxel
