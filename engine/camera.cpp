#include "engine/camera.h"

#include "voxel/world.h"

#include <cmath>
#include <limits>

namespace grotto {

Camera makeCamera(const voxel::CameraDesc& d, uint32_t width, uint32_t height) {
    Camera c;
    c.position = d.position;
    c.basis = lookAtBasis(d.position, d.target);
    c.fovY = glm::radians(d.fovDegrees);
    c.nearPlane = d.nearPlane;
    c.farPlane = d.farPlane;
    c.width = width;
    c.height = height;
    return c;
}

Camera worldCamera(const voxel::World& world, const std::string& name, uint32_t width, uint32_t height) {
    return makeCamera(world.camera(name, double(width) / double(height)), width, height);
}

glm::dmat4 Camera::viewFromWorld() const {
    const glm::dmat3 r = glm::transpose(basis);
    glm::dmat4 m(r);
    m[3] = glm::dvec4(-(r * position), 1.0);
    return m;
}

glm::dmat4 Camera::projection(bool flipY) const {
    const double f = 1.0 / std::tan(fovY * 0.5);
    glm::dmat4 p(0.0);
    p[0][0] = f / aspect();
    p[1][1] = flipY ? -f : f;
    p[2][3] = -1.0;  // clip w = -z_view
    if (farPlane > 0.0) {
        p[2][2] = nearPlane / (farPlane - nearPlane);
        p[3][2] = nearPlane * farPlane / (farPlane - nearPlane);
    } else {
        p[2][2] = 0.0;
        p[3][2] = nearPlane;
    }
    return p;
}

glm::dmat4 Camera::viewProjRelativeDouble() const { return projection() * glm::dmat4(glm::transpose(basis)); }

glm::mat4 Camera::viewProjRelative() const {
    return glm::mat4(viewProjRelativeDouble());
}

double Camera::linearDepth(double depth) const {
    const glm::dmat4 p = projection();
    const double denom = depth + p[2][2];
    return denom > 0.0 ? p[3][2] / denom : std::numeric_limits<double>::infinity();
}

glm::dvec3 Camera::rayDirection(double px, double py) const {
    const double t = std::tan(fovY * 0.5);
    const double x = (2.0 * px / width - 1.0) * t * aspect();
    const double y = (1.0 - 2.0 * py / height) * t;
    return glm::normalize(basis * glm::dvec3(x, y, -1.0));
}

glm::dvec3 Camera::pointAt(double px, double py, double viewDepth) const {
    const glm::dvec3 dir = rayDirection(px, py);
    return position + dir * (viewDepth / glm::dot(dir, -basis[2]));
}

CameraVoxel cameraVoxel(const Camera& camera, double voxelSize, glm::dvec3 worldOrigin) {
    const double limit = double(voxel::kMaxVoxelIndex) * 1.5;
    const glm::dvec3 index = glm::clamp((camera.position - worldOrigin) / voxelSize, -limit, limit);
    const glm::dvec3 cell = glm::floor(index);
    return {glm::ivec3(cell), glm::vec3(index - cell)};
}

}  // namespace grotto
