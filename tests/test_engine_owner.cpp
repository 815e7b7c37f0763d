// One owner for each piece of state: the session holds the frames' settings only
// until its renderer is made, then reads the renderer's; the GPU scene's occupancy
// and face cache are replaced by their one writer each (engine/scene/scene.h).
#include "engine/scene/scene.h"
#include "engine/session.h"
#include "tests/gpu_fixture.h"
#include "tests/scenes.h"

#include <gtest/gtest.h>

namespace grotto {
namespace {

// Could any holder of the scene replace the part? Its readers get const pointers only.
template <class Scene>
constexpr bool occupancyReplaceable = requires(Scene& s) { s.occupancy = nullptr; };
template <class Scene>
constexpr bool faceCacheReplaceable = requires(Scene& s) { s.faceCache = nullptr; };

TEST(SceneOwners, TheOccupancyAndTheFaceCacheAreNotReplacedByTheirReaders) {
    EXPECT_FALSE(occupancyReplaceable<GpuScene>);
    EXPECT_FALSE(faceCacheReplaceable<GpuScene>);
}

class SessionOwner : public test::GpuTest {};

TEST_F(SessionOwner, ReadsTheRenderersSettingsOnceItIsMade) {
    voxel::World world = test::floorWorld();
    const AoOptions gtao = aoOptionsFor({.method = "gtao"}, world.voxelSize(), "test");
    RenderSession session(ctx(), std::move(world), gtao, voxel::Detail{}, 16, 16);
    voxel::Lighting low = session.lighting();
    low.sunDirection = glm::normalize(glm::vec3(1.0f, 0.5f, 0.0f));
    session.setLighting(low);  // no renderer yet: the session holds it
    Renderer& renderer = session.renderer();
    EXPECT_EQ(session.lighting().sunDirection.x, low.sunDirection.x) << "handed over when the renderer is made";

    // Changed on the renderer itself, as a game may: the session has no copy of its own to go stale.
    voxel::Lighting high = low;
    high.sunDirection = glm::normalize(glm::vec3(0.0f, 1.0f, 1.0f));
    renderer.setLighting(high);
    EXPECT_EQ(session.lighting().sunDirection.x, high.sunDirection.x);
    EXPECT_EQ(session.lighting().sunDirection.z, high.sunDirection.z);
    renderer.setAo(aoOptionsFor({.method = "off"}, session.world().voxelSize(), "test"));
    EXPECT_FALSE(session.ao().enabled);

    // And through the session: the renderer's, read back.
    session.setAo(gtao);
    EXPECT_TRUE(renderer.ao().enabled);
    EXPECT_TRUE(session.ao().enabled);
}

}  // namespace
}  // namespace grotto
