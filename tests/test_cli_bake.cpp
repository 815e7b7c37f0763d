// grotto bake: a farm's parts (--chunk K/N) joined with --merge are byte for byte
// the one-machine bake; bad parts and bad files are refused with one line naming
// the file and what is wrong, and nothing written. render --bake reads a bake of
// its world and refuses another's, another radius's, a part and another --ao.
#include "tests/cli_fixture.h"

#include <gtest/gtest.h>

#include <fstream>
#include <iterator>

namespace grotto::test {
namespace {

class Bake : public CliErrors {
protected:
    void SetUp() override {
        CliErrors::SetUp();
        pillars_ = dir_ / "pillars.vdb";  // a floor with pillars and a roof over part of it
        writeSolid(pillars_, 12, 6, [](int x, int y, int z) {
            return y == 0 || (x % 4 == 1 && z % 4 == 1) || (y == 5 && x < 6);
        });
    }
    std::string bake(const fs::path& world, const fs::path& out, const std::string& more = "") {
        return "bake " + world.string() + " -o " + out.string() + " --rays 16 --sun-rays 2 " + more;
    }
    fs::path pillars_;
};

TEST_F(Bake, PartsJoinedInAnyOrderAreTheWholeBakeByteForByte) {
    const fs::path whole = dir_ / "whole.gfc";
    ASSERT_EQ(runGrotto(bake(pillars_, whole)).exitCode, 0);
    std::string parts;
    for (int k = 1; k <= 3; ++k) {
        const fs::path part = dir_ / ("part" + std::to_string(k) + ".gfc");
        const RunResult r = runGrotto(bake(pillars_, part, "--chunk " + std::to_string(k) + "/3"));
        ASSERT_EQ(r.exitCode, 0) << r.err;
        parts = part.string() + " " + parts;  // reversed: the order given does not matter
    }
    const fs::path merged = dir_ / "merged.gfc";
    const RunResult r = runGrotto("bake --merge " + parts + "-o " + merged.string());
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const std::string a = fileBytes(whole), b = fileBytes(merged);
    EXPECT_GT(a.size(), 132u + 100u * 4u * 24u);  // a header and hundreds of faces of 2 x 2 texels
    EXPECT_TRUE(a == b);
}

TEST_F(Bake, BadArgumentsPartsAndFilesAreRefused) {
    const fs::path out = dir_ / "out.gfc";
    expectRefused(bake(pillars_, out, "--chunk 4/3"), "--chunk", out);
    expectRefused(bake(pillars_, out, "--chunk 0/3"), "--chunk", out);
    expectRefused(bake(pillars_, dir_ / "out.bin"), "out.bin", dir_ / "out.bin");
    std::vector<fs::path> parts;
    for (int k = 1; k <= 3; ++k) {
        parts.push_back(dir_ / ("p" + std::to_string(k - 1) + ".gfc"));
        ASSERT_EQ(runGrotto(bake(pillars_, parts.back(), "--chunk " + std::to_string(k) + "/3")).exitCode, 0);
    }
    const std::string p0 = parts[0].string(), p1 = parts[1].string(), p2 = parts[2].string();
    expectRefused("bake --merge " + p0 + " " + p2 + " -o " + out.string(), "p2.gfc", out);  // a gap
    expectRefused("bake --merge " + p0 + " " + p1 + " -o " + out.string(), "missing", out);
    expectRefused("bake --merge " + p0 + " " + p0 + " " + p1 + " " + p2 + " -o " + out.string(), "overlap", out);
    const fs::path other = dir_ / "other.gfc";  // another world's part 1
    ASSERT_EQ(runGrotto(bake(good_, other, "--chunk 2/3")).exitCode, 0);
    expectRefused("bake --merge " + p0 + " " + other.string() + " " + p2 + " -o " + out.string(), "other.gfc", out);

    // Damaged files: each refused naming the file and the field.
    const std::string good = fileBytes(parts[1]);
    // Alone, the part's gap is `alone`: every header is compared before texels are read.
    auto damaged = [&](const std::string& name, const std::string& content, const std::string& field,
                       const std::string& alone = "") {
        const fs::path p = dir_ / name;
        std::ofstream(p, std::ios::binary) << content;
        expectRefused("bake --merge " + p0 + " " + p.string() + " " + p2 + " -o " + out.string(), field, out);
        EXPECT_NE(expectRefused("bake --merge " + p.string() + " -o " + out.string(), name, out).err.find(alone.empty() ? field : alone),
                  std::string::npos);
    };
    damaged("short.gfc", good.substr(0, 40), "header");
    damaged("truncated.gfc", good.substr(0, good.size() - 5), "texels");
    damaged("longer.gfc", good + "x", "texels");
    std::string magic = good;
    magic[0] = 'X';
    damaged("magic.gfc", magic, "magic");
    std::string version = good;
    version[8] = 9;
    damaged("version.gfc", version, "version");
    std::string huge = good;  // a face count that would need exabytes
    for (int i = 0; i < 8; ++i) huge[88 + i] = char(0x7f);  // the face count, at byte 88
    damaged("huge.gfc", huge, "faces");
    std::string counts = good;  // a texel with more open rays than rays
    counts[132 + 4] = char(0xff);  // the first texel's open rays (the header is 132 bytes)
    damaged("counts.gfc", counts, "texel 0", "leave a gap");
}

TEST_F(Bake, RenderReadsItsWorldsBakeAndRefusesAnyOther) {
    const fs::path bakeFile = dir_ / "pillars.gfc", part = dir_ / "part.gfc", png = dir_ / "out.png";
    ASSERT_EQ(runGrotto(bake(pillars_, bakeFile)).exitCode, 0);
    ASSERT_EQ(runGrotto(bake(pillars_, part, "--chunk 1/2")).exitCode, 0);
    const std::string render = "render " + pillars_.string() + " --size 48x32 -o " + png.string() + " --bake ";
    const RunResult ok = runGrotto(render + bakeFile.string());
    ASSERT_EQ(ok.exitCode, 0) << ok.err;
    EXPECT_NE(ok.out.find("1 frame,"), std::string::npos) << ok.out;  // converged already: nothing to accumulate
    ASSERT_TRUE(fs::exists(png));
    fs::remove(png);
    const fs::path moved = dir_ / "moved.vdb";  // one pillar more
    writeSolid(moved, 12, 6, [](int x, int y, int z) {
        return y == 0 || (x % 4 == 1 && z % 4 == 1) || (y == 5 && x < 6) || (x == 10 && z == 10);
    });
    expectRefused("render " + moved.string() + " --size 48x32 -o " + png.string() + " --bake " + bakeFile.string(),
                  "pillars.gfc: baked for other voxels", png);
    expectRefused(render + bakeFile.string() + " --radius 2", "AO radius", png);
    expectRefused(render + part.string(), "a part of a bake", png);
    expectRefused(render + bakeFile.string() + " --ao gtao", "--bake", png);
    expectRefused(render + bakeFile.string() + " --progressive", "--progressive: starts the face cache empty", png);

    // The day's sun (--time-of-day): one bake serves every hour, and is no fixed sun's.
    const fs::path day = dir_ / "day.gfc", dayPart = dir_ / "day-part.gfc";
    ASSERT_EQ(runGrotto(bake(pillars_, day, "--time-of-day 10")).exitCode, 0);
    ASSERT_EQ(runGrotto(bake(pillars_, dayPart, "--time-of-day 10 --chunk 2/2")).exitCode, 0);
    EXPECT_EQ(fileBytes(day).size(), fileBytes(bakeFile).size() + 4 * (fileBytes(bakeFile).size() - 132) / 24)
        << "4 bytes a texel more";
    for (const char* hour : {"6.5", "13", "18.25"}) {
        const RunResult r = runGrotto(render + day.string() + " --time-of-day " + hour);
        EXPECT_EQ(r.exitCode, 0) << r.err;
        EXPECT_TRUE(fs::remove(png));
    }
    expectRefused(render + day.string(), "day's sun: baked for latitude 45", png);
    expectRefused(render + bakeFile.string() + " --time-of-day 12", "day's sun: baked for none", png);
    expectRefused("bake --merge " + part.string() + " " + dayPart.string() + " -o " + (dir_ / "mixed.gfc").string(),
                  "day's sun", dir_ / "mixed.gfc");
}

// --progressive: no bake; the GPU traces what the still sees until none is left,
// and the image is the bake's (the same rays), to the 8-bit level.
TEST_F(Bake, AProgressiveStillRendersUntilConvergedAndMatchesTheBake) {
    const fs::path bakeFile = dir_ / "pillars.gfc", baked = dir_ / "baked.png", traced = dir_ / "traced.png";
    ASSERT_EQ(runGrotto("bake " + pillars_.string() + " -o " + bakeFile.string()).exitCode, 0);  // the defaults' rays
    const std::string render = "render " + pillars_.string() + " --size 48x32 -o ";
    ASSERT_EQ(runGrotto(render + baked.string() + " --bake " + bakeFile.string()).exitCode, 0);
    const RunResult r = runGrotto(render + traced.string() + " --ao cache --progressive");
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_EQ(r.out.find(" 1 frame,"), std::string::npos) << r.out;  // it took more than one
    const std::vector<uint8_t> a = readPixels8(baked);
    ASSERT_FALSE(a.empty());
    EXPECT_LE(worstDifference(a, readPixels8(traced)), 1);  // 8-bit sRGB levels
    expectRefused(render + (dir_ / "refused.png").string() + " --ao gtao --progressive", "--progressive", dir_ / "refused.png");
}

}  // namespace
}  // namespace grotto::test
