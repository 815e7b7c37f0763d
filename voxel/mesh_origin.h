#pragma once
// Where an exported mesh sits (export-mesh --origin). A world's own coordinates
// put a MagicaVoxel model's centre at the origin and a generated world wherever
// its generator did; an editor's scene wants the model standing on its ground.
#include "voxel/world.h"

#include <string>

namespace grotto::voxel {

enum class MeshOrigin {
    Base,    // the bounds centred in x and z, their bottom on y = 0: on the ground
    Centre,  // the bounds' centre at the origin
    World,   // the world's own coordinates: a camera path lines up with it
};

// "base", "centre" (or "center") and "world"; throws grotto::Error (input) naming `flag` otherwise.
MeshOrigin meshOrigin(const std::string& name, const std::string& flag);
const char* meshOriginName(MeshOrigin origin);

// What to add to a world position to place it as `origin` says (0 for World or empty bounds).
glm::dvec3 meshShift(const World& world, MeshOrigin origin);

}  // namespace grotto::voxel
