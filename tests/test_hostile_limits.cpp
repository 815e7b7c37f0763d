// Work too large for the process is refused by its estimate before it starts:
// under an address-space limit (`ulimit -v`, the hostile fixture's 2 GiB) a
// generated object that would take gigabytes is refused at once, not after a
// minute of generating ends in bad_alloc.
#include "tests/hostile_fixture.h"

#include <gtest/gtest.h>

namespace grotto {
namespace {

using test::HostileInputs;

TEST_F(HostileInputs, AnObjectPastTheAddressSpaceLeftIsRefusedByItsEstimate) {
    const auto world = writeText("caves.json", R"({"grid": {"file": "good.vdb"}, "objects": [{"name": "c",
        "generator": {"kind": "caves", "size": 4096}, "keys": [{"time": 0, "position": [0, 0, 0]}]}]})");
    // AddressSanitizer reserves terabytes of shadow address space, so its
    // processes run without RLIMIT_AS (tests/test_util.h): there is no limit to hold to.
    if (!test::kAddressSanitizer) {
        const test::RunResult r = runGrotto("info " + world.string(), "", test::kCaps);
        EXPECT_EQ(r.exitCode, 2) << r.err;
        EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
        for (const char* mention : {"objects[0].generator.size", "an estimated", "address space", "ulimit -v"})
            EXPECT_NE(r.err.find(mention), std::string::npos) << mention << " in: " << r.err;
    }
    // Without a limit the budget is the one named, as before.
    expectRefused("info " + writeText("small.json", R"({"grid": {"file": "good.vdb"}, "memory_budget_mib": 64,
        "objects": [{"name": "c", "generator": {"kind": "caves", "size": 4096}, "keys": [{"time": 0, "position": [0, 0, 0]}]}]})").string(),
                  "more than the memory budget of 64.0 MiB", dir_ / "no-output");
}

}  // namespace
}  // namespace grotto
