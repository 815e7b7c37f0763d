// Two frames in flight (Renderer::submit):
//  - frames submitted without waiting, the next before the last has finished,
//    copy out exactly what render() draws for the same frames;
//  - a frame waits for the game's semaphore on the GPU, not the CPU;
//  - with occlusion culling (against the tiles of a finished frame), the image
//    is render()'s for a static camera, and culling still hides clusters;
//  - synchronisation validation stays silent over frames with an edit, moving
//    objects and a game's reads of each frame in between (the fixture counts
//    every validation message).
#include "engine/frame/frame_copy.h"
#include "engine/renderer.h"
#include "engine/session.h"
#include "engine/vk/resources.h"
#include "tests/gpu_fixture.h"
#include "tests/test_util.h"
#include "voxel/world.h"

#include <chrono>
#include <cstring>
#include <thread>

namespace grotto {
namespace {

using test::GpuTest;
using FramesInFlight = GpuTest;

constexpr uint32_t kSize = 64;

bool sameBytes(const std::vector<float>& a, const std::vector<float>& b) {
    return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(float)) == 0;
}

struct Frames {
    voxel::World world;
    std::unique_ptr<GpuScene> scene;
    AoOptions ao;
    Camera camera;
    explicit Frames(vk::Context& ctx, const char* file)
        : world(voxel::World::load(test::worldsDir() / file)), scene(uploadScene(ctx, world)),
          ao(aoOptionsFor(world.desc().ao, world.voxelSize(), "test")),
          camera(makeCamera(world.camera("", 1.0), kSize, kSize)) {}
    std::unique_ptr<Renderer> renderer(vk::Context& ctx, bool occlusion) const {
        auto r = std::make_unique<Renderer>(ctx, *scene, world.desc().lighting, ao, kSize, kSize);
        r->setCulling({.lodBias = 0.0, .occlusion = occlusion});
        return r;
    }
};

uint64_t timelineNow(vk::Context& ctx, const Renderer& r) {
    uint64_t v = 0;
    VK_CHECK(vkGetSemaphoreCounterValue(ctx.device, r.timeline(), &v));
    return v;
}

void waitTimeline(vk::Context& ctx, VkSemaphore semaphore, uint64_t value) {
    const VkSemaphoreWaitInfo wi{.sType = VK_STRUCTURE_TYPE_SEMAPHORE_WAIT_INFO,
                                 .semaphoreCount = 1, .pSemaphores = &semaphore, .pValues = &value};
    VK_CHECK(vkWaitSemaphores(ctx.device, &wi, UINT64_MAX));
}

// Frames 1..4 of a static camera with AO, its temporal history and soft sun
// shadows: all four submitted before any is waited for, each copied by its own
// command buffer, then read after its timeline value.
TEST_F(FramesInFlight, SubmittedFramesAreTheBlockingPathsBitForBit) {
    Frames f(ctx(), "rooms.json");
    auto blocking = f.renderer(ctx(), false), inFlight = f.renderer(ctx(), false);
    constexpr uint32_t kFrames = 4;
    std::vector<std::unique_ptr<FrameCopy>> copies;
    std::vector<uint64_t> values;
    for (uint32_t i = 1; i <= kFrames; ++i) {
        copies.push_back(std::make_unique<FrameCopy>(ctx(), true));
        values.push_back(inFlight->submit(f.camera, i, {}, copies.back().get()).timelineValue);
    }
    EXPECT_LT(values[0], values[1]);
    for (uint32_t i = 1; i <= kFrames; ++i) {
        FrameCopy expected(ctx(), true);
        blocking->render(f.camera, i, &expected);
        waitTimeline(ctx(), inFlight->timeline(), values[i - 1]);
        const FrameImages a = expected.decode(), b = copies[i - 1]->decode();
        ASSERT_FALSE(a.color.empty());
        EXPECT_TRUE(sameBytes(a.color, b.color)) << "colour of frame " << i;
        EXPECT_TRUE(sameBytes(a.aoHistory, b.aoHistory)) << "AO history of frame " << i;
        EXPECT_TRUE(sameBytes(a.shadow, b.shadow)) << "shadow of frame " << i;
        EXPECT_TRUE(sameBytes(a.depthBuffer, b.depthBuffer)) << "depth of frame " << i;
    }
}

// The frame waits for the game's timeline semaphore on the GPU: submit returns
// at once, and the frame finishes only once the game signals.
TEST_F(FramesInFlight, WaitsForTheGamesSemaphoreOnTheGpu) {
    Frames f(ctx(), "rooms.json");
    auto renderer = f.renderer(ctx(), true);
    VkSemaphoreTypeCreateInfo type{.sType = VK_STRUCTURE_TYPE_SEMAPHORE_TYPE_CREATE_INFO,
                                   .semaphoreType = VK_SEMAPHORE_TYPE_TIMELINE};
    const VkSemaphoreCreateInfo sci{.sType = VK_STRUCTURE_TYPE_SEMAPHORE_CREATE_INFO, .pNext = &type};
    VkSemaphore game = VK_NULL_HANDLE;
    VK_CHECK(vkCreateSemaphore(ctx().device, &sci, nullptr, &game));
    const FrameSync sync{.waits = {{.semaphore = game, .value = 1}}};
    const uint64_t first = renderer->submit(f.camera, 1, sync).timelineValue;
    const uint64_t second = renderer->submit(f.camera, 2).timelineValue;  // queued behind the first
    std::this_thread::sleep_for(std::chrono::milliseconds(100));
    EXPECT_LT(timelineNow(ctx(), *renderer), first) << "the frame ran before the game's semaphore was signalled";
    const VkSemaphoreSignalInfo signal{.sType = VK_STRUCTURE_TYPE_SEMAPHORE_SIGNAL_INFO, .semaphore = game, .value = 1};
    VK_CHECK(vkSignalSemaphore(ctx().device, &signal));
    waitTimeline(ctx(), renderer->timeline(), second);
    // The pass times of frame 1 come back with frame 3, which reuses its slot.
    const FrameStats third = renderer->submit(f.camera, 3);
    EXPECT_FALSE(third.passMs.empty());
    renderer->finishFrames();
    vkDestroySemaphore(ctx().device, game, nullptr);
}

// Occlusion culling without a wait in the middle of the frame: the clusters the
// first phase did not draw are tested against the tiles of a finished frame of
// the same view. For a static camera the images equal render()'s.
TEST_F(FramesInFlight, OcclusionCullingOneFrameLateDrawsEveryVisibleCluster) {
    Frames f(ctx(), "caves.json");
    auto blocking = f.renderer(ctx(), true), inFlight = f.renderer(ctx(), true);
    FrameCopy expected(ctx(), true), got(ctx(), true);
    FrameStats stats;
    constexpr uint32_t kFrames = 5;
    for (uint32_t i = 1; i <= kFrames; ++i) {
        blocking->render(f.camera, i, i == kFrames ? &expected : nullptr);
        stats = inFlight->submit(f.camera, i, {}, i == kFrames ? &got : nullptr);
    }
    inFlight->finishFrames();
    EXPECT_GT(stats.culling.clustersHidden, 0u) << "the old tiles hid nothing: the test would mean nothing";
    const FrameImages a = expected.decode(), b = got.decode();
    EXPECT_TRUE(sameBytes(a.depthBuffer, b.depthBuffer));
    EXPECT_EQ(a.surfaceIds, b.surfaceIds);
    EXPECT_TRUE(sameBytes(a.color, b.color));
}

// Ten frames in flight on a world with moving objects, an edit in the middle and
// a camera that moves, each frame's colour copied by "the game" on the same
// queue after the frame's timeline value, before the next submit.
TEST_F(FramesInFlight, SynchronisationValidationStaysSilent) {
    ASSERT_TRUE(ctx().validationEnabled());
    voxel::World world = voxel::World::load(test::worldsDir() / "yard.json");
    const AoOptions ao = aoOptionsFor(world.desc().ao, world.voxelSize(), "test");
    voxel::CameraDesc c = world.camera("", 1.0);
    RenderSession session(ctx(), std::move(world), ao, voxel::Detail{}, kSize, kSize, true);
    ASSERT_NE(session.objects(), nullptr);
    Renderer& renderer = session.renderer();
    vk::Buffer read = vk::createBuffer(ctx(), 16ull * kSize * kSize, VK_BUFFER_USAGE_TRANSFER_DST_BIT, true);
    VkCommandBuffer reads[2] = {vk::allocateCommandBuffer(ctx()), vk::allocateCommandBuffer(ctx())};
    uint64_t readsDone[2] = {0, 0};
    uint64_t last = 0;
    for (uint32_t i = 1; i <= 10; ++i) {
        session.setTime(0.2 * i);
        c.position.x += 0.1;
        if (i == 5) {
            const glm::dvec3 at = c.position + 0.5 * (c.target - c.position);
            const voxel::EditResult r = session.apply({.op = voxel::Edit::Op::Fill, .shape = voxel::Edit::Shape::Sphere,
                                                       .centre = at, .radius = 1.5, .material = 1});
            EXPECT_GT(r.changed, 0u);
        }
        // The game's command buffer is its own to reuse once its submission has finished.
        VkCommandBuffer cmd = reads[i % 2];
        waitTimeline(ctx(), renderer.timeline(), readsDone[i % 2]);
        last = renderer.submit(makeCamera(c, kSize, kSize), i).timelineValue;
        const VkCommandBufferBeginInfo bi{.sType = VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO,
                                          .flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT};
        VK_CHECK(vkResetCommandBuffer(cmd, 0));
        VK_CHECK(vkBeginCommandBuffer(cmd, &bi));
        const VkBufferImageCopy region{.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1},
                                       .imageExtent = {kSize, kSize, 1}};
        // The image stays in GENERAL for the renderer: the game lays it out for its
        // copy and back.
        const vk::Image& color = renderer.colorImage();
        vk::transition(cmd, color, VK_IMAGE_LAYOUT_GENERAL, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL,
                       VK_PIPELINE_STAGE_TRANSFER_BIT, 0, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_READ_BIT);
        vkCmdCopyImageToBuffer(cmd, color.image, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, read.buffer, 1, &region);
        vk::transition(cmd, color, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, VK_IMAGE_LAYOUT_GENERAL,
                       VK_PIPELINE_STAGE_TRANSFER_BIT, 0, VK_PIPELINE_STAGE_TRANSFER_BIT, 0);
        const VkMemoryBarrier toHost{.sType = VK_STRUCTURE_TYPE_MEMORY_BARRIER,
                                     .srcAccessMask = VK_ACCESS_TRANSFER_WRITE_BIT,
                                     .dstAccessMask = VK_ACCESS_HOST_READ_BIT};
        vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_PIPELINE_STAGE_HOST_BIT, 0, 1, &toHost, 0,
                             nullptr, 0, nullptr);
        VK_CHECK(vkEndCommandBuffer(cmd));
        const VkSemaphore timeline = renderer.timeline();
        const VkPipelineStageFlags stage = VK_PIPELINE_STAGE_TRANSFER_BIT;
        const VkTimelineSemaphoreSubmitInfo values{.sType = VK_STRUCTURE_TYPE_TIMELINE_SEMAPHORE_SUBMIT_INFO,
                                                   .waitSemaphoreValueCount = 1, .pWaitSemaphoreValues = &last};
        const VkSubmitInfo si{.sType = VK_STRUCTURE_TYPE_SUBMIT_INFO, .pNext = &values, .waitSemaphoreCount = 1,
                              .pWaitSemaphores = &timeline, .pWaitDstStageMask = &stage,
                              .commandBufferCount = 1, .pCommandBuffers = &cmd};
        VK_CHECK(vkQueueSubmit(ctx().queue, 1, &si, VK_NULL_HANDLE));
        // Queue order: the read ends before the next frame's first command, which
        // the renderer's next timeline value therefore follows.
        readsDone[i % 2] = last + 1;
    }
    VK_CHECK(vkQueueWaitIdle(ctx().queue));
    const float* pixels = static_cast<const float*>(read.mapped());
    float sum = 0.0f;
    for (uint32_t p = 0; p < kSize * kSize; ++p) sum += pixels[4 * p];
    EXPECT_GT(sum, 0.0f) << "the game read a black frame";
    vkFreeCommandBuffers(ctx().device, ctx().commandPool, 2, reads);
    vk::destroy(ctx(), read);
}

}  // namespace
}  // namespace grotto
