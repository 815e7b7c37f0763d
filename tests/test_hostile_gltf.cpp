// glTF camera files against the import's promises: a URI reads only files in the
// .gltf's folder (no `..`, symbolic link, absolute path or file:// out of it); a
// file that cannot be read, a megabyte data URI and a bake folder's link loop
// each get one short line naming the file; an imported camera keeps a path file's
// ranges; what glTF 2.0 forbids is refused. All with exit code 2, within the caps.
#include "tests/gltf_camera_writer.h"
#include "tests/hostile_fixture.h"
#include "voxel/camera_path_desc.h"
#include "voxel/gltf/gltf_camera.h"

#include <nlohmann/json.hpp>

namespace grotto::test {
namespace {

// Longer than any error line needs; far shorter than what a file can quote.
constexpr size_t kLongestLine = 1024;

// A camera moved by two LINEAR translation keys.
GltfCameraScene shot() {
    GltfCameraScene s;
    s.samplers = {{"translation", "LINEAR", {0, 1}, {0, 5, 20, 4, 5, 20}}};
    return s;
}

class HostileGltf : public HostileInputs {
protected:
    fs::path pathJson() const { return dir_ / "shot.json"; }
    std::string import(const fs::path& file) const { return "path import " + file.string() + " -o " + pathJson().string(); }

    // Refused as HostileInputs requires, in a line that names the file and stays short.
    RunResult expectImportRefused(const fs::path& file, const std::string& mention) {
        return expectRefusedShort(import(file), file.filename().string(), mention, pathJson());
    }
    RunResult expectRefusedShort(const std::string& args, const std::string& names, const std::string& mention,
                                 const fs::path& output) {
        const RunResult r = expectCommandRefusedWithinCaps(args, mention, output);
        EXPECT_NE(r.err.find(names), std::string::npos) << r.err;
        EXPECT_LT(r.err.size(), kLongestLine) << r.err.substr(0, kLongestLine);
        return r;
    }

    // `base` (a .gltf) with its buffer's URI replaced, as `name` beside it.
    static fs::path withUri(const fs::path& base, const std::string& name, const std::string& uri) {
        nlohmann::json doc = nlohmann::json::parse(std::ifstream(base));
        doc["buffers"][0]["uri"] = uri;
        std::ofstream(base.parent_path() / name) << doc.dump();
        return base.parent_path() / name;
    }
};

TEST_F(HostileGltf, BufferUrisReadOnlyFilesInTheFilesFolder) {
    const fs::path sub = dir_ / "sub";
    fs::create_directories(sub / "bin");
    GltfCameraScene s = shot();
    s.bufferUri = "shot.bin";
    ASSERT_TRUE(writeGltfCamera(s, sub / "in.gltf"));
    // The same buffer beside the folder, below it, and a file of another size outside.
    fs::copy_file(sub / "shot.bin", dir_ / "outside.bin");
    fs::copy_file(sub / "shot.bin", sub / "bin" / "shot.bin");
    fs::create_symlink("../outside.bin", sub / "link.bin");
    const std::string secret(1234567, 's');
    std::ofstream(dir_ / "secret.bin") << secret;

    for (const char* uri : {"shot.bin", "./shot.bin", "bin/shot.bin", "bin/../shot.bin"}) {
        SCOPED_TRACE(uri);
        EXPECT_NO_THROW((void)voxel::importGltfCameraPath(withUri(sub / "in.gltf", "ok.gltf", uri)));
    }
    const std::string outside = (dir_ / "outside.bin").string();
    const std::pair<std::string, std::string> refused[] = {
        {"../outside.bin", "leads outside the file's folder"},
        {"bin/../../outside.bin", "leads outside the file's folder"},
        {"%2E%2E/outside.bin", "leads outside the file's folder"},  // URL-decoded first
        {"link.bin", "leads outside the file's folder"},            // a symbolic link out
        {"../secret.bin", "leads outside the file's folder"},
        {"../../../../../../../../../../etc/passwd", "leads outside the file's folder"},
        {outside, "is an absolute path"},
        {"file://" + outside, "is not a relative file name"},
    };
    for (size_t i = 0; i < std::size(refused); ++i) {
        SCOPED_TRACE(refused[i].first);
        const fs::path file = withUri(sub / "in.gltf", "out" + std::to_string(i) + ".gltf", refused[i].first);
        const RunResult r = expectImportRefused(file, refused[i].second);
        EXPECT_EQ(r.err.find(std::to_string(secret.size())), std::string::npos) << "a size from outside: " << r.err;
    }
}

TEST_F(HostileGltf, UnreadableFilesAndLongQuotesGetOneShortLine) {
    // /proc/self/mem is a "regular file" whose first read fails.
    fs::create_symlink("/proc/self/mem", dir_ / "mem.glb");
    expectImportRefused(dir_ / "mem.glb", "cannot be read");
    // 8 MiB of base64 in a data URI that does not decode to its byteLength.
    std::ofstream(dir_ / "big.gltf") << R"({"asset": {"version": "2.0"}, "buffers": [{"byteLength": 1, "uri": )"
                                     << "\"data:application/octet-stream;base64," << std::string(size_t(8) << 20, 'A')
                                     << "\"}]}";
    expectImportRefused(dir_ / "big.gltf", "Failed to decode");
}

TEST_F(HostileGltf, ASymbolicLinkLoopInTheBakeFolderIsRefused) {
    const fs::path bakes = dir_ / "bakes";
    fs::create_directories(bakes);
    fs::create_symlink("good.gfc", bakes / "good.gfc");  // good.vdb's bake, a link to itself
    const std::string run = "tradeoff " + good_.string() + " --size 32x24 --frames 1 --warmup 0 --csv " +
                            (dir_ / "t.csv").string() + " --bakes ";
    expectRefusedShort(run + bakes.string(), "good.gfc", "cannot be read", dir_ / "t.csv");
    fs::create_symlink("loop", dir_ / "loop");
    expectRefusedShort(run + (dir_ / "loop").string(), "loop", "cannot be read", dir_ / "t.csv");
}

// A camera far beyond a path file's ±1e12 is refused where it is read, by
// `path import` and by flythrough alike; one just inside imports and reads back.
TEST_F(HostileGltf, AnImportedCameraKeepsThePathFilesRanges) {
    GltfCameraScene s = shot();
    s.parentScale = 1e300;
    ASSERT_TRUE(writeGltfCamera(s, dir_ / "huge.glb"));
    const std::string at = "node 1 'Camera' (the camera) is at (0, 5e+300, 2e+301)";
    expectImportRefused(dir_ / "huge.glb", at);
    const fs::path frames = dir_ / "frames";
    expectRefusedShort("flythrough " + good_.string() + " --path-file " + (dir_ / "huge.glb").string() +
                           " --size 32x16 -o " + frames.string(),
                       "huge.glb", at, frames);
    s.parentScale = 1e11;  // the camera at z = 2e12
    ASSERT_TRUE(writeGltfCamera(s, dir_ / "far.glb"));
    expectImportRefused(dir_ / "far.glb", "(0, 5e+11, 2e+12)");
    s.parentScale = 4e10;  // at z = 8e11
    ASSERT_TRUE(writeGltfCamera(s, dir_ / "near.glb"));
    ASSERT_EQ(runGrotto(import(dir_ / "near.glb")).exitCode, 0);
    EXPECT_NEAR(voxel::loadCameraPath(pathJson()).keys.back().position.x, 1.6e11, 1.0);
}

TEST_F(HostileGltf, WhatGltf2ForbidsIsRefused) {
    ASSERT_TRUE(writeGltfCamera(shot(), dir_ / "v1.glb"));
    std::string glb = bytesOf(dir_ / "v1.glb");
    glb[4] = 1;  // the header's version
    expectImportRefused(writeBytes("v1.glb", glb), "GLB of version 1");
    GltfCameraScene old = shot();
    old.assetVersion = "1.0";
    ASSERT_TRUE(writeGltfCamera(old, dir_ / "old.glb"));
    expectImportRefused(dir_ / "old.glb", "'asset.version' is '1.0'");
    // The translation's channel aimed at node 50 of 2: the camera would play without it.
    GltfCameraScene stray = shot();
    stray.samplers.push_back({"rotation", "LINEAR", {0, 1}, {0, 0, 0, 1, 0, 0.38f, 0, 0.92f}});
    stray.samplers[0].node = 50;
    ASSERT_TRUE(writeGltfCamera(stray, dir_ / "stray.glb"));
    expectImportRefused(dir_ / "stray.glb", "channel 0 targets node 50, which does not exist");
}

}  // namespace
}  // namespace grotto::test
