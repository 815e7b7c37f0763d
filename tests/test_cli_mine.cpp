// The shipped mine's palette on a small mine from `mkworld`: `info` lists its
// three glowing materials (torches, crystals, lava) with their power. (The
// refusal of --lamps for other kinds is tested in test_mine_world.cpp, without
// a process.)
#include "tests/cli_fixture.h"

#include <fstream>
#include <sstream>

namespace grotto::test {
namespace {

class CliMine : public CliErrors {};

TEST_F(CliMine, InfoListsTheTorchesCrystalsAndLava) {
    const RunResult made = runGrotto("mkworld mine --size 64 -o " + (dir_ / "mine.vdb").string());
    ASSERT_EQ(made.exitCode, 0) << made.err;
    std::stringstream shipped;
    shipped << std::ifstream(worldsDir() / "mine.json").rdbuf();
    std::string text = shipped.str();
    ASSERT_NE(text.find("\"mine.vdb\""), std::string::npos) << "the shipped mine names mine.vdb";
    const RunResult r = runGrotto("info " + writeText("mine.json", text).string());
    ASSERT_EQ(r.exitCode, 0) << r.err;
    // Five flames on posts, five faces each in the air: pi x 8 x 25 x colour.
    EXPECT_NE(r.out.find("emitter        material 5: radiance (8 4.96 2.24) over 25 square units"), std::string::npos)
        << r.out;
    EXPECT_NE(r.out.find("emitter        material 6: radiance (0.875 1.625 2.5)"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("emitter        material 7: radiance (3 0.96 0.18)"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("emitters       3 materials"), std::string::npos) << r.out;
}

}  // namespace
}  // namespace grotto::test
