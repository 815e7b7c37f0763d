// OpenImageIO (some 250 shared libraries, 0.3 s of CPU to relocate at every start)
// is loaded by the image codec module on the first image encoded or decoded
// (but an 8-bit PNG written), never by a run that touches no image. The dynamic loader's own account
// (LD_DEBUG=files lists every object it maps) tells which runs mapped what.
#include "tests/cli_fixture.h"

#include <gtest/gtest.h>

namespace grotto {
namespace {

using test::CliErrors;
using test::runGrotto;

const std::string kListLoads = "LD_DEBUG=files";

bool mapped(const test::RunResult& r, const std::string& library) { return r.err.find(library) != std::string::npos; }

TEST_F(CliErrors, AnInfoRunMapsNoImageCodec) {
    const test::RunResult r = runGrotto("info " + good_.string(), kListLoads);
    ASSERT_EQ(r.exitCode, 0) << r.err;
    ASSERT_TRUE(mapped(r, "libvulkan")) << "LD_DEBUG listed nothing: " << r.err.substr(0, 400);
    EXPECT_FALSE(mapped(r, "libOpenImageIO"));
    EXPECT_FALSE(mapped(r, "libgrotto_image_codec"));
}

// A frame's 8-bit PNG is written by libpng in the program (png_writer.h): the
// commonest image loads nothing more.
TEST_F(CliErrors, APngFrameIsWrittenWithoutTheCodec) {
    const test::RunResult r = runGrotto(render(good_), kListLoads);
    ASSERT_EQ(r.exitCode, 0) << r.err;
    ASSERT_TRUE(mapped(r, "libvulkan")) << "LD_DEBUG listed nothing: " << r.err.substr(0, 400);
    EXPECT_FALSE(mapped(r, "libgrotto_image_codec"));
    EXPECT_FALSE(mapped(r, "libOpenImageIO"));
    EXPECT_FALSE(test::readPixels8(out()).empty());
}

TEST_F(CliErrors, AnExrWrittenLoadsTheCodecOnFirstUse) {
    const fs::path exr = dir_ / "out.exr";
    const test::RunResult r = runGrotto("render " + good_.string() + " --size 16x8 -o " + exr.string(), kListLoads);
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_TRUE(mapped(r, "libgrotto_image_codec"));
    EXPECT_TRUE(mapped(r, "libOpenImageIO"));
    EXPECT_TRUE(fs::exists(exr));
}

}  // namespace
}  // namespace grotto
