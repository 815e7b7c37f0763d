#pragma once
// The hostile-input tests' fixture: each damaged or hostile file is refused with
// exit code 2 and one line, nothing written, within 2 s of CPU time (RLIMIT_CPU on
// the grotto process: a run that needs more is killed and fails) and 512 MiB of
// memory beyond what grotto needs for a good world (its peak resident set,
// measured; RLIMIT_AS at 2 GiB only keeps a failing run from taking the machine).
#include "tests/cli_fixture.h"

#include <gtest/gtest.h>
#include "voxel/openvdb_grids.h"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <functional>
#include <random>
#include <string>

namespace grotto::test {

const RunLimits kCaps{.memoryMiB = 2048, .cpuSeconds = 2, .hangSeconds = 60};
constexpr double kReadingMiB = 512;

class HostileInputs : public CliErrors {
protected:
    // `grotto info` loads and meshes the world: the whole way a file is read.
    void expectRefusedWithinCaps(const fs::path& file, const std::string& mention) {
        SCOPED_TRACE(file.filename().string());
        expectCommandRefusedWithinCaps("info " + file.string(), mention);
    }
    // Any command; `output` is what it must not have written.
    RunResult expectCommandRefusedWithinCaps(const std::string& args, const std::string& mention,
                                             const fs::path& output = {}) {
        SCOPED_TRACE(args);
        const RunResult r = expectRefused(args, mention, output.empty() ? dir_ / "no-output" : output, "", kCaps);
        if (!kAddressSanitizer) EXPECT_LE(r.peakMiB, goodWorldMiB() + kReadingMiB);
        return r;
    }

    // What `grotto info` of a small good world takes, measured once.
    double goodWorldMiB() {
        static const double mib = [&] {
            const RunResult r = runGrotto("info " + good_.string(), "", kCaps);
            EXPECT_EQ(r.exitCode, 0) << r.err;
            return r.peakMiB;
        }();
        return mib;
    }

    std::string bytesOf(const fs::path& p) {
        std::ifstream in(p, std::ios::binary);
        return {std::istreambuf_iterator<char>(in), {}};
    }

    fs::path writeBytes(const std::string& name, const std::string& bytes) {
        std::ofstream(dir_ / name, std::ios::binary) << bytes;
        return dir_ / name;
    }

    // `real` with one bit flipped at byte at(n), for n < count, each file run as
    // `command` FILE `tail`: read (exit 0), or refused in one line naming the file
    // (exit 2) with `output` not written; never a crash, never past the caps.
    void expectBitFlipsReadOrRefused(const std::string& real, const std::string& ext, const std::string& command,
                                     const std::string& tail, const fs::path& output, int count,
                                     const std::function<size_t(int n)>& at, std::mt19937& rng) {
        for (int n = 0; n < count; ++n) {
            std::string bytes = real;
            const size_t i = at(n);
            bytes[i] = char(bytes[i] ^ (1 << (rng() % 8)));
            const fs::path flipped = writeBytes("flip" + std::to_string(n) + ext, bytes);
            const RunResult r = runGrotto(command + " " + flipped.string() + tail, "", kCaps);
            EXPECT_TRUE(r.exitCode == 0 || r.exitCode == 2) << r.err;
            if (r.exitCode == 2) {
                EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
                EXPECT_NE(r.err.find(flipped.filename().string()), std::string::npos) << r.err;
                if (!output.empty()) EXPECT_FALSE(fs::exists(output));
            }
            if (!output.empty()) fs::remove(output);
        }
    }

    fs::path oneVoxelGrid(const std::string& name, openvdb::Coord at, openvdb::math::Transform::Ptr xf = nullptr) {
        auto grid = openvdb::BoolGrid::create(false);
        grid->setName("solid");
        grid->tree().setValueOn(at, true);
        if (xf) grid->setTransform(xf);
        writeGrids(dir_ / name, {grid});
        return dir_ / name;
    }
};

}  // namespace grotto::test
