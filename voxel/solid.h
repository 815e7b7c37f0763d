#pragma once
// Internal to voxel/: the OpenVDB side of a World.
#include "voxel/edit_history.h"
#include "voxel/vdb_read.h"
#include "voxel/world.h"

#include "voxel/openvdb_grids.h"

#include <functional>

namespace grotto::voxel {

struct World::Impl {
    WorldDesc desc;
    openvdb::MaskGrid::Ptr solid;            // active = solid; tiles kept as tiles
    openvdb::Int32Grid::Ptr materials;       // int32 worlds (and painted ones): per-voxel material id
    int uniformMaterial = 1;                 // every other world
    IndexBox bounds;                         // of the solid voxels, cached once built
    double voxelSize = 1.0;
    glm::dvec3 origin{0.0};
    size_t sourceGridBytes = 0;
    uint64_t workBytesEstimate = 0;          // WorldStats::workBytesEstimate
    // What save() writes back: the source grid's name, type and metadata.
    std::string gridName = "solid";
    std::string sourceType;                  // openvdb type name, e.g. "Tree_bool_5_4_3"
    openvdb::MetaMap::ConstPtr sourceMeta;   // never changed after load: shared by copies
    EditHistory history;
};

// What one brick costs while the world is built or edited: its entry in
// World::bricks()'s list and its occupancy in the reference's brick table.
constexpr uint64_t kBytesPerBrick = sizeof(Brick) + 64;

// What a leaf node costs (a tile costs next to nothing), for estimates made
// before the grid exists: mask and bool leaves hold bits; int32 and float
// leaves hold 512 values besides, on the heap.
constexpr uint64_t kMaskLeafBytes = sizeof(openvdb::BoolTree::LeafNodeType);
constexpr uint64_t kValueLeafBytes = sizeof(openvdb::Int32Tree::LeafNodeType) + 512 * sizeof(int32_t);

// Bricks a solid tree stands for: its leaves, and every active tile as the full
// bricks World::bricks() splits it into. Leaves are counted, not walked.
uint64_t brickCount(const openvdb::MaskTree& tree);

// The memory a world's work may take: its budget, or less when the process may
// not map that much more (an address-space limit, `ulimit -v`), so an estimate
// past what would fail anyway is refused before the work instead of after it.
size_t memoryRoom(size_t budget);

// "N bricks of 8^3 voxels, an estimated X MiB, more than the memory budget of Y MiB"
// (or "... than the Y MiB of address space this process may still map"): the
// figures every refusal over memoryRoom(budget) gives.
std::string overBudget(double bricks, double bytes, size_t budget);

// Opens desc.gridFile and reads the named grid (or the first): readGridUnguarded,
// but a damaged or hostile file is refused within bounded memory and CPU time,
// because a reader process under limits reads it first. Throws grotto::Error.
openvdb::GridBase::Ptr loadGrid(const WorldDesc& desc);

// A MagicaVoxel scene's visible voxels as an int32 grid of colour indices (one
// world unit a voxel, MagicaVoxel's origin at 0; voxel/vox_world.h), refused over
// desc.memoryBudgetBytes before any voxel is placed.
struct VoxScene;
openvdb::GridBase::Ptr voxGrid(const VoxScene& scene, const WorldDesc& desc);

// Applies the solid rule; fills impl.solid, impl.materials, impl.uniformMaterial.
void buildSolid(const openvdb::GridBase::Ptr& grid, World::Impl& impl);

// Writes one grid to a .vdb atomically, every write checked (common/atomic_file.h).
// Throws grotto::Error naming `out`.
void writeGridFile(const openvdb::GridBase::ConstPtr& grid, const std::filesystem::path& out);

// A World around an in-memory grid (tests and generators).
World makeWorld(const openvdb::GridBase::Ptr& grid, WorldDesc desc);

}  // namespace grotto::voxel
