// A frame's images copied by its own command buffer (Renderer::render with a
// FrameCopy) and decoded afterwards must be exactly what a synchronous readback
// of the same frame returns, for every AOV: the flythrough's double-buffered
// read-back writes the same files as before.
#include "engine/frame/frame_copy.h"
#include "engine/renderer.h"
#include "tests/gpu_fixture.h"
#include "tests/scenes.h"
#include "tests/test_util.h"
#include "voxel/object_worlds.h"
#include "voxel/world.h"

#include <algorithm>
#include <cstring>

namespace grotto {
namespace {

using test::GpuTest;

// Bit for bit (NaN and -0 included), field by field.
void expectSame(const FrameImages& a, const FrameImages& b, const std::string& what) {
    EXPECT_EQ(a.width, b.width);
    EXPECT_EQ(a.height, b.height);
    auto same = [&](const auto& x, const auto& y, const char* field) {
        ASSERT_EQ(x.size(), y.size()) << what << ": " << field;
        EXPECT_TRUE(x.empty() || std::memcmp(x.data(), y.data(), x.size() * sizeof(x[0])) == 0) << what << ": " << field;
    };
    same(a.color, b.color, "color");
    same(a.depth, b.depth, "depth");
    same(a.normal, b.normal, "normal");
    same(a.albedo, b.albedo, "albedo");
    same(a.ao, b.ao, "ao");
    same(a.aoRaw, b.aoRaw, "aoRaw");
    same(a.aoSpatial, b.aoSpatial, "aoSpatial");
    same(a.aoTemporal, b.aoTemporal, "aoTemporal");
    same(a.aoHistory, b.aoHistory, "aoHistory");
    same(a.edges, b.edges, "edges");
    same(a.depthBuffer, b.depthBuffer, "depthBuffer");
    same(a.surfaceIds, b.surfaceIds, "surfaceIds");
    same(a.aoRawHalf, b.aoRawHalf, "aoRawHalf");
    same(a.motion, b.motion, "motion");
    same(a.shadow, b.shadow, "shadow");
}

// Frames of `worldFile` from a camera stepping sideways, each copied into one of
// two FrameCopy slots in turn, against readback after the same frame. Returns the last.
FrameImages compareFrames(vk::Context& ctx, const std::string& worldFile, bool aovs, bool shadows) {
    const voxel::World world = voxel::World::load(test::worldsDir() / worldFile);
    auto scene = uploadScene(ctx, world);
    const std::vector<voxel::World> objectWorlds = voxel::loadObjectWorlds(world.desc());
    auto objects = objectWorlds.empty() ? nullptr : uploadObjects(ctx, objectWorlds, world.desc());
    voxel::Lighting lighting = world.desc().lighting;
    lighting.sunShadows = shadows;
    const AoOptions ao = aoOptionsFor(world.desc().ao, world.voxelSize(), "test");
    Renderer renderer(ctx, *scene, lighting, ao, 96, 54, objects.get());
    FrameCopy slots[2] = {FrameCopy(ctx, aovs), FrameCopy(ctx, aovs)};
    voxel::CameraDesc c = world.camera("", 96.0 / 54.0);
    FrameImages last;
    for (uint32_t i = 1; i <= 4; ++i) {
        c.position.x += 0.25;
        const Camera camera = makeCamera(c, 96, 54);
        if (objects) renderer.setObjectPoses(objects->poses(0.1 * i));
        FrameCopy& copy = slots[i % 2];
        renderer.render(camera, i, &copy);
        last = copy.decode();
        expectSame(last, renderer.readback(camera, aovs), worldFile + " frame " + std::to_string(i));
    }
    return last;
}

using FrameCopyTest = GpuTest;

TEST_F(FrameCopyTest, CopiedFrameDecodesToTheReadback) {
    const FrameImages f = compareFrames(ctx(), "rooms.json", true, true);
    EXPECT_NE(std::count(f.shadow.begin(), f.shadow.end(), 0.0f), 0) << "the sun shadows were copied";
    EXPECT_TRUE(compareFrames(ctx(), "rooms.json", false, false).depth.empty());
}

TEST_F(FrameCopyTest, CopiedFrameWithMovingObjectsDecodesToTheReadback) {
    EXPECT_FALSE(compareFrames(ctx(), "yard.json", true, false).motion.empty()) << "the motion vectors were copied";
}

}  // namespace
}  // namespace grotto
