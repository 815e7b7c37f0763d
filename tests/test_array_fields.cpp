// Array-valued fields of world files (colours, directions, positions, voxel
// indices, sizes, quaternions): a bad component is named by its index and
// name, with its value, so "[0.5, 0.5, 7]" is not reported as "component 7".
#include "grotto/error.h"
#include "tests/test_util.h"
#include "voxel/world_desc.h"

#include <gtest/gtest.h>

#include <fstream>

namespace grotto {
namespace {

// The error loading a world whose top level holds `fields` besides its grid.
std::string worldError(const std::string& fields) {
    const test::ScratchDir dir;
    const std::filesystem::path file = dir / "w.json";
    std::ofstream(file) << R"({"grid": {"file": ")" << (test::worldsDir() / "rooms.vdb").string() << R"("}, )" << fields << "}";
    try {
        voxel::loadWorldDesc(file);
    } catch (const Error& e) {
        EXPECT_EQ(e.exitCode(), 2) << e.what();
        return e.what();
    }
    return "(accepted)";
}

TEST(ArrayFields, NameTheComponentByIndexAndNameWithItsValue) {
    const std::string box = R"("objects": [{"generator": {"kind": "box", "size": )";
    const std::pair<std::string, std::string> cases[] = {
        {R"("materials": [{"albedo": [0.5, 0.5, 7]}])",
         "field 'materials[0].albedo': albedo[2] (blue) = 7 is out of range (accepted: an array of 3 numbers, each 0 to 1)"},
        {R"("materials": [{"albedo": [0.5, "red", 0.5]}])", "field 'materials[0].albedo': albedo[1] (green) is not a finite number"},
        {R"("lighting": {"sun": {"color": [-1, 1, 1]}})", "field 'lighting.sun.color': color[0] (red) = -1 is out of range"},
        {R"("lighting": {"sky": {"horizon": [1, 1, 1e9]}})", "field 'lighting.sky.horizon': horizon[2] (blue) = 1000000000.0 is out of range"},
        {R"("lighting": {"sun": {"direction": [0, null, 1]}})", "field 'lighting.sun.direction': direction[1] (y) is not a finite number"},
        {R"("cameras": {"a": {"position": [0, 0, 1e13]}})", "field 'cameras.a.position': position[2] (z) = 10000000000000.0 is out of range"},
        {box + R"([2, 0, 2]}, "keys": [{"time": 0, "position": [0, 0, 0]}]}])",
         "field 'objects[0].generator.size': size[1] (y) = 0 is out of range (accepted: an array of 3 numbers, each 1 to 4096)"},
        {box + R"([2, 2, 2]}, "keys": [{"time": 0, "position": [0, 0, 0], "quaternion": [0, 0, "a", 1]}]}])",
         "field 'objects[0].keys[0].quaternion': quaternion[2] (z) is not a finite number"},
        {R"("paths": {"p": {"keys": [{"time": 0, "position": [0, 0, 0]}, {"time": 1, "position": [0, 0, 1]}],
            "edits": [{"time": 0, "op": "carve", "voxel": [0, 2000000000, 0]}]}})",
         "field 'paths.p.edits[0].voxel': voxel[1] (j) = 2000000000 is out of range"},
        {R"("paths": {"p": {"keys": [{"time": 0, "position": [0, 0, 0]}, {"time": 1, "position": [0, 0, 1]}],
            "edits": [{"time": 0, "op": "carve", "voxel": [0, 0, 0.5]}]}})",
         "field 'paths.p.edits[0].voxel': voxel[2] (k) is not a whole number"},
    };
    for (const auto& [fields, expected] : cases) {
        const std::string e = worldError(fields);
        EXPECT_NE(e.find(expected), std::string::npos) << fields << "\n -> " << e;
    }
}

}  // namespace
}  // namespace grotto
