#pragma once
// The CLI tests' fixture: a scratch directory with a small good world in it, and
// the check every refusal must pass (exit code 2, one stderr line naming the
// problem, no output and no temporary file left behind).
#include "engine/image_input.h"
#include "tests/test_util.h"

#include <gtest/gtest.h>
#include "voxel/openvdb_grids.h"

#include <algorithm>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

namespace grotto::test {

namespace fs = std::filesystem;

// Whether a file ends with a PNG's end chunk. libpng leaves a truncated PNG by a
// longjmp that leaks OpenImageIO's error string (LeakSanitizer fails the test),
// so a PNG without it is not handed to OpenImageIO.
inline bool endsWithPngEnd(const fs::path& file) {
    static constexpr char kEnd[12] = {0, 0, 0, 0, 'I', 'E', 'N', 'D', char(0xAE), 0x42, 0x60, char(0x82)};
    std::ifstream in(file, std::ios::binary);
    char tail[12] = {};
    return in.seekg(-12, std::ios::end) && in.read(tail, 12) && std::equal(tail, tail + 12, kEnd);
}

// An image's pixels as 8-bit channels, interleaved; empty if it cannot be read.
inline std::vector<uint8_t> readPixels8(const fs::path& file) {
    if (file.extension() == ".png" && !endsWithPngEnd(file)) return {};
    const std::optional<ImageFile> image = readImage(file, ReadAs::UInt8);
    return image ? image->bytes : std::vector<uint8_t>{};
}

// The largest difference of any channel of two images of one size (256 if the sizes differ).
inline int worstDifference(const std::vector<uint8_t>& a, const std::vector<uint8_t>& b) {
    if (a.size() != b.size()) return 256;
    int worst = 0;
    for (size_t k = 0; k < a.size(); ++k) worst = std::max(worst, std::abs(int(a[k]) - int(b[k])));
    return worst;
}

class CliErrors : public ::testing::Test {
protected:
    void SetUp() override {
        openvdb::initialize();
        good_ = dir_ / "good.vdb";
        writeSolid(good_, 16, 1, [](int, int, int) { return true; });  // a 16 x 16 floor
    }

    static void writeGrids(const fs::path& p, openvdb::GridPtrVec grids) { openvdb::io::File(p.string()).write(grids); }

    // A bool grid "solid" over x, z in [0, width) and y in [0, height), set where `solid` says.
    template <class Solid>
    static void writeSolid(const fs::path& p, int width, int height, Solid solid) {
        auto grid = openvdb::BoolGrid::create(false);
        grid->setName("solid");
        for (int x = 0; x < width; ++x)
            for (int y = 0; y < height; ++y)
                for (int z = 0; z < width; ++z)
                    if (solid(x, y, z)) grid->tree().setValueOn(openvdb::Coord(x, y, z), true);
        writeGrids(p, {grid});
    }

    fs::path writeText(const std::string& name, const std::string& text) {
        std::ofstream(dir_ / name) << text;
        return dir_ / name;
    }

    // Exit code 2, a single stderr line naming `mention`, and no output written.
    RunResult expectRefused(const std::string& args, const std::string& mention, const fs::path& output,
                       const std::string& env = "", const RunLimits& limits = {}) {
        const RunResult r = runGrotto(args, env, limits);
        EXPECT_EQ(r.exitCode, 2) << args << "\n" << r.err;
        EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
        EXPECT_NE(r.err.find(mention), std::string::npos) << "expected '" << mention << "' in: " << r.err;
        EXPECT_EQ(r.err.find("terminate"), std::string::npos);
        EXPECT_FALSE(fs::exists(output)) << output;
        for (auto& e : fs::directory_iterator(dir_.path))
            EXPECT_EQ(e.path().filename().string().find(".tmp"), std::string::npos) << "left behind: " << e.path();
        return r;
    }

    // A world over the test floor with a path "p" of one second: 9 frames at --fps 8.
    fs::path writeFlyWorld() {
        return writeText("fly.json", R"({"grid": {"file": "good.vdb"}, "paths": {"p": {"keys": [
            {"time": 0, "position": [8, 10, 30], "target": [8, 0, 8]},
            {"time": 0.5, "position": [20, 8, 24], "target": [8, 0, 8]},
            {"time": 1, "position": [26, 6, 12], "target": [8, 0, 6]}]}}})");
    }

    std::string render(const fs::path& world) { return "render " + world.string() + " --size 32x16 -o " + out().string(); }
    fs::path out() const { return dir_ / "out.png"; }

    ScratchDir dir_;
    fs::path good_;
};

}  // namespace grotto::test
