// The reader process that reads a .vdb under limits before the library does: it
// starts fresh, so locks other threads hold at that instant cannot stop it. (It
// was a bare fork: a fork copies the locks other threads hold, and a child that
// needed OpenVDB's type registries while a thread held them waited until the
// parent gave up, "reading it stalled for 20 s", about once in five suites.)
#include "grotto/error.h"
#include "tests/test_util.h"
#include "voxel/world.h"

#include <gtest/gtest.h>
#include "voxel/openvdb_grids.h"

#include <atomic>
#include <thread>

namespace grotto::voxel {
namespace {

namespace fs = std::filesystem;

TEST(VdbReader, LoadsWhileOtherThreadsHoldOpenVdbsRegistries) {
    openvdb::initialize();
    grotto::test::ScratchDir dir;
    const std::vector<uint8_t> ids(12 * 9 * 7, 1);
    World::fromDense({12, 9, 7}, ids.data(), 1.0, {0.0, 0.0, 0.0}).save(dir / "small.vdb");

    // Threads that keep taking the locks the reader needs: the grid and metadata
    // type registries, which every file read consults. (The fork stalled within
    // ten loads here.)
    std::atomic<bool> stop = false;
    std::vector<std::thread> threads;
    for (int t = 0; t < 2; ++t)
        threads.emplace_back([&] {
            while (!stop) {
                openvdb::GridBase::isRegistered(openvdb::FloatGrid::gridType());
                openvdb::Metadata::isRegisteredType("int64");
            }
        });
    int loaded = 0;
    std::string failure;
    for (; loaded < 30 && failure.empty(); ++loaded) {
        try {
            const World back = World::load(dir / "small.vdb");
            if (back.stats().solidVoxels != 12u * 9 * 7) failure = "read back wrong";
        } catch (const Error& e) {
            failure = e.what();
        }
    }
    stop = true;
    for (std::thread& t : threads) t.join();
    EXPECT_EQ(failure, "") << "load " << loaded;
}

}  // namespace
}  // namespace grotto::voxel
