// The `mine` generator and the houses' lamps: the glowing things are where
// docs/worlds.md says, the shaft lets the sky and the default sun reach the
// floor, and the seed moves the rock but never the layout. Size 64, the
// smallest that holds the whole layout (the shipped mine is 80).
#include "grotto/error.h"
#include "grotto/settings.h"
#include "tests/test_util.h"
#include "voxel/generators.h"
#include "voxel/solid.h"

#include <gtest/gtest.h>

#include <cmath>

namespace grotto::voxel {
namespace {

enum : int { Rock = 1, Wood = 4, Torch = 5, Crystal = 6, Lava = 7, Lamp = 6 };

World generated(const std::string& kind, uint32_t seed, bool lamps = false) {
    GeneratorOptions o;
    o.size = 64;
    o.seed = seed;
    o.lamps = lamps;
    WorldDesc desc;
    desc.materials.resize(7);  // the shipped mine's palette size; colours do not matter here
    return makeWorld(generateWorld(kind, o), desc);
}

const World& mine() {
    static const World world = generated("mine", 1);
    return world;
}

TEST(MineWorld, TorchesStandOnPostsInTheOpen) {
    const glm::ivec2 torches[] = {{-22, 14}, {-14, 22}, {-22, 22}, {-20, 0}, {0, 20}};
    for (const glm::ivec2 t : torches) {
        SCOPED_TRACE(std::to_string(t.x) + " " + std::to_string(t.y));
        EXPECT_TRUE(mine().solid({t.x, 3, t.y})) << "floor";
        for (int y = 4; y <= 6; ++y) EXPECT_EQ(mine().material({t.x, y, t.y}), Wood) << "post at y " << y;
        EXPECT_EQ(mine().material({t.x, 7, t.y}), Torch);
        // Five faces in the air, so it lights its surroundings.
        for (const glm::ivec3 d : {glm::ivec3(1, 0, 0), {-1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {0, 0, -1}})
            EXPECT_FALSE(mine().solid(glm::ivec3(t.x, 7, t.y) + d)) << d.x << " " << d.y << " " << d.z;
    }
    EXPECT_EQ(mine().voxelsByMaterial()[Torch], 5u) << "no flame but the five";
}

TEST(MineWorld, LavaFillsABasinInTheLavaHall) {
    // An ellipse 6 x 5 around (18, -18) at y = 2, open above, seen from the hall.
    EXPECT_EQ(mine().material({18, 2, -18}), Lava);
    EXPECT_FALSE(mine().solid({18, 3, -18}));
    EXPECT_EQ(mine().material({23, 2, -18}), Lava);
    EXPECT_NE(mine().material({24, 2, -18}), Lava);
    EXPECT_NE(mine().material({18, 2, -13}), Lava);
    const uint64_t lava = mine().voxelsByMaterial()[Lava];
    EXPECT_GT(lava, 80u);
    EXPECT_LT(lava, 100u);  // pi x 6 x 5 = 94 voxel columns, one deep
    const auto hit = mine().raycast(glm::dvec3(18, 8, -18), glm::dvec3(0, -1, 0), 20.0);
    ASSERT_TRUE(hit.has_value());
    EXPECT_EQ(mine().material(hit->voxel), Lava);
}

TEST(MineWorld, CrystalsClusterInTheCrystalHall) {
    const uint64_t crystals = mine().voxelsByMaterial()[Crystal];
    EXPECT_GE(crystals, 21u);  // three clusters of seven spikes, 1 to 4 high
    EXPECT_LE(crystals, 84u);
    for (const glm::ivec2 c : {glm::ivec2(13, 14), {23, 16}, {17, 24}}) EXPECT_EQ(mine().material({c.x, 4, c.y}), Crystal);
}

TEST(MineWorld, TheShaftLetsTheSkyAndTheSunReachTheFloor) {
    const glm::dvec3 floor(-18, 4, -18);  // just above the floor's top face (y = 3.5)
    EXPECT_FALSE(mine().raycast(floor, glm::dvec3(0, 1, 0), 1000.0).has_value()) << "straight up";
    const glm::dvec3 sun(Lighting{}.sunDirection);
    EXPECT_FALSE(mine().raycast(floor, sun, 1000.0).has_value()) << "toward the default sun";
    // The floor under the shaft is there, and a hall beside it is roofed.
    const auto down = mine().raycast(floor, glm::dvec3(0, -1, 0), 10.0);
    ASSERT_TRUE(down.has_value());
    EXPECT_NEAR(down->distance, 0.5, 1e-9);
    EXPECT_TRUE(mine().raycast(glm::dvec3(18, 6, 18), glm::dvec3(0, 1, 0), 1000.0).has_value()) << "crystal hall roof";
}

TEST(MineWorld, TheSeedMovesTheRockNotTheLayout) {
    const World other = generated("mine", 2);
    EXPECT_NE(other.stats().solidVoxels, mine().stats().solidVoxels);
    const std::vector<uint64_t> a = mine().voxelsByMaterial(), b = other.voxelsByMaterial();
    EXPECT_EQ(a[Torch], b[Torch]);
    EXPECT_EQ(a[Lava], b[Lava]);
    EXPECT_EQ(a[Wood], b[Wood]);
}

TEST(HousesLamps, OneLampUnderEachCeilingOnlyWhenAsked) {
    const World lit = generated("houses", 1, true);
    EXPECT_EQ(lit.voxelsByMaterial()[Lamp], 3u * 4u);
    for (const int x0 : {-22, -6, 10}) {
        EXPECT_EQ(lit.material({x0 + 5, 7, -8 + 5}), Lamp);
        EXPECT_EQ(lit.material({x0 + 6, 7, -8 + 6}), Lamp);
        EXPECT_FALSE(lit.solid({x0 + 5, 6, -8 + 5})) << "hangs in the room";
    }
    const World day = generated("houses", 1);
    EXPECT_EQ(day.voxelsByMaterial().size() > Lamp ? day.voxelsByMaterial()[Lamp] : 0u, 0u);
    // Every other voxel is the same.
    EXPECT_EQ(lit.stats().solidVoxels, day.stats().solidVoxels + 12u);

    GeneratorOptions o;
    o.lamps = true;
    try {
        generateWorld("caves", o);
        ADD_FAILURE() << "caves accepted --lamps";
    } catch (const Error& e) {
        EXPECT_EQ(e.exitCode(), 2);
        EXPECT_NE(std::string(e.what()).find("--lamps"), std::string::npos) << e.what();
    }
}

// The shipped files: their grids are this generator's (regenerated with
// scripts/make-worlds.sh), and only the lamps, torches, crystals and lava glow.
TEST(ShippedGlowingWorlds, MineAndHousesAtNightGlowWhereTheLayoutSays) {
    const World shipped = World::load(grotto::test::worldsDir() / "mine.json");
    EXPECT_EQ(shipped.bounds().max.x - shipped.bounds().min.x, 79) << "80 wide";
    EXPECT_EQ(shipped.material({-20, 7, 0}), Torch);
    EXPECT_EQ(shipped.material({18, 2, -18}), Lava);
    const std::vector<Material>& mineMaterials = shipped.desc().materials;
    for (size_t id = 1; id <= mineMaterials.size(); ++id)
        EXPECT_EQ(mineMaterials[id - 1].emits(), int(id) == Torch || int(id) == Crystal || int(id) == Lava) << mineMaterials[id - 1].name;

    const World night = World::load(grotto::test::worldsDir() / "houses-night.json");
    EXPECT_EQ(night.voxelsByMaterial()[Lamp], 12u);
    EXPECT_TRUE(night.desc().materials[Lamp - 1].emits());
    EXPECT_EQ(night.desc().lighting.sunIntensity, 0.0f);
}

}  // namespace
}  // namespace grotto::voxel
