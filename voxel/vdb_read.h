#pragma once
// Reading one grid from a .vdb file with OpenVDB, checked. Internal to voxel/;
// loadGrid (voxel/solid.h) runs this first in a limited reader process.
#include "voxel/world_desc.h"

#include <glm/vec3.hpp>
#include <openvdb/openvdb.h>

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <string>

namespace grotto::voxel {

// The reader's memory for a grid whose size is unknown, and its CPU time: one
// second plus one per this much file (a 9 MiB world reads in 0.25 s here).
constexpr size_t kReaderMemoryBytes = size_t(512) << 20;
constexpr uintmax_t kReaderBytesPerCpuSecond = uintmax_t(8) << 20;

// Registers OpenVDB's grid types, once per process (before any file is read or written).
void initializeOpenVdb();

// Where a grid's voxels are: their size and the corner of voxel (0, 0, 0).
struct GridPlacement {
    double voxelSize = 1.0;
    glm::dvec3 origin{0.0};
};

// Voxel size and corner origin from a uniform, axis-aligned transform (else Error).
GridPlacement readTransform(const openvdb::GridBase& grid, const std::string& file);

// Opens desc.gridFile (or openAs, when given; errors still name desc.gridFile)
// and reads the named grid (or the first), refusing a bad transform or a size
// over the budget before reading voxels. onEstimate gets the size the grid's
// metadata states, once it is known to be within the budget. No limits: what
// the reader process runs; fuzzers call it directly so that a crash shows.
openvdb::GridBase::Ptr readGridUnguarded(const WorldDesc& desc, const std::function<void(size_t)>& onEstimate = {},
                                         const std::filesystem::path& openAs = {});

}  // namespace grotto::voxel
