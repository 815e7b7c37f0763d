#pragma once
// MagicaVoxel .vox files as worlds (voxel/vox_read.h reads them): the palette as
// the world's materials, and (voxGrid, voxel/solid.h) the placed models as an
// int32 grid whose values are colour indices. OpenVDB-free.
#include "voxel/vox_read.h"
#include "voxel/world_desc.h"

#include <filesystem>
#include <vector>

namespace grotto::voxel {

// A file named *.vox (any case).
bool isVoxFile(const std::filesystem::path& path);

// Materials 1 .. the highest colour index any visible voxel uses: material k is
// colour index k, its albedo the palette's colour made linear (MagicaVoxel's
// palette is sRGB). An _emit material glows in its colour (vox_world.cpp says
// how _emit and _flux scale it); the other MATL properties are not modelled, and
// the name says the type.
std::vector<Material> voxMaterials(const VoxScene& scene);

}  // namespace grotto::voxel
