#include "engine/frame/object_frame.h"

#include "shaders/shared/quad.h"

namespace grotto {

glm::dvec3 surfaceNormal(uint32_t id, std::span<const voxel::ObjectPose> poses) {
    const uint32_t face = gpu::surfaceFace(id), object = gpu::surfaceObject(id);
    glm::dvec3 n(0.0);
    n[gpu::faceAxis(face)] = gpu::facePositive(face) ? 1.0 : -1.0;
    if (object == 0 || object > poses.size()) return n;
    return poses[object - 1].rotation * n;
}

void normalTable(glm::vec4* table, const glm::dmat3& rotation, std::span<const voxel::ObjectPose> poses) {
    for (uint32_t slot = 0; slot < GROTTO_NORMAL_SLOTS; ++slot) {
        const uint32_t object = slot / 8, face = slot % 8;
        table[slot] = glm::vec4(0.0f);
        if (face >= 6 || object > poses.size()) continue;
        const glm::dvec3 n = surfaceNormal(gpu::surfaceWithObject(gpu::packSurface(face, 0), object), poses);
        table[slot] = glm::vec4(glm::vec3(rotation * n), 0.0f);
    }
}

gpu::ObjectUniforms objectUniforms(std::span<const voxel::ObjectPose> poses, const Camera& previousCamera,
                                   std::span<const voxel::ObjectPose> previousPoses) {
    gpu::ObjectUniforms u{};
    normalTable(u.worldNormals, glm::dmat3(1.0), poses);
    normalTable(u.previousViewNormals, glm::transpose(previousCamera.basis), previousPoses);
    return u;
}

}  // namespace grotto
