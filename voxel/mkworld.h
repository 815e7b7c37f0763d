#pragma once
// `grotto mkworld`: writes a generated world to a .vdb file (atomically).
// OpenVDB-free, so the command line does not compile OpenVDB's headers.
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace grotto::voxel {

struct GeneratorOptions {
    uint32_t seed = 1;
    int size = 0;              // horizontal extent in voxels; 0 = the kind's default
    double voxelSize = 1.0;    // world units per voxel
    std::string meshFile;      // `mesh` only: an OBJ or PLY to voxelise
    bool lamps = false;        // `houses` only: a lamp (material 6) on each room's ceiling
};

// The kinds accepted, in the order `mkworld --help` lists them.
const std::vector<std::string>& worldKinds();

// Generates `kind` and writes it to `out` (a .vdb). Throws grotto::Error (input)
// for an unknown kind, bad options, an unreadable mesh or an unwritable output.
void makeWorldFile(const std::string& kind, const GeneratorOptions& options,
                   const std::filesystem::path& out);

}  // namespace grotto::voxel
