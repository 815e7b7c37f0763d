#pragma once
// Rays drawn toward the faces that pass a region most of its bounced light. A
// room lit by the sun through a hole takes nearly all its light off the sunlit
// patch on its floor; a texel's cosine rays find that patch a few times in a
// hundred, so texels next to each other read it differently (blotches).
//
// Each region (the faces looking one way in one 8^3 brick) casts probe rays from
// every one of its faces and lists the faces they found sending the most light
// back. A texel's bounced light then comes in two parts, each unbiased:
//  - the listed faces in its view: rays drawn toward uniform points on them,
//    each face chosen in proportion to its form factor (closed form) times its
//    mean light, each ray weighted by its share of the area integral;
//  - everything else: its cosine rays. One that hits a listed face counts beta
//    times that face's mean light, a control variate whose mean the drawn rays
//    estimate too: with beta 1 a closed box of even light is exact, with beta 0
//    (the rest of the view dark beside the face) the face is left to the drawn
//    rays alone.
// The probes are fixed by the region's faces alone: a texel's own rays never
// decide what it draws toward, and a region relit after an edit draws toward
// what a fresh bake would.
#include "voxel/face_cache.h"

#include <glm/vec3.hpp>

#include <algorithm>
#include <cstdint>
#include <functional>
#include <span>
#include <vector>

namespace grotto::voxel {

class BrickTable;

// One drawn ray: the texel it was drawn to, kBlocked added when something stood
// between, and its weight: weight x what that texel sends (0 when blocked) is
// the ray's share of the receiving texel's light (irradiance over pi).
struct GuidedHit {
    static constexpr uint32_t kBlocked = 1u << 31;
    uint32_t texel;
    float weight;
    bool reached() const { return (texel & kBlocked) == 0; }
};

// A cosine ray's hit on a face the texel drew toward: counted for nothing but
// beta times that face's mean light (the hit texel, this bit added).
inline constexpr uint32_t kHitOnDrawnFace = 1u << 31;

// What a texel drew: the faces it drew toward (bits of its region's list), and
// what it adds to the light its rays reach (bounce_guide.cpp): beta times the
// mean light of the faces its cosine rays hit among those drawn toward
// (`marked`, summed over the rays), less beta times the drawn rays' estimate of
// the same (`guided`).
struct Drawn {
    uint32_t faces = 0;
    float beta = 0.0f;
    glm::vec3 guided{0.0f}, marked{0.0f};
    // For a texel with `rays` cosine rays.
    glm::vec3 base(uint32_t rays) const { return guided + beta * marked / float(std::max(rays, 1u)); }
};

class BounceGuide {
public:
    static constexpr uint32_t kMaxListed = 32;  // Drawn::faces' bits
    struct Settings {
        uint32_t listed = 16;     // faces a region lists (at most kMaxListed)
        uint32_t probeRays = 32;  // cosine rays from each face of a region, to find them
        // A texel draws toward no face nearer it than this (voxels, to the face's
        // centre): near a face its area samples would be noisier than the cosine rays.
        double nearest = 2.0;
    };
    static constexpr uint32_t kMinProbes = 256;  // probes a region casts at the least, over all its faces
    // The texel a ray from `start` along `dir` (voxel index units) hits first, or `missed`.
    using HitTexel = std::function<uint32_t(glm::dvec3 start, glm::dvec3 dir)>;
    // Lists, for the regions of the faces `relit`, the faces their probe rays see
    // sending the most light back (`sent`: what every texel of `faces` sends, k x k
    // a face, converged).
    BounceGuide(std::span<const ExposedFace> faces, uint32_t k, std::span<const uint32_t> relit,
                std::span<const glm::vec3> sent, uint32_t missed, const Settings& settings, const HitTexel& hitTexel);

    // Draws out.size() rays for the m-th relit texel (at `point` on its face,
    // `normal` its normal), stratified over its listed faces, from `seed`, then
    // takes in its base cosine rays' hits as `takeIn` does. `bounced`: the
    // luminance of the light they brought in the passes so far. Drew toward no
    // face when nothing listed is in its view.
    Drawn draw(const BrickTable& table, size_t m, glm::dvec3 point, glm::dvec3 normal, double epsilon, uint64_t seed,
               std::span<uint32_t> cosineHits, double bounced, std::span<GuidedHit> out) const;
    // Marks the hits on the faces drawn toward (kHitOnDrawnFace), their mean
    // light added to drawn.marked.
    void takeIn(size_t m, Drawn& drawn, std::span<uint32_t> hits) const;

    // The mean light `face` sends, as the lists were made.
    glm::vec3 faceLight(uint32_t face) const { return faceLight_[face]; }

private:
    const std::vector<uint32_t>& listOf(size_t m) const;

    std::span<const ExposedFace> faces_;
    uint32_t k_, missed_;
    double nearest_;
    std::vector<uint32_t> regionOfFace_;           // per relit face
    std::vector<std::vector<uint32_t>> lists_;     // per region
    std::vector<glm::vec3> faceLight_;             // per face: what its texels send, averaged
};

}  // namespace grotto::voxel
