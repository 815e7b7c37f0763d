#include "voxel/face_cache_edit.h"

#include "voxel/brick_table.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

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

StaleRule::StaleRule(const IndexBox& changed, const FaceBakeSettings& s, double voxelSize,
                     std::span<const glm::dvec3> daySun)
    : empty_(changed.empty()),
      lo_(changed.min),
      hi_(glm::dvec3(changed.max) + 1.0),
      centre_(0.5 * (lo_ + hi_)),
      sun_(glm::normalize(s.sunDirection)),
      slack_(1e-3 + s.epsilon),  // rays start a hair in front of the face
      aoReach_(s.radius / voxelSize + slack_),
      halfDiagonal_(glm::length(hi_ - lo_) * 0.5),
      tanHalfAngle_(std::tan(glm::radians(0.5 * s.sunAngleDegrees))),
      texelHalf_(0.5 / std::max(s.texelsPerSide, 1u)),
      daySun_(daySunPositions(s) != 0) {
    if (daySun_) daySunDirections_ = daySun.empty() ? daySunDirections(*s.day) : std::vector<glm::dvec3>(daySun.begin(), daySun.end());
}

StaleParts StaleRule::at(glm::dvec3 point, uint8_t dir) const {
    StaleParts stale;
    if (empty_) return stale;
    stale.ao = distanceToBox(point, lo_, hi_) <= aoReach_;

    const double d = glm::length(centre_ - point);
    const double reach = halfDiagonal_ + d;  // farther than any box point
    // The disc's spread over the distance, and the texel's square: its sun rays
    // start up to half a texel from its centre along each of the face's axes.
    const double spread = tanHalfAngle_ * reach + texelHalf_ + slack_;
    glm::dvec3 normal(0.0);
    normal[dir >> 1] = (dir & 1) == 0 ? 1.0 : -1.0;
    if (daySun_) {
        // One ray a position from the texel's centre (face_bake.h).
        for (const glm::dvec3& toward : daySunDirections_)
            stale.sun = stale.sun || (glm::dot(toward, normal) > 0.0 && rayMeetsBox(point, toward, lo_ - slack_, hi_ + slack_));
    } else {
        stale.sun = rayMeetsBox(point, sun_, lo_ - spread, hi_ + spread);
    }

    const double r = halfDiagonal_;
    if (glm::dot(centre_ - point, normal) > -r) {  // some of the box in front of the face
        const bool near = d <= r || (r * r) / (d * d) > kSkyStaleShare;
        stale.skyNear = near;
        stale.skyFar = !near;
    }
    return stale;
}

StaleParts StaleRule::worstOnFace(const ExposedFace& face, uint32_t k) const {
    StaleParts worst;
    auto eachTexel = [&] {
        for (uint32_t j = 0; j < k; ++j)
            for (uint32_t i = 0; i < k; ++i) {
                const StaleParts p = at(texelPoint(face, k, i, j), face.dir);
                worst.ao |= p.ao, worst.sun |= p.sun, worst.skyNear |= p.skyNear, worst.skyFar |= p.skyFar;
            }
        return worst;
    };
    if (empty_ || daySun_) return eachTexel();
    // The texels' points lie within `rho` of the face's centre, on its plane (and
    // a little more, so rounding never decides).
    const glm::dvec3 c = texelPoint(face, 1, 0, 0);
    const double rho = std::sqrt(2.0) * (0.5 - 0.5 / double(std::max(k, 1u))) + 1e-6;
    // AO: the distance to the box moves by at most rho.
    if (distanceToBox(c, lo_, hi_) - rho <= aoReach_) return eachTexel();
    // Sun: a ray from a texel that meets the box grown by its spread is a ray
    // from the centre that meets it grown by rho more; the spread grows with the
    // distance, at most rho more than the centre's.
    const double d = glm::length(centre_ - c);
    const double spread = tanHalfAngle_ * (halfDiagonal_ + d + rho) + texelHalf_ + slack_ + rho;
    if (rayMeetsBox(c, sun_, lo_ - spread, hi_ + spread)) return eachTexel();
    // Sky: whether the box lies in front is the plane's, the same for every
    // texel; far only where every texel is farther than the centre less rho.
    glm::dvec3 normal(0.0);
    normal[face.dir >> 1] = (face.dir & 1) == 0 ? 1.0 : -1.0;
    const double r = halfDiagonal_;
    if (glm::dot(centre_ - c, normal) > -r) {
        const double nearest = d - rho;
        if (nearest <= r || (r * r) / (nearest * nearest) > kSkyStaleShare) return eachTexel();
        worst.skyFar = true;
    }
    return worst;
}

StaleParts staleAfterEdit(glm::dvec3 point, uint8_t dir, const IndexBox& changed, const FaceBakeSettings& s,
                          double voxelSize, std::span<const glm::dvec3> daySun) {
    return StaleRule(changed, s, voxelSize, daySun).at(point, dir);
}

void updateAfterEdit(const BrickTable& table, const World& world, const IndexBox& changed,
                     const FaceBakeSettings& s, std::vector<ExposedFace>& faces, std::vector<FaceTexel>& texels,
                     CacheEditStats* stats, bool traceNow, std::vector<FaceReach>* reach) {
    const uint32_t k = s.texelsPerSide, perFace = k * k;
    std::vector<ExposedFace> now = exposedFacesAfterEdit(table, world, faces, changed);
    // The lists differ only near the edit: between a common head and tail, one
    // stretch of each. The texels change in place there alone (a world's texels
    // are tens of megabytes: a fresh copy an edit cost more than the rest of it).
    size_t head = 0, oldTail = faces.size(), newTail = now.size();
    while (head < oldTail && head < newTail && faces[head] == now[head]) ++head;
    while (oldTail > head && newTail > head && faces[oldTail - 1] == now[newTail - 1]) --oldTail, --newTail;
    std::vector<FaceTexel> middle((newTail - head) * perFace);  // the new stretch's, carried or empty
    std::vector<FaceReach> reached(now.size(), FaceReach::Untouched);
    const StaleRule rule(changed, s, world.voxelSize());
    // Each face on its own: in parallel, each range walking both lists (in order) together.
    tbb::parallel_for(tbb::blocked_range<size_t>(0, now.size(), 4096), [&](const tbb::blocked_range<size_t>& r) {
        size_t old = size_t(std::lower_bound(faces.begin(), faces.end(), now[r.begin()]) - faces.begin());
        for (size_t f = r.begin(); f < r.end(); ++f) {
            while (old < faces.size() && faces[old] < now[f]) ++old;
            const bool existed = old < faces.size() && faces[old] == now[f];
            const StaleParts worst = existed ? rule.worstOnFace(now[f], k) : StaleParts{};
            if (!existed || worst.now()) {
                const bool skyOnly = existed && !worst.ao && !worst.sun;
                reached[f] = skyOnly ? FaceReach::SkyNear : FaceReach::Stale;
            } else if (worst.skyFar) {
                reached[f] = FaceReach::SkyFar;
            }
            if (existed && f >= head && f < newTail)
                std::copy_n(texels.begin() + ptrdiff_t(old * perFace), perFace, middle.begin() + ptrdiff_t((f - head) * perFace));
        }
    });
    // The tail moved to its new place, the new stretch put in.
    const size_t oldSize = texels.size();
    if (newTail > oldTail) {
        const size_t size = now.size() * perFace;
        if (texels.capacity() < size) texels.reserve(size + size / 8);  // room for the next edit's faces
        texels.resize(size);
        std::move_backward(texels.begin() + ptrdiff_t(oldTail * perFace), texels.begin() + ptrdiff_t(oldSize), texels.end());
    } else if (newTail < oldTail) {
        std::move(texels.begin() + ptrdiff_t(oldTail * perFace), texels.end(), texels.begin() + ptrdiff_t(newTail * perFace));
        texels.resize(now.size() * perFace);
    }
    std::copy(middle.begin(), middle.end(), texels.begin() + ptrdiff_t(head * perFace));
    std::vector<uint32_t> retrace;
    uint64_t far = 0;
    for (size_t f = 0; f < now.size(); ++f) {
        if (reached[f] == FaceReach::Stale || reached[f] == FaceReach::SkyNear) retrace.push_back(uint32_t(f));
        far += reached[f] == FaceReach::SkyFar;
    }
    if (stats) *stats = {.traced = retrace.size(), .carried = now.size() - retrace.size(), .skyFar = far};
    if (reach) *reach = std::move(reached);
    faces = std::move(now);
    if (!traceNow) return;  // the stale keep their old texels till the GPU traces them
    std::vector<ExposedFace> redo(retrace.size());
    for (size_t n = 0; n < retrace.size(); ++n) redo[n] = faces[retrace[n]];
    std::vector<FaceTexel> traced(redo.size() * perFace);
    bakeFaces(table, world, redo, s, traced);
    for (size_t n = 0; n < retrace.size(); ++n)
        std::copy_n(traced.begin() + ptrdiff_t(n * perFace), perFace, texels.begin() + ptrdiff_t(size_t(retrace[n]) * perFace));
}

}  // namespace grotto::voxel
