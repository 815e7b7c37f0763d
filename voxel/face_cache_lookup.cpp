#include "voxel/face_cache_lookup.h"

#include "shaders/shared/quad.h"

#include <cmath>

namespace grotto::voxel {

FaceCacheLookup::FaceCacheLookup(std::span<const ExposedFace> faces, std::span<const FaceTexel> texels,
                                 uint32_t texelsPerSide)
    : texels_(texels), k_(texelsPerSide) {
    index_.reserve(faces.size());
    for (uint32_t f = 0; f < faces.size(); ++f) index_.emplace(faces[f], f);
}

int64_t FaceCacheLookup::find(const ExposedFace& face) const {
    const auto it = index_.find(face);
    return it == index_.end() ? -1 : int64_t(it->second);
}

CachedLight FaceCacheLookup::at(glm::dvec3 p, uint8_t dir) const {
    const int axis = int(gpu::faceAxis(dir)), ua = int(gpu::faceUAxis(dir)), va = int(gpu::faceVAxis(dir));
    const int plane = int(std::lround(p[axis]));
    glm::ivec3 cell(0);
    cell[axis] = gpu::facePositive(dir) ? plane - 1 : plane;
    // Texel-centre coordinates over the whole plane: centre (I, J) at (I + 0.5) / k.
    const double su = p[ua] * k_ - 0.5, sv = p[va] * k_ - 0.5;
    const double fu = std::floor(su), fv = std::floor(sv);
    const double wu = su - fu, wv = sv - fv;
    CachedLight out;
    double weight = 0.0, ao = 0.0, horizon = 0.0, zenith = 0.0, sun = 0.0;
    uint32_t fewest = UINT32_MAX;
    for (int c = 0; c < 4; ++c) {
        const int64_t I = int64_t(fu) + (c & 1), J = int64_t(fv) + (c >> 1);
        const double w = ((c & 1) ? wu : 1.0 - wu) * ((c >> 1) ? wv : 1.0 - wv);
        // Floor division: texel I lies on the face of cell floor(I / k).
        const int64_t cu = I >= 0 ? I / k_ : -((-I + k_ - 1) / k_), cv = J >= 0 ? J / k_ : -((-J + k_ - 1) / k_);
        glm::ivec3 q = cell;
        q[ua] = int(cu), q[va] = int(cv);
        const int64_t f = find({q, dir});
        if (f < 0 || w <= 0.0) continue;
        const FaceTexel& t = texels_[size_t(f) * k_ * k_ + size_t(J - cv * k_) * k_ + size_t(I - cu * k_)];
        if (t.samples == 0) continue;
        weight += w;
        ao += w * t.ao();
        horizon += w * t.skyHorizon / t.samples;
        zenith += w * t.skyZenith / t.samples;
        sun += w * t.sun();
        fewest = std::min(fewest, t.samples);
    }
    if (weight <= 0.0) return out;
    out.ao = ao / weight, out.skyHorizon = horizon / weight, out.skyZenith = zenith / weight, out.sun = sun / weight;
    out.samples = fewest;
    return out;
}

}  // namespace grotto::voxel
