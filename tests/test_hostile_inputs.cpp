// Damaged and hostile input files: each is refused with exit code 2 and one line,
// nothing written, within 2 s of CPU time (RLIMIT_CPU on the grotto process: a
// run that needs more is killed and fails) and 512 MiB of memory beyond what
// grotto needs for a good world (its peak resident set, measured; RLIMIT_AS at
// 2 GiB only keeps a failing run from taking the machine).
#include "tests/hostile_fixture.h"
#include "tests/gltf_camera_writer.h"
#include "tests/vox_writer.h"

#include <gtest/gtest.h>
#include "voxel/openvdb_grids.h"

#include <sys/stat.h>

#include <climits>
#include <cmath>
#include <fstream>
#include <functional>
#include <random>

namespace grotto {
namespace {

namespace fs = std::filesystem;
using test::HostileInputs;
using test::kCaps;
using test::runGrotto;

TEST_F(HostileInputs, TruncationsAtManyOffsets) {
    const std::string real = bytesOf(test::worldsDir() / "rooms.vdb");
    for (size_t cut : {size_t(0), size_t(1), size_t(7), size_t(8), size_t(16), size_t(40), size_t(64), size_t(100),
                       size_t(150), size_t(200), size_t(300), size_t(500), size_t(1000), size_t(3000), size_t(10000),
                       size_t(30000), size_t(60000), size_t(90000), size_t(120000), real.size() - 100})
        expectRefusedWithinCaps(writeBytes("cut" + std::to_string(cut) + ".vdb", real.substr(0, cut)), "cut");
}

TEST_F(HostileInputs, RandomBytesAfterARealHeader) {
    // A megabyte of noise after a real file's first bytes: OpenVDB reads sizes
    // from the noise and tries to allocate them.
    const std::string real = bytesOf(test::worldsDir() / "rooms.vdb");
    std::mt19937 rng(7);
    for (size_t header : {8, 16, 32, 60, 100, 200, 400, 1000}) {
        std::string bytes = real.substr(0, header);
        bytes.resize(header + (1 << 20));
        for (size_t i = header; i < bytes.size(); ++i) bytes[i] = char(rng());
        expectRefusedWithinCaps(writeBytes("noise" + std::to_string(header) + ".vdb", bytes), "noise");
    }
}

// A baked face cache (grotto bake) cut at many offsets is refused; one with a
// byte changed anywhere is refused or, where the change leaves every count and
// size consistent, accepted: never a crash, never more than the caps.
TEST_F(HostileInputs, DamagedFaceCaches) {
    const fs::path good = dir_ / "good.gfc";
    ASSERT_EQ(runGrotto("bake " + good_.string() + " -o " + good.string() + " --rays 4 --sun-rays 1").exitCode, 0);
    const std::string real = bytesOf(good);
    const fs::path out = dir_ / "joined.gfc";
    for (size_t cut : {size_t(0), size_t(1), size_t(8), size_t(40), size_t(87), size_t(88), size_t(100), real.size() - 1})
        expectCommandRefusedWithinCaps("bake --merge " + writeBytes("cut" + std::to_string(cut) + ".gfc", real.substr(0, cut)).string() +
                                           " -o " + out.string(),
                                       "cut", out);
    std::mt19937 rng(3);
    expectBitFlipsReadOrRefused(real, ".gfc", "bake --merge", " -o " + out.string(), out, 14, [&](int n) {
        return n < 7 ? size_t(n) * 13 : 88 + rng() % (real.size() - 88);  // header, then texels
    }, rng);
}

// A glTF camera file cut at many offsets is refused; one with a bit flipped
// anywhere is refused or, where the file stays consistent, read: never a crash,
// never more than the caps, never a half-written path file.
TEST_F(HostileInputs, DamagedGltfCameras) {
    test::GltfCameraScene s;
    s.samplers = {{"translation", "CUBICSPLINE", {0, 1}, {0, 0, 0, 0, 0, 0, 8, 0, 0, -4, 6, 0, 5, 2, 1, 0, 0, 0}},
                  {"rotation", "STEP", {0, 2}, {0, 0, 0, 1, 0, 0.38f, 0, 0.92f}}};
    ASSERT_TRUE(test::writeGltfCamera(s, dir_ / "good.glb"));
    const std::string real = bytesOf(dir_ / "good.glb");
    const fs::path out = dir_ / "shot.json";
    // A sample through the command line (exit code, one line, caps); GltfCamera's
    // tests try every cut and byte in-process.
    for (size_t cut : {size_t(0), size_t(12), size_t(100), real.size() / 2, real.size() - 1})
        expectCommandRefusedWithinCaps("path import " + writeBytes("cut" + std::to_string(cut) + ".glb", real.substr(0, cut)).string() +
                                           " -o " + out.string(), "cut", out);
    std::mt19937 rng(5);
    expectBitFlipsReadOrRefused(real, ".glb", "path import", " -o " + out.string(), out, 8,
                                [&](int) { return rng() % real.size(); }, rng);
}

// A MagicaVoxel scene cut at many offsets is refused naming the file; one with a
// bit flipped anywhere is refused or, where it stays consistent, read; an
// instancing bomb (a small file placing more than 2^24 voxels) is refused. All
// within the caps, through `info`, which reads, builds and meshes the world.
TEST_F(HostileInputs, DamagedAndHostileVoxFiles) {
    using voxel::test::VoxWriter;
    std::vector<std::array<uint8_t, 4>> block;
    for (uint8_t x = 0; x < 6; ++x)
        for (uint8_t y = 0; y < 6; ++y)
            for (uint8_t z = 0; z < 3; ++z) block.push_back({x, y, z, uint8_t(1 + (x + y) % 3)});
    const std::vector<uint8_t> good = VoxWriter()
        .model({6, 6, 3}, block).model({1, 1, 2}, {{0, 0, 0, 4}, {0, 0, 1, 4}})
        .transform(0, 1).group(1, {2, 4}).transform(2, 3, {0, 0, 0}, 0x11).shape(3, 0)
        .transform(4, 5, {0, 0, 4}).shape(5, 1).material(4, {{"_type", "_emit"}, {"_emit", "2"}})
        .bytes();
    const std::string real(good.begin(), good.end());
    ASSERT_EQ(runGrotto("info " + writeBytes("good.vox", real).string(), "", kCaps).exitCode, 0);
    // A sample through the command line (exit code, one line, caps); VoxReadHostile's
    // tests try every cut and every bit in-process.
    for (size_t cut : {size_t(0), size_t(8), size_t(40), real.size() / 2, real.size() - 1})
        expectRefusedWithinCaps(writeBytes("cut" + std::to_string(cut) + ".vox", real.substr(0, cut)), "cut");
    std::mt19937 rng(9);
    expectBitFlipsReadOrRefused(real, ".vox", "info", "", {}, 8, [&](int) { return rng() % real.size(); }, rng);
    // 4096 instances of a 4096-voxel model: 16 KiB of nodes placing 2^24 + 4096 voxels.
    std::vector<std::array<uint8_t, 4>> slab;
    for (uint8_t x = 0; x < 64; ++x)
        for (uint8_t y = 0; y < 64; ++y) slab.push_back({x, y, 0, 1});
    VoxWriter bomb;
    bomb.model({64, 64, 1}, slab);
    std::vector<int32_t> children;
    for (int32_t i = 0; i < 4097; ++i) children.push_back(2 + 2 * i);
    bomb.transform(0, 1).group(1, children);
    for (int32_t i = 0; i < 4097; ++i) bomb.transform(2 + 2 * i, 3 + 2 * i, {0, 0, i}).shape(3 + 2 * i, 0);
    const std::vector<uint8_t> b = bomb.bytes();
    expectRefusedWithinCaps(writeBytes("bomb.vox", std::string(b.begin(), b.end())), "bomb.vox");
}

TEST_F(HostileInputs, ExtremeTransforms) {
    using openvdb::math::Transform;
    expectRefusedWithinCaps(oneVoxelGrid("tiny.vdb", openvdb::Coord(0), Transform::createLinearTransform(5e-5)),
                            "voxel size 5e-05, outside the supported range");
    expectRefusedWithinCaps(oneVoxelGrid("huge.vdb", openvdb::Coord(0), Transform::createLinearTransform(1e9)),
                            "voxel size 1e+09, outside the supported range");
    auto far = Transform::createLinearTransform(1.0);
    far->postTranslate(openvdb::Vec3d(0, 1e15, 0));
    expectRefusedWithinCaps(oneVoxelGrid("far.vdb", openvdb::Coord(0), far), "on y, outside the supported range");
    auto rotated = Transform::createLinearTransform(1.0);
    rotated->postRotate(0.3, openvdb::math::Y_AXIS);
    expectRefusedWithinCaps(oneVoxelGrid("rotated.vdb", openvdb::Coord(0), rotated), "not an axis-aligned");
    auto mirrored = Transform::createLinearTransform(openvdb::Mat4R(-1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1));
    expectRefusedWithinCaps(oneVoxelGrid("mirrored.vdb", openvdb::Coord(0), mirrored), "not an axis-aligned");
}

TEST_F(HostileInputs, IndicesOutsideTheSupportedRange) {
    const int top = INT_MAX, bottom = INT_MIN, edge = 1 << 30;
    expectRefusedWithinCaps(oneVoxelGrid("top.vdb", openvdb::Coord(0, top, 0)), "outside the supported index range");
    expectRefusedWithinCaps(oneVoxelGrid("bottom.vdb", openvdb::Coord(bottom, 0, 0)), "outside the supported index range");
    expectRefusedWithinCaps(oneVoxelGrid("edge.vdb", openvdb::Coord(0, 0, edge)), "index 1073741824 on z");
    expectRefusedWithinCaps(oneVoxelGrid("below.vdb", openvdb::Coord(0, -edge - 1, 0)), "index -1073741825 on y");
    // One active 8^3 tile ending at the top of the int32 range: a 10 KB file
    // whose brick and meshing loops once overflowed and never ended.
    auto tile = openvdb::BoolGrid::create(false);
    tile->setName("solid");
    tile->tree().addTile(1, openvdb::Coord(top - 7), true, true);
    writeGrids(dir_ / "tile.vdb", {tile});
    expectRefusedWithinCaps(dir_ / "tile.vdb", "outside the supported index range");
    // The range's own ends are inside it.
    for (auto [name, at] : {std::pair{"low.vdb", openvdb::Coord(-edge)}, std::pair{"high.vdb", openvdb::Coord(edge - 1)}}) {
        const test::RunResult r = runGrotto("info " + oneVoxelGrid(name, at).string(), "", kCaps);
        EXPECT_EQ(r.exitCode, 0) << name << ": " << r.err;
        EXPECT_NE(r.out.find("quads          6"), std::string::npos) << r.out;
    }
}

TEST_F(HostileInputs, EmptyGridsAndNothingSolid) {
    auto empty = openvdb::BoolGrid::create(false);
    empty->setName("solid");
    writeGrids(dir_ / "empty.vdb", {empty});
    expectRefusedWithinCaps(dir_ / "empty.vdb", "has no solid voxels");
    auto thin = openvdb::FloatGrid::create(0.0f);
    thin->setName("density");
    thin->setGridClass(openvdb::GRID_FOG_VOLUME);
    thin->tree().setValueOn(openvdb::Coord(0), 0.1f);  // below the default threshold of 0.5
    writeGrids(dir_ / "thin.vdb", {thin});
    expectRefusedWithinCaps(dir_ / "thin.vdb", "has no solid voxels");
}

TEST_F(HostileInputs, VectorGrids) {
    auto vec = openvdb::Vec3SGrid::create();
    vec->setName("velocity");
    vec->tree().setValueOn(openvdb::Coord(0), openvdb::Vec3s(1));
    writeGrids(dir_ / "vec.vdb", {vec});
    expectRefusedWithinCaps(dir_ / "vec.vdb", "unsupported grid type 'vec3s'");
}

TEST_F(HostileInputs, NanValues) {
    auto fog = openvdb::FloatGrid::create(0.0f);
    fog->setName("density");
    fog->setGridClass(openvdb::GRID_FOG_VOLUME);
    fog->tree().setValueOn(openvdb::Coord(0), 1.0f);
    fog->tree().setValueOn(openvdb::Coord(3, 4, 5), std::nanf(""));
    writeGrids(dir_ / "nan.vdb", {fog});
    expectRefusedWithinCaps(dir_ / "nan.vdb", "NaN or infinite value at index (3, 4, 5)");
    auto ls = openvdb::DoubleGrid::create(std::numeric_limits<double>::infinity());
    ls->setName("surface");
    ls->setGridClass(openvdb::GRID_LEVEL_SET);
    ls->tree().setValueOn(openvdb::Coord(0), -1.0);
    writeGrids(dir_ / "inf.vdb", {ls});
    expectRefusedWithinCaps(dir_ / "inf.vdb", "NaN or infinite value as its background");
}

TEST_F(HostileInputs, InputsThatAreNotRegularFiles) {
    ASSERT_EQ(mkfifo((dir_ / "pipe.vdb").c_str(), 0644), 0);
    expectRefusedWithinCaps(dir_ / "pipe.vdb", "is a FIFO, not a regular file");  // once, it waited forever
    ASSERT_EQ(mkfifo((dir_ / "pipe.json").c_str(), 0644), 0);
    expectRefusedWithinCaps(dir_ / "pipe.json", "is a FIFO, not a regular file");
    fs::create_directory(dir_ / "folder.vdb");
    expectRefusedWithinCaps(dir_ / "folder.vdb", "is a directory, not a regular file");
    expectRefusedWithinCaps("/dev/zero", "is a character device, not a regular file");
    const fs::path world = writeText("w.json", R"({"grid": {"file": "/dev/zero"}})");
    expectRefusedWithinCaps(world, "is a character device");
}

TEST_F(HostileInputs, OutputsOnlyReplaceRegularFiles) {
    // A link to a device: renaming onto the path would replace the link, but it
    // names a device, and the device is what the user pointed at.
    fs::create_symlink("/dev/null", dir_ / "device.png");
    const std::string render = "render " + good_.string() + " --size 8x8 -o ";
    expectRefused(render + (dir_ / "device.png").string(), "is a character device, not a regular file",
                  dir_ / "no-output");
    EXPECT_TRUE(fs::is_symlink(dir_ / "device.png"));
    ASSERT_EQ(mkfifo((dir_ / "pipe.json").c_str(), 0644), 0);
    expectRefused("bench " + good_.string() + " --size 8x8 --frames 1 --json " + (dir_ / "pipe.json").string(),
                  "is a FIFO, not a regular file", dir_ / "no-output");
    EXPECT_EQ(fs::status(dir_ / "pipe.json").type(), fs::file_type::fifo);
    fs::create_directory(dir_ / "folder.png");
    expectRefused(render + (dir_ / "folder.png").string(), "is a directory", dir_ / "no-output");
}

// Ten megabytes of '[' (a parser makes a node of each: gigabytes) as each kind of
// JSON file grotto reads, and a file larger than any JSON input should be.
TEST_F(HostileInputs, JsonBombs) {
    const std::string bomb = writeBytes("bomb.json", std::string(10 << 20, '[')).string();
    const std::string world = writeFlyWorld().string(), frames = (dir_ / "frames").string();
    expectCommandRefusedWithinCaps("info " + bomb, "bomb.json: nests arrays and objects more than 64 deep");
    expectCommandRefusedWithinCaps("flythrough " + world + " --path " + bomb + " --size 32x16 -o " + frames, "bomb.json: nests",
                                   frames);
    expectCommandRefusedWithinCaps("view " + good_.string() + " --size 32x16 --script " + bomb, "bomb.json: nests");
    expectCommandRefusedWithinCaps("stability " + world + " --path p --size 32x16 --baseline " + bomb + " --json " +
                                       (dir_ / "s.json").string(),
                                   "bomb.json: nests", dir_ / "s.json");
    // The files a flythrough keeps in its directory: its manifest, and the stats
    // of a run made there first.
    const fs::path kept = dir_ / "kept";
    fs::create_directory(kept);
    fs::copy_file(bomb, kept / "flythrough.json");
    expectCommandRefusedWithinCaps("flythrough " + world + " --path p --size 32x16 -o " + kept.string(), "flythrough.json: nests",
                                   kept / "frame.0001.png");
    const test::RunResult first = runGrotto("flythrough " + world + " --path p --size 32x16 --frames 2 -o " + frames);
    ASSERT_EQ(first.exitCode, 0) << first.err;
    fs::copy_file(bomb, fs::path(frames) / "stats.json", fs::copy_options::overwrite_existing);
    expectCommandRefusedWithinCaps("flythrough " + world + " --path p --size 32x16 -o " + frames, "stats.json: nests",
                                   fs::path(frames) / "frame.0003.png");
    // Brackets in strings are text, not nesting: a deep-looking name is only a name.
    const std::string brackets = std::string(100, '[');
    expectCommandRefusedWithinCaps("info " + writeText("quoted.json", R"({"grid": {"file": ")" + brackets + R"("}})").string(),
                                   brackets + ": no such file");
    const std::string wide = R"({"grid": {"file": "good.vdb"}, "x": ")" + std::string(17 << 20, 'a') + R"("})";
    expectCommandRefusedWithinCaps("info " + writeBytes("wide.json", wide).string(), "wide.json: is larger than 16 MiB");
}

// Objects that glow on more faces in all than the object light pass samples are
// refused, naming the file and field, before anything is rendered or written.
TEST_F(HostileInputs, ObjectsGlowingOnTooManyFaces) {
    const std::string world = writeText("glow.json", R"({"grid": {"file": "good.vdb"},
        "materials": [{"albedo": [0.5, 0.5, 0.5]}, {"albedo": [0, 0, 0], "emission": {"intensity": 2}}],
        "lighting": {"ambient": {"from": "full"}}, "ao": {"method": "cache"},
        "objects": [{"generator": {"kind": "box", "size": [8, 8, 8], "material": 2}, "keys": [{"time": 0, "position": [0, 0, 0]}]}]})")
                                  .string();
    expectCommandRefusedWithinCaps(render(world), "glow.json: field 'objects': the objects glow on 384 faces in all", out());
}

// Objects and edits whose memory passes the budget are refused from their sizes,
// before any voxel is made (and before anything is written), not after minutes.
TEST_F(HostileInputs, ObjectsAndEditsPastTheMemoryBudget) {
    auto world = [&](const std::string& name, const std::string& extra) {
        return writeText(name, R"({"grid": {"file": "good.vdb"}, )" + extra + "}").string();
    };
    const std::string key = R"("keys": [{"time": 0, "position": [0, 0, 0]}])";
    // At the documented limit of a box, and a box past a small budget.
    const std::string box4096 = world("box4096.json", R"("objects": [{"generator": {"kind": "box", "size": [4096, 4096, 4096]}, )" + key + "}]");
    expectCommandRefusedWithinCaps(render(box4096), "box4096.json: field 'objects[0].generator.size': object 'object1' could make", out());
    const std::string box1024 = world("box1024.json", R"("memory_budget_mib": 64, "objects": [{"generator": {"kind": "box", "size": [1024, 1024, 1024]}, )" + key + "}]");
    expectCommandRefusedWithinCaps(render(box1024), "more than the memory budget of 64.0 MiB", out());
    const std::string caves = world("caves.json", R"("memory_budget_mib": 1024, "objects": [{"generator": {"kind": "caves", "size": 4096}, )" + key + "}]");
    expectCommandRefusedWithinCaps(render(caves), "caves.json: field 'objects[0].generator.size'", out());
    // A path's edit: refused when the path is read, before the output directory is made.
    const std::string frames = (dir_ / "frames").string();
    const std::string fill = world("fill.json", R"("memory_budget_mib": 64, "paths": {"p": {"keys": [
        {"time": 0, "position": [8, 10, 30], "target": [8, 0, 8]}, {"time": 1, "position": [26, 6, 12], "target": [8, 0, 6]}],
        "edits": [{"time": 0.9, "op": "fill", "voxels": {"min": [0, 0, 0], "max": [1023, 1023, 1023]}, "material": 2}]}})");
    expectCommandRefusedWithinCaps("flythrough " + fill + " --path p --size 32x16 --fps 4 -o " + frames,
                                   "fill.json: field 'paths.p.edits[0]': could make the world", frames);
    const fs::path far = writeText("far.json", R"({"keys": [
        {"time": 0, "position": [8, 10, 30], "target": [8, 0, 8]}, {"time": 1, "position": [26, 6, 12], "target": [8, 0, 6]}],
        "edits": [{"time": 0.9, "op": "carve", "sphere": {"centre": [0, 3e9, 0], "radius": 2}}]})");
    expectCommandRefusedWithinCaps("flythrough " + good_.string() + " --path " + far.string() + " --size 32x16 --fps 4 -o " + frames,
                                   "far.json: field 'edits[0]': reaches outside the supported index range on y", frames);
}

// What a flythrough reads in its output directory: a FIFO there once blocked the
// run forever, and a directory named stats.json ended it as an internal failure.
TEST_F(HostileInputs, FlythroughDirectoryFilesThatAreNotRegularFiles) {
    const std::string run = "flythrough " + writeFlyWorld().string() + " --path p --size 16x8 --fps 8 --frames 2 -o ";
    for (const char* name : {"flythrough.json", "stats.json"}) {
        const fs::path seq = dir_ / (std::string("fifo-") + name);
        fs::create_directory(seq);
        ASSERT_EQ(mkfifo((seq / name).c_str(), 0644), 0);
        expectRefused(run + seq.string(), name + std::string(": is a FIFO, not a regular file"), seq / "frame.0001.png",
                      "", {.hangSeconds = 60});
    }
    const fs::path seq = dir_ / "folder";
    fs::create_directories(seq / "stats.json");
    expectRefused(run + seq.string(), "stats.json: is a directory, not a regular file", seq / "frame.0001.png");
}

TEST_F(HostileInputs, TextFromFilesIsPrintedEscaped) {
    auto grid = openvdb::BoolGrid::create(false);
    grid->setName("evil\n\x1b[2J\x07name");
    grid->tree().setValueOn(openvdb::Coord(0), true);
    writeGrids(dir_ / "evil.vdb", {grid});
    const fs::path world = writeText("w.json", R"({"grid": {"file": "evil.vdb", "name": "plain"}})");
    expectRefused("info " + world.string(), "grids in the file: evil\\n\\x1B[2J\\x07name", dir_ / "no-output");
    const test::RunResult r = runGrotto("info " + world.string());
    EXPECT_EQ(r.err.find('\x1b'), std::string::npos);
}

}  // namespace
}  // namespace grotto
