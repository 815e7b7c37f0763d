#pragma once
// A voxel face's unit square, in voxel index units: the corner it starts at, its
// U and V edges (shaders/shared/quad.h's axes) and its outward normal. What
// rays drawn toward a face (a glowing one, a bright one) sample points of.
#include "shaders/shared/quad.h"
#include "voxel/face_cache.h"

#include <glm/vec3.hpp>

namespace grotto::voxel {

struct FaceSquare {
    glm::dvec3 corner, u, v, normal;
    glm::dvec3 centre() const { return corner + 0.5 * (u + v); }
};

inline FaceSquare squareOf(const ExposedFace& f) {
    glm::dvec3 corner(f.cell), u(0.0), v(0.0);
    corner[int(gpu::faceAxis(f.dir))] += gpu::facePositive(f.dir) ? 1.0 : 0.0;
    u[int(gpu::faceUAxis(f.dir))] = 1.0;
    v[int(gpu::faceVAxis(f.dir))] = 1.0;
    return {corner, u, v, faceNormal(f.dir)};
}

}  // namespace grotto::voxel
