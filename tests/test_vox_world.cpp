// MagicaVoxel models as worlds: a .vox opened directly is a world whose solid
// voxels are where MagicaVoxel places them (z up turned into y up), whose
// materials are the palette's colours made linear, and which a world file can
// name as its grid; its .vdb conversion is the same world.
#include "grotto/error.h"
#include "tests/test_util.h"
#include "tests/vox_writer.h"
#include "voxel/world.h"

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>

namespace grotto::voxel {
namespace {

namespace fs = std::filesystem;

void writeBytes(const fs::path& file, const std::vector<uint8_t>& bytes) {
    std::ofstream(file, std::ios::binary).write(reinterpret_cast<const char*>(bytes.data()), std::streamsize(bytes.size()));
}

float linear(uint8_t byte) {
    const double c = byte / 255.0;
    return float(c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4));
}

// A 4 x 4 x 1 slab (colour 1) and, 10 units along MagicaVoxel's +x, a 1 x 1 x 3
// column standing up its z (colour 3), under one group.
std::vector<uint8_t> slabAndColumn() {
    std::array<VoxColor, 256> palette{};
    palette[0] = {200, 30, 30, 255};   // colour 1
    palette[2] = {20, 220, 90, 255};   // colour 3
    std::vector<std::array<uint8_t, 4>> slab;
    for (uint8_t x = 0; x < 4; ++x)
        for (uint8_t y = 0; y < 4; ++y) slab.push_back({x, y, 0, 1});
    return test::VoxWriter()
        .model({4, 4, 1}, slab)
        .model({1, 1, 3}, {{0, 0, 0, 3}, {0, 0, 1, 3}, {0, 0, 2, 3}})
        .palette(palette)
        .transform(0, 1)
        .group(1, {2, 4})
        .transform(2, 3, {0, 0, 0})
        .shape(3, 0)
        .transform(4, 5, {10, 0, 2})
        .shape(5, 1)
        .bytes();
}

TEST(VoxWorld, AModelOpensDirectlyWithItsUpAlongYAndItsPaletteAsMaterials) {
    const grotto::test::ScratchDir dir;
    writeBytes(dir / "scene.vox", slabAndColumn());
    const World world = World::load(dir / "scene.vox");
    EXPECT_EQ(world.stats().solidVoxels, 16u + 3u);
    EXPECT_EQ(world.voxelSize(), 1.0);
    // The column stands along Grotto's y: three voxels stacked in y, one in x and z.
    const IndexBox b = world.bounds();
    int columnVoxels = 0;
    glm::ivec3 lo(1 << 30), hi(-(1 << 30));
    for (int x = b.min.x; x <= b.max.x; ++x)
        for (int y = b.min.y; y <= b.max.y; ++y)
            for (int z = b.min.z; z <= b.max.z; ++z)
                if (world.material({x, y, z}) == 3) {
                    ++columnVoxels;
                    lo = glm::min(lo, glm::ivec3(x, y, z)), hi = glm::max(hi, glm::ivec3(x, y, z));
                }
    EXPECT_EQ(columnVoxels, 3);
    EXPECT_EQ(hi - lo, glm::ivec3(0, 2, 0));
    // The slab lies flat in x and z, one voxel thick in y, and the column stands on top of it
    // (its pivot is its middle voxel, so translation z 2 lifts it onto the slab), 10 along +x.
    EXPECT_EQ(b.max.x - b.min.x, 10 + 0 - (-2));  // slab from -2 (pivot 2) to 1, column at 10
    EXPECT_GT(lo.y, b.min.y);
    // Materials: colour k is material k, its albedo the colour made linear.
    ASSERT_EQ(world.desc().materials.size(), 3u);
    EXPECT_NEAR(world.desc().materials[0].albedo.r, linear(200), 1e-6);
    EXPECT_NEAR(world.desc().materials[2].albedo.g, linear(220), 1e-6);
    EXPECT_NEAR(world.desc().materials[2].albedo.b, linear(90), 1e-6);
}

TEST(VoxWorld, AWorldFileNamesAModelAndItsConversionIsTheSameWorld) {
    const grotto::test::ScratchDir dir;
    writeBytes(dir / "scene.vox", slabAndColumn());
    std::ofstream(dir / "world.json") << R"({"grid": {"file": "scene.vox"}, "lighting": {"sun": {"intensity": 2}}})";
    const World named = World::load(dir / "world.json");
    const World direct = World::load(dir / "scene.vox");
    EXPECT_EQ(named.stats().solidVoxels, direct.stats().solidVoxels);
    EXPECT_EQ(named.desc().materials.size(), 3u);  // the palette, as no materials are given
    const World::SavedFiles saved = direct.save(dir / "converted.vdb");
    const World converted = World::load(saved.world);
    EXPECT_EQ(converted.bounds().min, direct.bounds().min);
    EXPECT_EQ(converted.bounds().max, direct.bounds().max);
    for (int x = direct.bounds().min.x; x <= direct.bounds().max.x; ++x)
        for (int y = direct.bounds().min.y; y <= direct.bounds().max.y; ++y)
            for (int z = direct.bounds().min.z; z <= direct.bounds().max.z; ++z)
                ASSERT_EQ(converted.material({x, y, z}), direct.material({x, y, z}));
    ASSERT_EQ(converted.desc().materials.size(), 3u);
    EXPECT_EQ(converted.desc().materials[2].albedo, direct.desc().materials[2].albedo);
    // A solid rule other than the model's own is refused, naming the field.
    std::ofstream(dir / "fog.json") << R"({"grid": {"file": "scene.vox", "rule": "fog"}})";
    try {
        (void)World::load(dir / "fog.json");
        ADD_FAILURE() << "a fog rule on a .vox was accepted";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("grid.rule"), std::string::npos) << e.what();
    }
}

}  // namespace
}  // namespace grotto::voxel
