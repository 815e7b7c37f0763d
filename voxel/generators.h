#pragma once
// Deterministic procedural worlds, written with OpenVDB. Conventions of the grids
// they return (world JSON "grid.rule" in brackets):
//   rooms, caves, city -> openvdb::Int32Grid "material" [int32]: value = material id >= 1
//   thin               -> openvdb::BoolGrid  "solid"    [mask]:  active = solid
//   sphere, mesh       -> openvdb::FloatGrid "surface"  [level_set]: narrow-band SDF
// Index space: Y up, the ground (where there is one) at y = 0.
#include "voxel/mkworld.h"

#include "voxel/openvdb_grids.h"

namespace grotto::voxel {

// Same seed and options -> the same grid, bit for bit.
openvdb::GridBase::Ptr generateWorld(const std::string& kind, const GeneratorOptions& options);

// What generating takes, bounded from the kind and size alone, before any of it
// is made: the 8^3 bricks its solid voxels reach (active tiles counted as the
// bricks they cover), how many of those its grid may hold as leaves (the rest
// are tiles, nearly free), and what one leaf of its grid costs. Throws as
// generateWorld does for an unknown kind or a size out of range.
struct GeneratedSize {
    double bricks = 0.0, leaves = 0.0;
    uint64_t leafBytes = 0;
};
GeneratedSize generatedSize(const std::string& kind, const GeneratorOptions& options);

}  // namespace grotto::voxel
