// World::voxelsByMaterial: every solid voxel's material counted once, tiles
// included (counted whole where the material grid is uniform over them, voxel by
// voxel where a voxel inside differs), and a world without a material grid.
#include "voxel/world.h"
#include "voxel/world_from_grid.h"

#include <gtest/gtest.h>
#include "voxel/openvdb_grids.h"

namespace grotto::voxel {
namespace {

TEST(WorldMaterials, CountsVoxelsTilesAndMixedTiles) {
    openvdb::initialize();
    auto grid = openvdb::Int32Grid::create(0);
    openvdb::Int32Tree& tree = grid->tree();
    tree.addTile(2, openvdb::Coord(128, 0, 0), 4, true);  // a 128^3 tile of material 4
    tree.addTile(1, openvdb::Coord(0, 0, 0), 3, true);    // an 8^3 tile of material 3
    tree.addTile(1, openvdb::Coord(16, 0, 0), 3, true);   // another, one voxel of it painted 5
    tree.setValueOn(openvdb::Coord(17, 2, 3), 5);
    tree.setValueOn(openvdb::Coord(40, 0, 0), 2);         // a lone voxel
    WorldDesc desc;
    desc.rule = SolidRule::Int32;
    desc.materials.resize(6);
    const World w = worldFromGrid(*grid, desc);
    const std::vector<uint64_t> counts = w.voxelsByMaterial();
    ASSERT_EQ(counts.size(), 6u);
    EXPECT_EQ(counts[0], 0u);
    EXPECT_EQ(counts[1], 0u);
    EXPECT_EQ(counts[2], 1u);
    EXPECT_EQ(counts[3], 512u + 511u);
    EXPECT_EQ(counts[4], 128u * 128u * 128u);
    EXPECT_EQ(counts[5], 1u);
    uint64_t total = 0;
    for (uint64_t n : counts) total += n;
    EXPECT_EQ(total, w.stats().solidVoxels);

    // One material, no material grid: every solid voxel is it.
    auto mask = openvdb::BoolGrid::create(false);
    mask->tree().addTile(1, openvdb::Coord(0, 0, 0), true, true);
    const std::vector<uint64_t> uniform = worldFromGrid(*mask).voxelsByMaterial();
    ASSERT_EQ(uniform.size(), 2u);
    EXPECT_EQ(uniform[1], 512u);
}

}  // namespace
}  // namespace grotto::voxel
