#pragma once
// The side planes and near plane of a camera's frustum in camera-relative world
// space (from the rows of the view-projection matrix; the far plane only when
// finite), for culling boxes.
#include "engine/camera.h"

namespace grotto {

struct Frustum {
    glm::vec4 planes[6];
    int count = 5;
    explicit Frustum(const Camera& camera) {
        const glm::mat4 m = glm::transpose(camera.viewProjRelative());  // m[i] = row i
        planes[0] = m[3] + m[0];
        planes[1] = m[3] - m[0];
        planes[2] = m[3] + m[1];
        planes[3] = m[3] - m[1];
        planes[4] = m[3] - m[2];  // reverse-Z: depth <= 1 in front of the near plane
        if (camera.farPlane > 0.0) planes[count++] = m[2];  // depth >= 0
    }
    // True when the box lies wholly outside one plane.
    bool outside(const glm::vec3& lo, const glm::vec3& hi) const {
        for (int i = 0; i < count; ++i) {
            const glm::vec4& p = planes[i];
            const glm::vec3 corner(p.x >= 0 ? hi.x : lo.x, p.y >= 0 ? hi.y : lo.y, p.z >= 0 ? hi.z : lo.z);
            if (glm::dot(glm::vec3(p), corner) + p.w < 0.0f) return true;
        }
        return false;
    }
};

}  // namespace grotto
