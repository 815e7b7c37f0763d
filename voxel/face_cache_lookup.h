#pragma once
// Reading the face cache at a surface point, as the composite reads it on the GPU:
// the four texel centres nearest the point on its face plane, bilinearly, where a
// centre on a coplanar neighbouring face counts when that face is exposed too (so
// the light runs on across face edges), and drops out (the others reweighted)
// where the neighbour is open or covered (convex and concave edges).
#include "voxel/face_cache.h"

#include <glm/vec3.hpp>

#include <cstdint>
#include <span>
#include <unordered_map>
#include <vector>

namespace grotto::voxel {

// What a point reads: AO, sky light weights (per ray), sun visibility, and the
// fewest samples among the texels it blends (its confidence).
struct CachedLight {
    double ao = 1.0, skyHorizon = 0.0, skyZenith = 0.0, sun = 1.0;
    uint32_t samples = 0;
};

class FaceCacheLookup {
public:
    // `faces` as exposedFaces lists them; `texels` k x k per face in the same order.
    FaceCacheLookup(std::span<const ExposedFace> faces, std::span<const FaceTexel> texels, uint32_t texelsPerSide);
    // A point in voxel index units on the plane of an exposed face looking `dir`.
    // A point on no exposed face reads the defaults (open, unlit by sky, samples 0).
    CachedLight at(glm::dvec3 point, uint8_t dir) const;
    // The face's index, or -1 when it is not exposed.
    int64_t find(const ExposedFace& face) const;

private:
    struct Hash {
        size_t operator()(const ExposedFace& f) const {
            return size_t(uint32_t(f.cell.x)) * 73856093u ^ size_t(uint32_t(f.cell.y)) * 19349663u ^
                   size_t(uint32_t(f.cell.z)) * 83492791u ^ size_t(f.dir) * 2654435761u;
        }
    };
    std::unordered_map<ExposedFace, uint32_t, Hash> index_;
    std::span<const FaceTexel> texels_;
    uint32_t k_;
};

}  // namespace grotto::voxel
