// What a new user met first: a subcommand word that is not one, a silent mesh
// export, a palette listed colour by colour, and a glTF placed half under the
// ground. Each through the command line.
#include "tests/cli_fixture.h"
#include "tests/vox_writer.h"

#include <tiny_gltf.h>

#include <glm/vec3.hpp>

#include <limits>
#include <regex>

namespace grotto::test {
namespace {

class CliFirstUse : public CliErrors {
protected:
    // A 6 x 6 floor of colour 1 and a 2 x 2 x 3 tower of colour 5: a palette of
    // five entries, three of them unused.
    fs::path writeTwoColourVox() {
        std::array<voxel::VoxColor, 256> palette{};
        for (auto& c : palette) c = {128, 128, 128, 255};
        palette[0] = {180, 180, 170, 255};
        palette[4] = {40, 90, 200, 255};
        std::vector<std::array<uint8_t, 4>> voxels;
        for (uint8_t x = 0; x < 6; ++x)
            for (uint8_t y = 0; y < 6; ++y) voxels.push_back({x, y, 0, 1});
        for (uint8_t x = 0; x < 2; ++x)
            for (uint8_t y = 0; y < 2; ++y)
                for (uint8_t z = 1; z < 4; ++z) voxels.push_back({x, y, z, 5});
        const std::vector<uint8_t> bytes = voxel::test::VoxWriter().model({6, 6, 4}, voxels).palette(palette).bytes();
        const fs::path file = dir_ / "two.vox";
        std::ofstream(file, std::ios::binary).write(reinterpret_cast<const char*>(bytes.data()), std::streamsize(bytes.size()));
        return file;
    }
};

// The word that is not a subcommand is named, with the subcommands accepted
// where it stands; a missing one is worded the same at every level.
TEST_F(CliFirstUse, UnknownAndMissingSubcommandsAreNamedAtEveryLevel) {
    const std::pair<std::string, std::string> cases[] = {
        {"path check x", "grotto: error: unknown subcommand 'check' of 'grotto path' (subcommands: import)\n"},
        {"path imprt a.glb", "grotto: error: unknown subcommand 'imprt' of 'grotto path' (did you mean 'import'? subcommands: import)\n"},
        {"path", "grotto: error: 'grotto path' requires a subcommand (subcommands: import)\n"},
    };
    for (const auto& [args, expected] : cases) {
        const RunResult r = runGrotto(args);
        EXPECT_EQ(r.exitCode, 2) << args;
        EXPECT_EQ(r.err, expected) << args;
    }
    const RunResult bare = runGrotto("");
    EXPECT_EQ(bare.exitCode, 2);
    EXPECT_EQ(bare.err.rfind("grotto: error: 'grotto' requires a subcommand (subcommands: render, info, ", 0), 0u) << bare.err;
    EXPECT_EQ(std::count(bare.err.begin(), bare.err.end(), '\n'), 1) << bare.err;
}

// info lists the materials the model draws, with their voxels, and only counts the rest of the palette.
TEST_F(CliFirstUse, InfoListsTheMaterialsUsedAndCountsTheRest) {
    const RunResult r = runGrotto("info " + writeTwoColourVox().string());
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_NE(r.out.find("material 1     colour 1: albedo (0.456411 0.456411 0.401978), 36 voxels\n"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("material 5     colour 5: albedo (0.021219 0.102242 0.57758), 12 voxels\n"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("materials      2 used; the palette holds 3 more that no voxel uses (not listed)\n"), std::string::npos) << r.out;
    const std::regex listed(R"(\nmaterial \d)");
    EXPECT_EQ(std::distance(std::sregex_iterator(r.out.begin(), r.out.end(), listed), std::sregex_iterator()), 2) << r.out;
}

// export-mesh shows its bake's progress with an ETA, as bake does, and counts in the singular where it is one.
TEST_F(CliFirstUse, ExportMeshShowsProgressAndCountsInTheSingular) {
    const RunResult r = runGrotto("export-mesh " + good_.string() + " --rays 1 --texels 1 -o " + (dir_ / "floor.glb").string());
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_NE(r.err.find("1/100 5 of 576 faces (ETA "), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("100/100 576 of 576 faces (ETA 0:00)"), std::string::npos) << r.err;
    EXPECT_NE(r.out.find(" triangles, 1 material, "), std::string::npos) << r.out;
}

// The exported glTF's bounds in its scene: the node's translation plus its positions' extent.
std::pair<glm::dvec3, glm::dvec3> gltfBounds(const fs::path& file) {
    tinygltf::Model m;
    tinygltf::TinyGLTF loader;
    std::string err, warn;
    EXPECT_TRUE(loader.LoadBinaryFromFile(&m, &err, &warn, file.string())) << err;
    glm::dvec3 lo(std::numeric_limits<double>::max()), hi(-std::numeric_limits<double>::max());
    if (m.nodes.size() != 1 || m.meshes.size() != 1) return {lo, hi};
    glm::dvec3 t(0.0);
    if (m.nodes[0].translation.size() == 3) t = {m.nodes[0].translation[0], m.nodes[0].translation[1], m.nodes[0].translation[2]};
    for (const tinygltf::Primitive& p : m.meshes[0].primitives) {
        const tinygltf::Accessor& a = m.accessors[size_t(p.attributes.at("POSITION"))];
        for (int i = 0; i < 3; ++i) lo[i] = std::min(lo[i], t[i] + a.minValues[size_t(i)]), hi[i] = std::max(hi[i], t[i] + a.maxValues[size_t(i)]);
    }
    return {lo, hi};
}

// --origin: base (the default) stands the mesh on y = 0 centred in x and z, centre
// puts its centre at the origin, world keeps the world's coordinates.
TEST_F(CliFirstUse, ExportMeshPlacesTheMeshAsOriginSays) {
    // A 16 x 1 x 16 floor of half-unit voxels moved to (100, -40, 7): the world's
    // coordinates are none of the others.
    const fs::path world = dir_ / "far.vdb";
    auto grid = openvdb::BoolGrid::create(false);
    grid->setName("solid");
    for (int x = 0; x < 16; ++x)
        for (int z = 0; z < 16; ++z) grid->tree().setValueOn(openvdb::Coord(x, 0, z), true);
    openvdb::math::Transform::Ptr placement = openvdb::math::Transform::createLinearTransform(0.5);
    placement->postTranslate(openvdb::Vec3d(100, -40, 7));
    grid->setTransform(placement);
    writeGrids(world, {grid});
    const std::pair<std::string, std::pair<glm::dvec3, glm::dvec3>> cases[] = {
        {"", {{-4, 0, -4}, {4, 0.5, 4}}},
        {"--origin base", {{-4, 0, -4}, {4, 0.5, 4}}},
        {"--origin centre", {{-4, -0.25, -4}, {4, 0.25, 4}}},
        {"--origin center", {{-4, -0.25, -4}, {4, 0.25, 4}}},
        {"--origin world", {{99.75, -40.25, 6.75}, {107.75, -39.75, 14.75}}},  // voxel (0, 0, 0) centred on the translation
    };
    for (const auto& [flag, expected] : cases) {
        const fs::path glb = dir_ / "floor.glb";
        const RunResult r = runGrotto("export-mesh " + world.string() + " --rays 1 --texels 1 " + flag + " -o " + glb.string());
        ASSERT_EQ(r.exitCode, 0) << flag << ": " << r.err;
        const auto [lo, hi] = gltfBounds(glb);
        for (int i = 0; i < 3; ++i) {
            EXPECT_NEAR(lo[i], expected.first[i], 1e-6) << flag << " axis " << i;
            EXPECT_NEAR(hi[i], expected.second[i], 1e-6) << flag << " axis " << i;
        }
    }
    expectRefused("export-mesh " + world.string() + " --origin floor -o " + (dir_ / "x.glb").string(), "--origin", dir_ / "x.glb");
}

}  // namespace
}  // namespace grotto::test
