#include "voxel/bounce_guide.h"

#include "shaders/shared/quad.h"
#include "voxel/brick_table.h"
#include "voxel/face_bake.h"
#include "voxel/face_square.h"
#include "voxel/form_factor.h"
#include "voxel/luminance.h"
#include "voxel/ray_sampling.h"

#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>

#include <glm/geometric.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <tuple>

namespace grotto::voxel {

BounceGuide::BounceGuide(std::span<const ExposedFace> faces, uint32_t k, std::span<const uint32_t> relit,
                         std::span<const glm::vec3> sent, uint32_t missed, const Settings& settings,
                         const HitTexel& hitTexel)
    : faces_(faces), k_(k), missed_(missed), nearest_(settings.nearest) {
    const size_t perFace = size_t(k) * k;
    const size_t listed = std::min(settings.listed, kMaxListed);
    faceLight_.assign(faces.size(), glm::vec3(0.0f));
    tbb::parallel_for(size_t(0), faces.size(), [&](size_t f) {
        glm::dvec3 sum(0.0);
        for (size_t t = f * perFace; t < (f + 1) * perFace; ++t) sum += glm::dvec3(sent[t]);
        faceLight_[f] = glm::vec3(sum / double(perFace));
    });

    // Every face of the world by region, and the regions the relit faces lie in.
    using Key = std::tuple<int, int, int, int>;
    auto keyOf = [&](uint32_t f) {
        return Key{faces[f].cell.x >> 3, faces[f].cell.y >> 3, faces[f].cell.z >> 3, faces[f].dir};
    };
    std::vector<std::pair<Key, uint32_t>> all(faces.size());
    for (uint32_t f = 0; f < faces.size(); ++f) all[f] = {keyOf(f), f};
    std::sort(all.begin(), all.end());
    std::vector<std::pair<Key, uint32_t>> keyed(relit.size());
    for (size_t n = 0; n < relit.size(); ++n) keyed[n] = {keyOf(relit[n]), uint32_t(n)};
    std::sort(keyed.begin(), keyed.end());
    regionOfFace_.assign(relit.size(), 0);
    std::vector<Key> regionKeys;
    for (size_t i = 0; i < keyed.size(); ++i) {
        if (i == 0 || keyed[i].first != keyed[i - 1].first) regionKeys.push_back(keyed[i].first);
        regionOfFace_[keyed[i].second] = uint32_t(regionKeys.size() - 1);
    }
    lists_.assign(regionKeys.size(), {});

    // Each region's list: the faces its probe rays found sending the most light
    // back, summed over those rays. The probes leave every face of the region,
    // relit or not, from points and in directions fixed by the face alone: a
    // region relit after an edit lists what a fresh bake would list, and no
    // texel's own rays choose the faces it draws toward.
    struct Scratch {
        std::vector<float> sum;
        std::vector<uint32_t> touched;
    };
    tbb::enumerable_thread_specific<Scratch> scratch([&] { return Scratch{std::vector<float>(faces.size(), 0.0f), {}}; });
    tbb::parallel_for(size_t(0), regionKeys.size(), [&](size_t r) {
        Scratch& s = scratch.local();
        const auto first = std::lower_bound(all.begin(), all.end(), std::pair<Key, uint32_t>{regionKeys[r], 0u});
        auto last = first;
        while (last != all.end() && last->first == regionKeys[r]) ++last;
        // Enough probes in all to find a small bright patch, however few the faces.
        const uint32_t probeRays = std::max(settings.probeRays, uint32_t((kMinProbes + (last - first) - 1) / (last - first)));
        for (auto it = first; it != last; ++it) {
            const ExposedFace& face = faces[it->second];
            const FaceSquare q = squareOf(face);
            const uint64_t h = splitmix64(texelSeed(face, 0, 0) ^ 0x6775696465ull);
            const glm::dvec2 place(unitInterval(h), unitInterval(splitmix64(h))), turn(unitInterval(splitmix64(h ^ 1)),
                                                                                          unitInterval(splitmix64(h ^ 2)));
            for (uint32_t ray = 0; ray < probeRays; ++ray) {
                const glm::dvec2 at = r2(ray, place), u = r2(ray, turn);
                const glm::dvec3 start = q.corner + q.u * at.x + q.v * at.y + q.normal * 1e-4;
                const uint32_t hit = hitTexel(start, cosineAbout(q.normal, u.x, u.y));
                if (hit == missed) continue;
                const float l = float(luminance(glm::dvec3(sent[hit])));
                const uint32_t f = uint32_t(hit / perFace);
                if (!(l > 0.0f)) continue;
                if (s.sum[f] == 0.0f) s.touched.push_back(f);
                s.sum[f] += l;
            }
        }
        const size_t keep = std::min<size_t>(s.touched.size(), listed);
        std::partial_sort(s.touched.begin(), s.touched.begin() + ptrdiff_t(keep), s.touched.end(),
                          [&](uint32_t a, uint32_t b) { return s.sum[a] > s.sum[b] || (s.sum[a] == s.sum[b] && a < b); });
        lists_[r].assign(s.touched.begin(), s.touched.begin() + ptrdiff_t(keep));
        for (uint32_t f : s.touched) s.sum[f] = 0.0f;
        s.touched.clear();
    });
}

const std::vector<uint32_t>& BounceGuide::listOf(size_t m) const {
    return lists_[regionOfFace_[m / (size_t(k_) * k_)]];
}

Drawn BounceGuide::draw(const BrickTable& table, size_t m, glm::dvec3 point, glm::dvec3 normal, double epsilon, uint64_t seed,
                        std::span<uint32_t> cosineHits, double bounced, std::span<GuidedHit> out) const {
    std::fill(out.begin(), out.end(), GuidedHit{missed_, 0.0f});
    const std::vector<uint32_t>& list = listOf(m);
    const glm::dvec3 start = point + normal * epsilon;
    // Each listed face's share: its form factor from here times the light it sends.
    std::array<double, kMaxListed> share{};
    double total = 0.0, formFactors = 0.0;
    glm::dvec3 drawnLight(0.0);
    Drawn drawn;
    for (size_t i = 0; i < list.size(); ++i) {
        const FaceSquare q = squareOf(faces_[list[i]]);
        if (glm::length(q.centre() - point) < nearest_ || glm::dot(start - q.corner, q.normal) <= 0.0) continue;
        const glm::dvec3 corners[4] = {q.corner, q.corner + q.u, q.corner + q.u + q.v, q.corner + q.v};
        const double formFactor = polygonFormFactor(start, normal, corners);
        share[i] = formFactor * luminance(glm::dvec3(faceLight_[list[i]]));
        if (!(share[i] > 0.0)) continue;
        total += share[i], formFactors += formFactor;
        drawnLight += formFactor * glm::dvec3(faceLight_[list[i]]);
        drawn.faces |= uint32_t(1) << i;
    }
    if (drawn.faces == 0 || out.empty()) return {};

    uint64_t state = seed;
    auto next = [&] { return unitInterval(splitmix64(state++)); };
    const size_t perFace = size_t(k_) * k_;
    size_t at = 0;
    double below = 0.0;
    glm::dvec3 reached(0.0);  // the drawn rays' estimate of what the cosine rays' hits on drawn faces bring
    for (size_t s = 0; s < out.size(); ++s) {
        // Stratified over the shares, then a uniform point of the face drawn.
        const double target = (double(s) + next()) / double(out.size()) * total;
        while (at + 1 < list.size() && (share[at] == 0.0 || below + share[at] <= target)) below += share[at++];
        if (share[at] == 0.0) continue;  // only where rounding ran past the last share
        const FaceSquare q = squareOf(faces_[list[at]]);
        const double a = next(), b = next();
        const glm::dvec3 toPoint = q.corner + q.u * a + q.v * b - start;
        const double d2 = glm::dot(toPoint, toPoint);
        if (!(d2 > 0.0)) continue;
        const double d = std::sqrt(d2);
        const double cosHere = glm::dot(normal, toPoint) / d, cosThere = -glm::dot(q.normal, toPoint) / d;
        if (cosHere <= 0.0 || cosThere <= 0.0) continue;
        const uint32_t i = std::min(uint32_t(a * k_), k_ - 1), j = std::min(uint32_t(b * k_), k_ - 1);
        const double pdf = share[at] / total * double(out.size());  // per unit area of the face (its area is 1)
        const double weight = cosHere * cosThere / (std::numbers::pi * d2) / pdf;
        // Stop a hair short of the face itself: anything before it blocks.
        const bool blocked = table.hitWithin(start, toPoint / d, d * (1.0 - 1e-9) - 1e-7);
        if (!blocked) reached += weight * glm::dvec3(faceLight_[list[at]]);
        out[s] = {uint32_t(list[at] * perFace + j * k_ + i) | (blocked ? GuidedHit::kBlocked : 0u), float(weight)};
    }

    // The cosine rays: a hit on a drawn face counts for nothing but a control
    // variate: that face's mean light, whose mean over the cosine rays the drawn
    // rays estimate too (`reached`). Taken beta times: 1 where the rest of the
    // view is as bright as the drawn faces (a closed box of even light is then
    // exact), 0 where it is dark (the sunlit patch's light would then be counted
    // again, as unevenly as the cosine rays find it). beta: the rest's light over
    // the drawn faces', the variance-minimising weight when the two are not
    // correlated.
    const double faces = luminance(drawnLight);
    const double rest = formFactors < 0.999 ? (bounced - faces) / (1.0 - formFactors) : faces / formFactors;
    drawn.beta = float(std::clamp(rest / (faces / formFactors), 0.0, 1.0));
    drawn.guided = glm::vec3(-double(drawn.beta) * reached);
    takeIn(m, drawn, cosineHits);
    return drawn;
}

void BounceGuide::takeIn(size_t m, Drawn& drawn, std::span<uint32_t> hits) const {
    if (drawn.faces == 0) return;
    const std::vector<uint32_t>& list = listOf(m);
    const uint32_t perFace = k_ * k_;
    std::array<uint32_t, kMaxListed> drawnFaces;
    size_t count = 0;
    for (size_t i = 0; i < list.size(); ++i)
        if ((drawn.faces >> i) & 1) drawnFaces[count++] = list[i];
    glm::dvec3 marked(0.0);
    for (uint32_t& hit : hits) {
        if (hit >= kHitOnDrawnFace) continue;  // missed, dropped or marked
        const uint32_t face = hit / perFace;
        if (std::find(drawnFaces.begin(), drawnFaces.begin() + ptrdiff_t(count), face) == drawnFaces.begin() + ptrdiff_t(count))
            continue;
        hit |= kHitOnDrawnFace;
        marked += glm::dvec3(faceLight_[face]);
    }
    drawn.marked += glm::vec3(marked);
}

}  // namespace grotto::voxel
