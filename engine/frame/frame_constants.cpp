#include "engine/frame/frame_constants.h"

#include "engine/frame/frame_plan.h"
#include "engine/frame/sky_light.h"
#include "shaders/shared/tone_map.h"

#include <cmath>

namespace grotto {

gpu::FrameUniforms frameUniforms(const Camera& camera, const voxel::Lighting& l, const AoOptions& ao) {
    gpu::FrameUniforms u{};
    u.viewProj = camera.viewProjRelative();
    u.sunDirection = glm::vec4(l.sunDirection, l.sunAngle > 0.0f ? 0.0f : 1.0f);
    u.sunRadiance = glm::vec4(l.sunColor * l.sunIntensity, 0.0f);
    const voxel::AmbientSource source = ambientSource(l, ao);
    if (source != voxel::AmbientSource::Color) {  // w: 1 the sky's light, 2 the face cache's full light
        u.ambient = glm::vec4(glm::vec3(l.ambientIntensity), source == voxel::AmbientSource::Full ? 2.0f : 1.0f);
        const auto rows = skyLightTable(l.skyZenith, l.skyHorizon);
        for (int k = 0; k < GROTTO_SKY_LIGHT_ROWS; ++k) u.skyLight[k] = glm::vec4(rows[k], 0.0f);
    } else {
        u.ambient = glm::vec4(l.ambientColor * l.ambientIntensity, 0.0f);
    }
    u.skyZenith = glm::vec4(l.skyZenith, 0.0f);
    u.skyHorizon = glm::vec4(l.skyHorizon, 0.0f);
    // rayDirection() is linear in the pixel position before normalising.
    const double t = std::tan(camera.fovY * 0.5);
    const glm::dvec3 right = camera.basis[0] * (2.0 * t * camera.aspect() / camera.width);
    const glm::dvec3 down = -camera.basis[1] * (2.0 * t / camera.height);
    const glm::dvec3 corner = -camera.basis[2] - camera.basis[0] * (t * camera.aspect()) + camera.basis[1] * t;
    u.rayOrigin = glm::vec4(glm::vec3(corner), 0.0f);
    u.rayStepX = glm::vec4(glm::vec3(right), 0.0f);
    u.rayStepY = glm::vec4(glm::vec3(down), 0.0f);
    u.aoStrength = glm::vec4(ao.enabled ? ao.chain.strength : 0.0f, 0.0f, 0.0f, 0.0f);
    u.exposure = glm::vec4(l.exposure, 0.0f, 0.0f, 0.0f);
    u.size = {camera.width, camera.height};
    const glm::dmat4 p = camera.projection();
    u.depthAB = glm::vec4(float(p[2][2]), float(p[3][2]), 0.0f, 0.0f);
    return u;
}

gpu::GtaoConstants gtaoConstants(const Camera& camera, const gpu::GtaoSettings& settings, uint32_t frameIndex,
                                 uint32_t scale) {
    gpu::GtaoConstants c{};
    c.settings = settings;
    const double tanY = std::tan(camera.fovY * 0.5), tanX = tanY * camera.aspect();
    c.ndcToViewMul_Add = glm::vec4(float(2.0 * tanX / camera.width), float(-2.0 * tanY / camera.height),
                                   float(-tanX), float(tanY));
    for (int f = 0; f < 6; ++f) {
        glm::dvec3 n(0.0);
        n[f / 2] = f % 2 == 0 ? 1.0 : -1.0;
        // World to view is the transpose of the camera basis.
        c.viewNormals[f] = glm::vec4(glm::vec3(glm::transpose(camera.basis) * n), 0.0f);
    }
    c.fullSize = {camera.width, camera.height};
    c.scale = scale;
    c.halfSize = {(camera.width + scale - 1) / scale, (camera.height + scale - 1) / scale};
    c.frameIndex = frameIndex;
    c.pixelViewSize = float(scale * 2.0 * tanX / camera.width);  // an AO pixel spans `scale`
    const glm::dmat4 p = camera.projection();
    c.depthA = float(p[2][2]);
    c.depthB = float(p[3][2]);
    return c;
}

gpu::TemporalConstants temporalConstants(const Camera& current, const Camera* previous) {
    gpu::TemporalConstants t{};
    t.reset = previous ? 0u : 1u;
    const Camera& prev = previous ? *previous : current;
    // Rotation and the camera's step, never an absolute position: exact far from the origin.
    const glm::dmat3 rotation = glm::transpose(prev.basis) * current.basis;
    glm::dmat4 m(rotation);
    m[3] = glm::dvec4(glm::transpose(prev.basis) * (current.position - prev.position), 1.0);
    t.currentToPrevious = glm::mat4(m);
    const gpu::GtaoConstants g = gtaoConstants(prev, {}, 0);
    t.previousNdcToViewMul_Add = g.ndcToViewMul_Add;
    for (int f = 0; f < 6; ++f) t.previousViewNormals[f] = g.viewNormals[f];
    for (int k = 0; k < 3; ++k) t.viewToWorld[k] = glm::vec4(glm::vec3(current.basis[k]), 0.0f);
    return t;
}

uint32_t toneMapCurve(voxel::ToneMap t) { return t == voxel::ToneMap::Filmic ? GROTTO_TONE_MAP_FILMIC : GROTTO_TONE_MAP_CLAMP; }

}  // namespace grotto
