#include "voxel/face_cache_edit.h"

#include "voxel/brick_table.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace grotto::voxel {
namespace {

// Does the ray p + t d (t >= 0) meet the box [lo, hi]?
bool rayMeetsBox(glm::dvec3 p, glm::dvec3 d, glm::dvec3 lo, glm::dvec3 hi) {
    double t0 = 0.0, t1 = std::numeric_limits<double>::infinity();
    for (int a = 0; a < 3; ++a) {
        if (std::abs(d[a]) < 1e-12) {
            if (p[a] < lo[a] || p[a] > hi[a]) return false;
            continue;
        }
        double ta = (lo[a] - p[a]) / d[a], tb = (hi[a] - p[a]) / d[a];
        if (ta > tb) std::swap(ta, tb);
        t0 = std::max(t0, ta), t1 = std::min(t1, tb);
        if (t0 > t1) return false;
    }
    return true;
}

double distanceToBox(glm::dvec3 p, glm::dvec3 lo, glm::dvec3 hi) {
    const glm::dvec3 d = glm::max(glm::max(lo - p, p - hi), glm::dvec3(0.0));
    return std::sqrt(d.x * d.x + d.y * d.y + d.z * d.z);
}

}  // namespace

StaleParts staleAfterEdit(glm::dvec3 point, uint8_t dir, const IndexBox& changed, const FaceBakeSettings& s,
                          double voxelSize, std::span<const glm::dvec3> daySun) {
    StaleParts stale;
    if (changed.empty()) return stale;
    const glm::dvec3 lo(changed.min), hi(glm::dvec3(changed.max) + 1.0);
    const double slack = 1e-3 + s.epsilon;  // rays start a hair in front of the face
    stale.ao = distanceToBox(point, lo, hi) <= s.radius / voxelSize + slack;

    const glm::dvec3 sun = glm::normalize(s.sunDirection);
    const glm::dvec3 centre = 0.5 * (lo + hi);
    const double reach = glm::length(hi - lo) * 0.5 + glm::length(centre - point);  // farther than any box point
    // The disc's spread over the distance, and the texel's square: its sun rays
    // start up to half a texel from its centre along each of the face's axes.
    const double spread = std::tan(glm::radians(0.5 * s.sunAngleDegrees)) * reach + 0.5 / std::max(s.texelsPerSide, 1u) + slack;
    glm::dvec3 normal(0.0);
    normal[dir >> 1] = (dir & 1) == 0 ? 1.0 : -1.0;
    if (daySunPositions(s)) {
        // One ray a position from the texel's centre (face_bake.h).
        std::vector<glm::dvec3> found;
        if (daySun.empty()) found = daySunDirections(*s.day), daySun = found;
        for (const glm::dvec3& d : daySun)
            stale.sun = stale.sun || (glm::dot(d, normal) > 0.0 && rayMeetsBox(point, d, lo - slack, hi + slack));
    } else {
        stale.sun = rayMeetsBox(point, sun, lo - spread, hi + spread);
    }

    const double r = glm::length(hi - lo) * 0.5, d = glm::length(centre - point);
    if (glm::dot(centre - point, normal) > -r) {  // some of the box in front of the face
        const bool near = d <= r || (r * r) / (d * d) > kSkyStaleShare;
        stale.skyNear = near;
        stale.skyFar = !near;
    }
    return stale;
}

void updateAfterEdit(const BrickTable& table, const World& world, const IndexBox& changed,
                     const FaceBakeSettings& s, std::vector<ExposedFace>& faces, std::vector<FaceTexel>& texels,
                     CacheEditStats* stats, bool traceNow, std::vector<FaceReach>* reach) {
    const uint32_t k = s.texelsPerSide, perFace = k * k;
    std::vector<ExposedFace> now = exposedFaces(table, world);
    std::vector<FaceTexel> carried(now.size() * perFace);
    std::vector<uint32_t> retrace;
    uint64_t far = 0;
    if (reach) reach->assign(now.size(), FaceReach::Untouched);
    const std::vector<glm::dvec3> daySun = daySunPositions(s) ? daySunDirections(*s.day) : std::vector<glm::dvec3>{};
    for (size_t f = 0; f < now.size(); ++f) {
        const auto it = std::lower_bound(faces.begin(), faces.end(), now[f]);
        const bool existed = it != faces.end() && *it == now[f];
        StaleParts worst;
        for (uint32_t j = 0; j < k && existed; ++j)
            for (uint32_t i = 0; i < k; ++i) {
                const StaleParts p = staleAfterEdit(texelPoint(now[f], k, i, j), now[f].dir, changed, s, world.voxelSize(), daySun);
                worst.ao |= p.ao, worst.sun |= p.sun, worst.skyNear |= p.skyNear, worst.skyFar |= p.skyFar;
            }
        const size_t old = size_t(it - faces.begin());
        if (!existed || worst.now()) {
            retrace.push_back(uint32_t(f));
            const bool skyOnly = existed && !worst.ao && !worst.sun;
            if (reach) (*reach)[f] = skyOnly ? FaceReach::SkyNear : FaceReach::Stale;
            if (!existed || traceNow) continue;
        } else if (worst.skyFar) {
            ++far;
            if (reach) (*reach)[f] = FaceReach::SkyFar;
        }
        std::copy_n(texels.begin() + ptrdiff_t(old * perFace), perFace, carried.begin() + ptrdiff_t(f * perFace));
    }
    if (stats) *stats = {.traced = retrace.size(), .carried = now.size() - retrace.size(), .skyFar = far};
    if (!traceNow) retrace.clear();  // the stale keep their old texels till the GPU traces them
    std::vector<ExposedFace> redo(retrace.size());
    for (size_t n = 0; n < retrace.size(); ++n) redo[n] = now[retrace[n]];
    std::vector<FaceTexel> traced(redo.size() * perFace);
    bakeFaces(table, world, redo, s, traced);
    for (size_t n = 0; n < retrace.size(); ++n)
        std::copy_n(traced.begin() + ptrdiff_t(n * perFace), perFace, carried.begin() + ptrdiff_t(size_t(retrace[n]) * perFace));
    faces = std::move(now);
    texels = std::move(carried);
}

}  // namespace grotto::voxel
