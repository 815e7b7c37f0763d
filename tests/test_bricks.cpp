// Bricks and solid rules: popcounts of brick occupancy equal the solid voxel
// count, active tiles included, for every grid type the loader accepts.
#include "grotto/error.h"
#include "voxel/solid.h"

#include <gtest/gtest.h>
#include <openvdb/tools/LevelSetSphere.h>

#include <bit>
#include <random>

namespace grotto::voxel {
namespace {

uint64_t brickPopcount(const World& w) {
    uint64_t n = 0;
    for (const Brick& b : w.bricks())
        for (uint64_t word : b.occupancy) n += std::popcount(word);
    return n;
}

WorldDesc plainDesc() {
    WorldDesc d;
    d.materials = defaultMaterials();
    return d;
}

class Bricks : public ::testing::Test {
protected:
    static void SetUpTestSuite() { openvdb::initialize(); }
};

TEST_F(Bricks, PopcountEqualsActiveVoxelsWithTiles) {
    std::mt19937 rng(7);
    for (int trial = 0; trial < 5; ++trial) {
        auto grid = openvdb::BoolGrid::create(false);
        auto acc = grid->getAccessor();
        std::uniform_int_distribution<int> coord(-100, 100);
        for (int i = 0; i < 3000; ++i) acc.setValueOn(openvdb::Coord(coord(rng), coord(rng), coord(rng)), true);
        // Active tiles: a whole 128^3 block and some 8^3 blocks stay tiles, not leaves.
        grid->tree().addTile(2, openvdb::Coord(256, 0, 0), true, true);
        grid->tree().addTile(1, openvdb::Coord(-512, 64, 0), true, true);
        const uint64_t expected = grid->activeVoxelCount();
        ASSERT_GT(expected, 128u * 128 * 128);
        const World w = makeWorld(grid, plainDesc());
        EXPECT_EQ(w.stats().solidVoxels, expected);
        EXPECT_EQ(brickPopcount(w), expected) << "trial " << trial;
    }
}

TEST_F(Bricks, LevelSetInteriorIncludesInactiveInteriorTiles) {
    const float radius = 60.0f;
    auto sphere = openvdb::tools::createLevelSetSphere<openvdb::FloatGrid>(radius, openvdb::Vec3f(0), 1.0f, 3.0f);
    const World w = makeWorld(sphere, plainDesc());
    // The narrow band holds only a shell; solid must be the whole ball.
    const double ball = 4.0 / 3.0 * M_PI * radius * radius * radius;
    EXPECT_NEAR(double(w.stats().solidVoxels), ball, 0.02 * ball);
    EXPECT_TRUE(w.solid({0, 0, 0}));
    EXPECT_TRUE(w.solid({0, int(radius) - 2, 0}));
    EXPECT_FALSE(w.solid({0, int(radius) + 2, 0}));
    EXPECT_EQ(brickPopcount(w), w.stats().solidVoxels);
}

TEST_F(Bricks, FogVolumeThreshold) {
    auto fog = openvdb::FloatGrid::create(0.0f);
    fog->setGridClass(openvdb::GRID_FOG_VOLUME);
    auto acc = fog->getAccessor();
    acc.setValueOn(openvdb::Coord(0, 0, 0), 0.2f);
    acc.setValueOn(openvdb::Coord(1, 0, 0), 0.5f);
    acc.setValueOn(openvdb::Coord(2, 0, 0), 0.9f);
    fog->tree().addTile(2, openvdb::Coord(128, 0, 0), 1.0f, true);  // dense 128^3 tile
    fog->tree().addTile(2, openvdb::Coord(256, 0, 0), 0.1f, true);  // thin 128^3 tile
    const World w = makeWorld(fog, plainDesc());
    EXPECT_FALSE(w.solid({0, 0, 0}));
    EXPECT_TRUE(w.solid({1, 0, 0}));
    EXPECT_TRUE(w.solid({2, 0, 0}));
    EXPECT_TRUE(w.solid({130, 5, 5}));
    EXPECT_FALSE(w.solid({260, 5, 5}));
    EXPECT_EQ(w.stats().solidVoxels, 2u + 128u * 128 * 128);
    EXPECT_EQ(brickPopcount(w), w.stats().solidVoxels);
}

TEST_F(Bricks, Int32NonzeroIsSolidAndPaletteIsChecked) {
    auto ints = openvdb::Int32Grid::create(0);
    auto acc = ints->getAccessor();
    acc.setValueOn(openvdb::Coord(0, 0, 0), 0);
    acc.setValueOn(openvdb::Coord(1, 0, 0), 3);
    ints->tree().addTile(2, openvdb::Coord(128, 0, 0), 2, true);
    const World w = makeWorld(ints, plainDesc());
    EXPECT_FALSE(w.solid({0, 0, 0}));
    EXPECT_TRUE(w.solid({1, 0, 0}));
    EXPECT_EQ(w.stats().solidVoxels, 1u + 128u * 128 * 128);
    EXPECT_EQ(brickPopcount(w), w.stats().solidVoxels);

    acc.setValueOn(openvdb::Coord(5, 0, 0), 99);  // beyond the 8-entry default palette
    EXPECT_THROW(makeWorld(ints, plainDesc()), grotto::Error);
}

}  // namespace
}  // namespace grotto::voxel
