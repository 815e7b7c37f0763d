// The flythrough's frame writer (app/frame_writer.h): every frame rendered into
// a slot reaches its job with the images readback would give, in any number of
// frames through two slots; and the first error a job throws reaches the main
// thread, after which no later job runs.
#include "app/frame_writer.h"
#include "grotto/error.h"
#include "engine/renderer.h"
#include "tests/gpu_fixture.h"
#include "tests/test_util.h"
#include "voxel/world.h"

#include <atomic>
#include <chrono>
#include <map>
#include <mutex>
#include <thread>

namespace grotto {
namespace {

using test::GpuTest;

struct Rendering {
    voxel::World world = voxel::World::load(test::worldsDir() / "rooms.json");
    std::unique_ptr<GpuScene> scene;
    std::unique_ptr<Renderer> renderer;
    Camera camera;
    explicit Rendering(vk::Context& ctx) : scene(uploadScene(ctx, world)) {
        const AoOptions ao = aoOptionsFor(world.desc().ao, world.voxelSize(), "test");
        renderer = std::make_unique<Renderer>(ctx, *scene, world.desc().lighting, ao, 48, 27);
        camera = worldCamera(world, "", 48, 27);
    }
};

using FrameWriterTest = GpuTest;

TEST_F(FrameWriterTest, EveryFrameReachesItsJob) {
    Rendering r(ctx());
    std::mutex m;
    std::map<int, std::vector<float>> seen;
    std::map<int, std::vector<float>> expected;
    {
        app::FrameWriter writer(ctx(), false, 3);
        for (int i = 1; i <= 12; ++i) {
            FrameCopy& slot = writer.slot();
            r.renderer->render(r.camera, uint32_t(i), &slot);
            expected[i] = r.renderer->readback(r.camera, false).color;
            writer.submit(slot, [&, i](const FrameImages& f) {
                std::lock_guard lock(m);
                seen[i] = f.color;
            });
        }
        writer.finish();
    }
    ASSERT_EQ(seen.size(), 12u);
    for (auto& [i, colour] : expected) EXPECT_TRUE(seen[i] == colour) << "frame " << i;
}

TEST_F(FrameWriterTest, FirstErrorReachesTheMainThreadAndStopsTheRest) {
    Rendering r(ctx());
    std::atomic<int> ran{0}, after{0}, afterCaught{0};
    std::atomic<bool> thrown{false}, caughtHere{false};
    app::FrameWriter writer(ctx(), false, 2);
    std::string caught;
    try {
        for (int i = 1; i <= 40; ++i) {
            FrameCopy& slot = writer.slot();
            r.renderer->render(r.camera, uint32_t(i), &slot);
            writer.submit(slot, [&, i](const FrameImages&) {
                ++ran;
                if (caughtHere) ++afterCaught;
                if (i == 3) {
                    thrown = true;
                    throw Error("frame.0003.png", "cannot be written: disk full");
                }
                // Later jobs wait for frame 3's to fail: on a busy machine its
                // thread may be held up while the other runs frame after frame.
                const auto start = std::chrono::steady_clock::now();
                while (i > 3 && !thrown && std::chrono::steady_clock::now() - start < std::chrono::seconds(10))
                    std::this_thread::yield();
                if (i > 3) ++after;
            });
        }
        writer.finish();
    } catch (const Error& e) {
        caughtHere = true;
        caught = e.what();
    }
    EXPECT_EQ(caught, "frame.0003.png: cannot be written: disk full");
    // Jobs already under way when frame 3 failed may finish; none is started
    // after, and the main thread stops at its next call.
    EXPECT_LT(ran.load(), 40) << "the run stopped at the error";
    EXPECT_LT(after.load(), 10);
    EXPECT_EQ(afterCaught.load(), 0) << "no job starts once the main thread has the error";
}

}  // namespace
}  // namespace grotto
