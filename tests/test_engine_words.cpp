// Engine errors speak the engine's words: a game embedding the engine never typed
// a command-line flag, so none is named (the command line adds its own).
#include "engine/ao_settings.h"
#include "engine/renderer.h"
#include "engine/scene/live_scene.h"
#include "tests/gpu_fixture.h"
#include "tests/scenes.h"
#include "tests/test_util.h"

#include <grotto/grotto.h>

#include <gtest/gtest.h>

#include <string>

namespace grotto {
namespace {

// The message of the Error `f` throws ("" and a failure when it throws none).
template <class F>
std::string engineErrorOf(F&& f) {
    try {
        f();
    } catch (const Error& e) {
        return e.what();
    }
    ADD_FAILURE() << "no error";
    return "";
}

TEST(EngineWords, AnUnknownQualityIsNamedAsASetting) {
    Engine engine({.width = 16, .height = 16, .validation = true});
    engine.loadWorld(test::worldsDir() / "rooms.json");
    const std::string message = engineErrorOf([&] { engine.setAo({.quality = "extreme"}); });
    EXPECT_NE(message.find("extreme"), std::string::npos) << message;
    EXPECT_EQ(message.find("--"), std::string::npos) << "names a flag: " << message;
}

TEST(EngineWords, ASettingOutOfRangeIsNamedAsASettingWhereverItCameFrom) {
    AoOptions ao = aoOptionsFor({}, 1.0, "test");
    ao.estimator.radius = -1.0f;
    // The command line's own name for itself once made the engine name its flag.
    const std::string message = engineErrorOf([&] { validateAo(ao, "command line"); });
    EXPECT_NE(message.find("AO setting 'radius'"), std::string::npos) << message;
    EXPECT_EQ(message.find("--"), std::string::npos) << "names a flag: " << message;
}

class EngineWordsGpu : public test::GpuTest {};

TEST_F(EngineWordsGpu, TheFaceCacheMissingIsNamedWithoutFlags) {
    const voxel::World floor = test::floorWorld();
    LiveScene scene(ctx(), voxel::World(floor));  // no face cache loaded or baked
    AoOptions ao = aoOptionsFor({.method = "cache"}, floor.voxelSize(), "test");
    const std::string message = engineErrorOf([&] { Renderer(ctx(), scene.gpu(), floor.desc().lighting, ao, 16, 16); });
    EXPECT_NE(message.find("face cache"), std::string::npos) << message;
    EXPECT_EQ(message.find("--"), std::string::npos) << "names a flag: " << message;
}

}  // namespace
}  // namespace grotto
