#pragma once
// Deterministic procedural worlds, written with OpenVDB. Conventions of the grids
// they return (world JSON "grid.rule" in brackets):
//   rooms, caves, city -> openvdb::Int32Grid "material" [int32]: value = material id >= 1
//   thin               -> openvdb::BoolGrid  "solid"    [mask]:  active = solid
//   sphere, mesh       -> openvdb::FloatGrid "surface"  [level_set]: narrow-band SDF
// Index space: Y up, the ground (where there is one) at y = 0.
#include "voxel/mkworld.h"

#include <openvdb/openvdb.h>

namespace grotto::voxel {

// Same seed and options -> the same grid, bit for bit.
openvdb::GridBase::Ptr generateWorld(const std::string& kind, const GeneratorOptions& options);

}  // namespace grotto::voxel
