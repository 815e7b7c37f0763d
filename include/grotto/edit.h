#pragma once
// Edits of a world as plain data: set one voxel, fill or carve a box or a sphere,
// paint the material of solid voxels; and what an edit changed. A game makes
// these and hands them to Engine::edit; Grotto's own paths and commands carry the
// same types.
#include <glm/vec3.hpp>

#include <cstdint>

namespace grotto {

// Inclusive range of voxel indices; empty() when it holds none.
struct IndexBox {
    glm::ivec3 min{0}, max{-1};
    bool empty() const { return max.x < min.x || max.y < min.y || max.z < min.z; }
    bool contains(glm::ivec3 v) const {
        return v.x >= min.x && v.y >= min.y && v.z >= min.z && v.x <= max.x && v.y <= max.y && v.z <= max.z;
    }
    // The smallest box holding both (either may be empty).
    IndexBox merged(const IndexBox& o) const;
};

// An axis-aligned box in world units; empty() when min > max on an axis.
struct WorldBox {
    glm::dvec3 min{0.0}, max{-1.0};
    bool empty() const { return max.x < min.x || max.y < min.y || max.z < min.z; }
    WorldBox grown(double by) const { return empty() ? *this : WorldBox{min - by, max + by}; }
    WorldBox merged(const WorldBox& o) const;
};

struct Edit {
    enum class Op { Fill, Carve, Paint };  // make solid with `material`; make empty; recolour solid voxels only
    enum class Shape { Box, Sphere };
    Op op = Op::Fill;
    Shape shape = Shape::Box;
    IndexBox box;                 // Box: the voxels, inclusive (a single voxel is a 1x1x1 box)
    glm::dvec3 centre{0.0};       // Sphere: world units; a voxel is inside when its centre is
    double radius = 0.0;          // Sphere: world units, > 0
    int material = 1;             // Fill and Paint: material id, 1..GROTTO_MAX_MATERIALS

    static Edit setVoxel(glm::ivec3 voxel, int material) {  // material 0 = make empty
        return material == 0 ? Edit{.op = Op::Carve, .box = {voxel, voxel}}
                             : Edit{.op = Op::Fill, .box = {voxel, voxel}, .material = material};
    }
    static Edit fillBox(IndexBox b, int material) { return {.op = Op::Fill, .box = b, .material = material}; }
    static Edit carveBox(IndexBox b) { return {.op = Op::Carve, .box = b}; }
    static Edit fillSphere(glm::dvec3 c, double r, int material) {
        return {.op = Op::Fill, .shape = Shape::Sphere, .centre = c, .radius = r, .material = material};
    }
    static Edit carveSphere(glm::dvec3 c, double r) {
        return {.op = Op::Carve, .shape = Shape::Sphere, .centre = c, .radius = r};
    }
    static Edit paintBox(IndexBox b, int material) { return {.op = Op::Paint, .box = b, .material = material}; }
    static Edit paintSphere(glm::dvec3 c, double r, int material) {
        return {.op = Op::Paint, .shape = Shape::Sphere, .centre = c, .radius = r, .material = material};
    }
};

// What one edit (or its undo) changed.
struct EditResult {
    IndexBox voxels;        // the voxels whose solidity or material changed (tight); empty if none
    WorldBox box;           // the same, in world units (voxel corners)
    uint64_t changed = 0;   // how many voxels changed
};

}  // namespace grotto
