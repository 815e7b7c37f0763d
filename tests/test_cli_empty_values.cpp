// An empty value given to a flag is refused naming the flag, for every command:
// CLI11 took '' as the type's empty value, so `bake --chunk ''` baked everything
// and `--radius ''` took the default.
#include "tests/cli_fixture.h"

#include <gtest/gtest.h>

#include <utility>

namespace grotto::test {
namespace {

TEST_F(CliErrors, EmptyFlagValuesAreRefusedNamingTheFlag) {
    const std::string good = good_.string(), fly = writeFlyWorld().string();
    const fs::path gfc = dir_ / "out.gfc", seq = dir_ / "seq", glb = dir_ / "out.glb";
    auto empty = [](const std::string& flag) { return flag + ": an empty value is not accepted"; };
    const std::pair<std::string, std::string> cases[] = {
        {"bake " + good + " -o " + gfc.string() + " --chunk ''", empty("--chunk")},
        {"bake " + good + " -o " + gfc.string() + " --chunk=", "--chunk: 1 required"},  // no value at all
        {"bake " + good + " -o " + gfc.string() + " --rays ''", empty("--rays")},
        {render(good_) + " --radius ''", empty("--radius")},
        {render(good_) + " --camera ''", empty("--camera")},
        {render(good_) + " --temporal ''", empty("--temporal")},   // a setting of the settings table
        {render(good_) + " --lod-bias ''", empty("--lod-bias")},   // and one of its detail block
        {"render " + good + " -o ''", empty("--output")},
        {"flythrough " + fly + " --path p -o " + seq.string() + " --fps ''", empty("--fps")},
        {"flythrough " + fly + " --path p -o " + seq.string() + " --warmup ''", empty("--warmup")},
        {"flythrough " + fly + " --path p -o " + seq.string() + " --chunk ''", empty("--chunk")},
        {"flythrough " + fly + " --path '' -o " + seq.string(), empty("--path")},  // in an option group
        {"export-mesh " + good + " -o " + glb.string() + " --radius ''", empty("--radius")},
        {"info ''", empty("world")},  // a positional value too
    };
    for (const auto& [args, mention] : cases) {
        SCOPED_TRACE(args);
        expectRefused(args, mention, out());
        EXPECT_FALSE(fs::exists(gfc));
        EXPECT_FALSE(fs::exists(seq));
        EXPECT_FALSE(fs::exists(glb));
    }
}

}  // namespace
}  // namespace grotto::test
