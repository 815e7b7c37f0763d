#include "engine/lab/sun_agreement.h"

#include "engine/lab/surface_points.h"
#include "voxel/daylight.h"

#include <glm/geometric.hpp>

#include <cmath>

namespace grotto {

voxel::Lighting sunAlone(const voxel::Lighting& lighting) {
    voxel::Lighting l = lighting;
    l.ambientFrom = voxel::AmbientSource::Color, l.ambientIntensity = 0.0f;
    return l;
}

namespace {

// Does a ray from world point `p` along `d` meet a solid voxel of the world or of an object?
bool blocked(const voxel::World& world, std::span<const voxel::PosedWorld> objects, glm::dvec3 p, glm::dvec3 d) {
    if (world.raycast(p, d, 1e7)) return true;
    for (const voxel::PosedWorld& o : objects)
        if (o.world->raycast(o.pose.toLocal(p), glm::conjugate(o.pose.rotation) * d, 1e7)) return true;
    return false;
}

bool glows(const voxel::World& world, int id) {
    const auto& m = world.desc().materials;
    return id >= 1 && size_t(id) <= m.size() && glm::length(m[size_t(id) - 1].emission()) > 0.0f;
}

}  // namespace

SunAgreement sunAgainstRays(const FrameImages& f, const Camera& camera, const voxel::World& world,
                            std::span<const voxel::PosedWorld> objects, const voxel::Lighting& lighting) {
    const voxel::Lighting l = voxel::lightingInEffect(lighting);
    const glm::dvec3 sun = glm::normalize(glm::dvec3(l.sunDirection));
    const glm::dvec3 radiance = glm::dvec3(l.sunColor) * double(l.sunIntensity) * double(l.exposure);
    const SurfacePoints sp = surfacePoints(f, camera, world, objects);
    SunAgreement s;
    for (size_t i = 0; i < sp.points.size(); ++i) {
        if (sp.owners[i] != 0) continue;
        ++s.surface;
        const double cosSun = glm::dot(sp.normals[i], sun);
        // The voxel behind the face: a glowing one adds light of its own.
        const glm::ivec3 cell(glm::floor((sp.points[i] - world.origin()) / world.voxelSize() - sp.normals[i] * 0.5));
        if (cosSun <= 0.0 || glows(world, world.material(cell))) continue;
        ++s.facing;
        // The brightest channel of the sun's light: the least relative rounding.
        const size_t p = sp.pixels[i];
        int c = radiance.r >= radiance.g && radiance.r >= radiance.b ? 0 : radiance.g >= radiance.b ? 1 : 2;
        const double full = double(f.albedo[3 * p + size_t(c)]) * radiance[c] * cosSun;
        const double exact = blocked(world, objects, sp.points[i] + sp.normals[i] * (1e-4 * world.voxelSize()), sun) ? 0.0 : 1.0;
        // No light from the sun (set, or a black surface): its term is 0 whatever its visibility.
        const double shown = full > 0.0 ? double(f.color[4 * p + size_t(c)]) / full : exact;
        s.off += std::abs(shown - exact) > 0.5;
        s.aovOff += !f.shadow.empty() && std::abs(double(f.shadow[p]) - exact) > 0.25;
    }
    return s;
}

}  // namespace grotto
