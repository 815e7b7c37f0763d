#pragma once
// The world's glowing materials as lights: each one's radiance, the area of its
// faces open to the air, and the power it gives off, for `grotto info` and for
// whatever weighs lights by their power.
#include "voxel/world.h"

#include <glm/vec3.hpp>

#include <span>
#include <vector>

namespace grotto::voxel {

struct Emitter {
    int material = 0;         // palette id
    glm::dvec3 radiance{0.0};  // emissionColor x emissionIntensity
    double area = 0.0;        // its exposed faces, world units squared (the world's and the objects')
    // Radiant flux of a Lambertian emitter: pi x radiance x area, per channel,
    // in radiance x world units squared.
    glm::dvec3 power() const { return 3.14159265358979323846 * radiance * area; }
};

// The materials that glow and that some exposed face of the world or of
// `objects` (which share the world's palette) shows, in id order.
std::vector<Emitter> emitters(const World& world, std::span<const World> objects);

}  // namespace grotto::voxel
