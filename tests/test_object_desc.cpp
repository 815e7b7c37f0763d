// Objects in world files: poses against analytic values (linear position, slerp,
// held outside the keys), strict parsing with errors naming file and field, and
// the command line's exit code 2 for a bad object.
#include "grotto/error.h"
#include "tests/test_util.h"
#include "voxel/object_pose.h"
#include "voxel/world_desc.h"

#include <gtest/gtest.h>

#include <fstream>
#include <numbers>

namespace grotto {
namespace {

namespace fs = std::filesystem;

voxel::ObjectDesc door() {
    voxel::ObjectDesc d;
    d.pivot = {0.0, -0.5, -0.5};
    const glm::dvec3 up(0, 1, 0);
    d.keys = {{1.0, {10, 0, 0}, glm::angleAxis(0.0, up)},
              {3.0, {14, 2, -4}, glm::angleAxis(glm::radians(90.0), up)},
              {4.0, {14, 2, -4}, glm::angleAxis(glm::radians(170.0), up)}};
    return d;
}

TEST(ObjectPose, InterpolatesKeysAndHoldsOutsideThem) {
    const voxel::ObjectDesc d = door();
    EXPECT_TRUE(d.moves());
    // Halfway between the first two keys: position halfway, a 45 degree turn.
    const voxel::ObjectPose mid = voxel::objectPose(d, 2.0);
    EXPECT_NEAR(glm::length(mid.position - glm::dvec3(12, 1, -2)), 0.0, 1e-12);
    const glm::dvec3 x = mid.rotation * glm::dvec3(1, 0, 0);
    EXPECT_NEAR(x.x, std::cos(std::numbers::pi / 4), 1e-12);
    EXPECT_NEAR(x.z, -std::sin(std::numbers::pi / 4), 1e-12);
    // A quarter of the way through the last segment: 90 + 20 degrees.
    const glm::dvec3 x2 = voxel::objectPose(d, 3.25).rotation * glm::dvec3(1, 0, 0);
    EXPECT_NEAR(std::atan2(-x2.z, x2.x), glm::radians(110.0), 1e-12);
    // Held before the first key and after the last.
    EXPECT_EQ(voxel::objectPose(d, 0.0).position, glm::dvec3(10, 0, 0));
    EXPECT_EQ(voxel::objectPose(d, 1e6).rotation, d.keys.back().rotation);
    // The pivot stays where the pose puts it, whatever the rotation.
    EXPECT_NEAR(glm::length(mid.toWorld(d.pivot) - mid.position), 0.0, 1e-12);
    const glm::dvec3 p(0.3, 5.0, 2.0);
    EXPECT_NEAR(glm::length(mid.toLocal(mid.toWorld(p)) - p), 0.0, 1e-12);
    const glm::dvec4 m = mid.worldFromLocal(glm::dvec3(1e6)) * glm::dvec4(p, 1.0);
    EXPECT_NEAR(glm::length(glm::dvec3(m) + glm::dvec3(1e6) - mid.toWorld(p)), 0.0, 1e-9);
    voxel::ObjectDesc still = d;
    still.keys.resize(1);
    EXPECT_FALSE(still.moves());
}

struct WorldFile {
    test::ScratchDir dir;
    fs::path path = dir / "w.json";
    explicit WorldFile(const std::string& objects) {
        std::ofstream(path) << R"({"grid": {"file": ")" << (test::worldsDir() / "rooms.vdb").string()
                            << R"("}, "objects": )" << objects << "}";
    }
};

std::string errorOf(const std::string& objects) {
    const WorldFile f(objects);
    try {
        voxel::loadWorldDesc(f.path);
    } catch (const Error& e) {
        EXPECT_EQ(e.exitCode(), 2);
        EXPECT_NE(std::string(e.what()).find(f.path.string()), std::string::npos) << e.what();
        return e.what();
    }
    return "";
}

TEST(ObjectDesc, ParsesGridsGeneratorsAndRotations) {
    const WorldFile f(R"([{"name": "door", "generator": {"kind": "box", "size": [1, 8, 4], "material": 3},
        "pivot": [0, -0.5, -0.5], "keys": [{"time": 0, "position": [1, 2, 3]},
        {"time": 2, "position": [1, 2, 3], "angle_degrees": 90, "axis": [0, 2, 0]}]},
        {"grid": {"file": "rooms.vdb", "rule": "int32"}, "keys": [{"time": 0, "position": [0, 0, 0],
        "quaternion": [0, 0, 0, 2]}, {"time": 1, "position": [0, 0, 0], "quaternion": [1e200, 0, 0, 1e200]},
        {"time": 2, "position": [0, 0, 0], "quaternion": [0, -1e-200, 0, 1e-200]}]}])");
    const voxel::WorldDesc w = voxel::loadWorldDesc(f.path);
    ASSERT_EQ(w.objects.size(), 2u);
    EXPECT_EQ(w.objects[0].name, "door");
    EXPECT_EQ(w.objects[0].boxSize, glm::ivec3(1, 8, 4));
    EXPECT_EQ(w.objects[0].material, 3);
    EXPECT_NEAR(glm::length(w.objects[0].keys[1].rotation * glm::dvec3(1, 0, 0) - glm::dvec3(0, 0, -1)), 0.0, 1e-12);
    EXPECT_EQ(w.objects[1].name, "object2");
    EXPECT_EQ(w.objects[1].gridFile, f.path.parent_path() / "rooms.vdb");
    EXPECT_EQ(w.objects[1].keys[0].rotation, glm::dquat(1, 0, 0, 0));  // normalised
    // Components whose squares overflow or underflow: normalised all the same
    // (90 degrees about x, then -90 about y), not taken for no rotation.
    const glm::dvec3 y = w.objects[1].keys[1].rotation * glm::dvec3(0, 1, 0);
    EXPECT_NEAR(glm::length(y - glm::dvec3(0, 0, 1)), 0.0, 1e-12);
    const glm::dvec3 x = w.objects[1].keys[2].rotation * glm::dvec3(1, 0, 0);
    EXPECT_NEAR(glm::length(x - glm::dvec3(0, 0, 1)), 0.0, 1e-12);
}

TEST(ObjectDesc, ErrorsNameFileAndField) {
    const std::string key = R"("keys": [{"time": 0, "position": [0, 0, 0]}])";
    const std::string box = R"("generator": {"kind": "box", "size": [2, 2, 2]}, )";
    const std::pair<std::string, std::string> cases[] = {
        {"{}", "field 'objects': expected an array"},
        {"[{" + key + "}]", "field 'objects[0].grid': missing"},
        {"[{" + box + R"("grid": {"file": "a.vdb"}, )" + key + "}]", "field 'objects[0].generator': given with 'grid'"},
        {"[{" + box.substr(0, box.size() - 2) + "}]", "field 'objects[0].keys': missing"},
        {"[{" + box + R"("keys": []}])", "field 'objects[0].keys': expected a non-empty array"},
        {"[{" + box + R"("keys": [{"time": 1, "position": [0, 0, 0]}, {"time": 1, "position": [0, 0, 0]}]}])",
         "field 'objects[0].keys[1].time': must exceed"},
        {"[{" + box + R"("keys": [{"time": 0}]}])", "field 'objects[0].keys[0].position': missing"},
        {"[{" + box + R"("keys": [{"time": 0, "position": [0, 0, 0], "quaternion": [0, 0, 0, 0]}]}])",
         "field 'objects[0].keys[0].quaternion': must not be zero"},
        // A misspelt key is news, not the key it was meant to be missing.
        {"[{" + box + R"("keys": [{"time": 0, "position": [0, 0, 0], "angle_degree": 9, "axis": [0, 1, 0]}]}])",
         "field 'objects[0].keys[0].angle_degree': unknown field, did you mean 'angle_degrees'?"},
        {"[{" + box + R"("keys": [{"time": 0, "postion": [0, 0, 0]}]}])",
         "field 'objects[0].keys[0].postion': unknown field, did you mean 'position'?"},
        {"[{" + box + key + R"(, "pivott": [0, 0, 0]}])", "field 'objects[0].pivott': unknown field, did you mean 'pivot'?"},
        // The object's own field, not the world's grid block.
        {R"([{"generator": {"kind": "box", "size": [2, 2, 2], "material": 9}, )" + key + "}]",
         "field 'objects[0].generator.material': id 9 has no entry in 'materials'"},
        {R"([{"grid": {"file": "rooms.vdb", "material": 12}, )" + key + "}]",
         "field 'objects[0].grid.material': id 12 has no entry in 'materials'"},
        {R"([{"generator": {"kind": "caves", "seed": 1.5}, )" + key + "}]",
         "field 'objects[0].generator.seed': value 1.5 is not a whole number"},
        {"[{" + box + R"("keys": [{"time": 0, "position": [0, 0, 0], "angle_degrees": 9}]}])",
         "field 'objects[0].keys[0].axis': missing"},
        {"[{" + box + key + R"(, "spin": 1}])", "field 'objects[0].spin': unknown field"},
        {R"([{"generator": {"kind": "cube"}, )" + key + "}]", "field 'objects[0].generator.kind': unknown generator 'cube'"},
        {R"([{"generator": {"kind": "box", "size": [0, 1, 1]}, )" + key + "}]",
         "field 'objects[0].generator.size': size[0] (x) = 0 is out of range"},
        {"[{\"name\": \"a\", " + box + key + "}, {\"name\": \"a\", " + box + key + "}]",
         "field 'objects[1].name': 'a' names an earlier object too"},
    };
    for (const auto& [objects, expected] : cases) {
        const std::string e = errorOf(objects);
        EXPECT_NE(e.find(expected), std::string::npos) << objects << "\n -> " << e;
    }
    std::string many = "[";
    for (int i = 0; i < 32; ++i) many += (i ? ", {" : "{") + box + key + "}";
    EXPECT_NE(errorOf(many + "]").find("at most 31 objects"), std::string::npos);
}

TEST(ObjectDesc, CommandLineRefusesABadObjectWithExitCode2) {
    const WorldFile bad(R"([{"generator": {"kind": "box", "size": [2, 2, 2]}, "keys": [{"time": 0, "position": [0, 0, "x"]}]}])");
    const test::RunResult r = test::runGrotto("render " + bad.path.string() + " --size 32x32 -o " + (bad.dir / "a.png").string());
    EXPECT_EQ(r.exitCode, 2) << r.err;
    EXPECT_NE(r.err.find("objects[0].keys[0].position"), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(bad.dir / "a.png"));
    const WorldFile empty(R"([{"generator": {"kind": "sphere", "size": 2}, "keys": [{"time": 0, "position": [0, 0, 0]}]}])");
    const test::RunResult g = test::runGrotto("render " + empty.path.string() + " --size 32x32 -o " + (empty.dir / "a.png").string());
    EXPECT_EQ(g.exitCode, 2) << g.err;
    EXPECT_NE(g.err.find("objects[0].generator"), std::string::npos) << g.err;
}

}  // namespace
}  // namespace grotto
