#pragma once
// What a world file says about its objects: extra voxel models (a .vdb of their
// own or a generator) placed in the world with a transform over time, as plain
// data ("objects" in docs/worlds.md). OpenVDB-free; voxel/object_pose.h
// evaluates the keys, voxel/object_worlds.h loads the voxels.
#include "voxel/mkworld.h"

#include <glm/gtc/quaternion.hpp>
#include <glm/vec3.hpp>

#include <filesystem>
#include <string>
#include <vector>

namespace grotto::voxel {

class Reader;
enum class SolidRule;  // voxel/world_desc.h

// At most this many objects per world: the G-buffer's surface id keeps an
// object's index in 5 bits (shaders/shared/objects.h), 0 being the world.
inline constexpr size_t kMaxObjects = 31;

struct ObjectKey {
    double time = 0.0;                          // seconds; strictly increasing, >= 0
    glm::dvec3 position{0.0};                   // where the pivot is, world units
    glm::dquat rotation{1.0, 0.0, 0.0, 0.0};    // object-local to world, unit length
};

struct ObjectDesc {
    std::string name;
    // Either a grid file (resolved path; name, rule, threshold and material as a
    // world's "grid" block) ...
    std::filesystem::path gridFile;
    std::string gridName;
    SolidRule rule{};                            // SolidRule::Auto
    double threshold = 0.5;
    int material = 1;
    // ... or a generator: a `grotto mkworld` kind, or "box" (a solid box of
    // boxSize voxels of `material`).
    std::string generator;
    GeneratorOptions generatorOptions;
    glm::ivec3 boxSize{0};
    glm::dvec3 pivot{0.0};                       // object-local world units: what rotations turn about
    std::vector<ObjectKey> keys;                 // at least one

    // More than one distinct pose: the object moves (and the renderer needs motion vectors).
    bool moves() const;
};

// Reads the "objects" array of a world file from its reader; `palette` is the
// number of the world's materials. Throws grotto::Error (input) naming the file
// and the field for anything missing, malformed, unknown or outside the palette.
std::vector<ObjectDesc> parseObjects(Reader& world, const std::filesystem::path& file, size_t palette);

}  // namespace grotto::voxel
