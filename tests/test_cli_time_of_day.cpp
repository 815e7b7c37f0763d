// The time of day through the command line: a path's day track lights each
// frame as `render --time-of-day` lights that hour, the day brightens to noon
// and goes dark at midnight, the viewer's script sets the hour as render does,
// and a world's day out of range is refused by name.
#include "cli_fixture.h"
#include "tests/virtual_display.h"

#include <gtest/gtest.h>

#include <numeric>

namespace grotto::test {
namespace {

class CliTimeOfDay : public CliErrors {
protected:
    // The floor, a block on it (a shadow that turns with the sun), a camera and a
    // still path over it whose day runs from midnight to midnight in one second.
    // No AO: a flythrough's temporal AO and a still's converge differently, and
    // what is compared here is the light.
    fs::path writeDayWorld(const std::string& lighting = "") {
        writeSolid(dir_ / "block.vdb", 16, 4, [](int x, int y, int z) { return y == 0 || (x >= 6 && x < 10 && z >= 6 && z < 10); });
        const std::string pose = R"("position": [8, 14, 26], "target": [8, 0, 8])";
        return writeText("day.json", R"({"grid": {"file": "block.vdb"}, "ao": {"method": "off"},)" + lighting + R"(
            "cameras": {"c": {)" + pose + R"(}},
            "paths": {"p": {"interpolation": "linear", "keys": [{"time": 0, )" + pose + R"(}, {"time": 1, )" + pose + R"(}],
                "day": [{"time": 0, "hours": 0}, {"time": 1, "hours": 24}]}}})");
    }
    static double mean(const std::vector<uint8_t>& px) {
        return px.empty() ? -1.0 : std::accumulate(px.begin(), px.end(), 0.0) / double(px.size());
    }
};

TEST_F(CliTimeOfDay, APathsDayTrackLightsEachFrameAsThatHourRenders) {
    const fs::path world = writeDayWorld();
    const fs::path seq = dir_ / "seq";
    // 4 frames a second: path times 0, 0.25, 0.5, 0.75 are 0, 6, 12 and 18 hours.
    const RunResult fly = runGrotto("flythrough " + world.string() + " --path p --fps 4 --size 48x32 --frames 4 --quiet -o " + seq.string());
    ASSERT_EQ(fly.exitCode, 0) << fly.err;
    std::vector<double> means;
    for (const auto& [frame, hours] : {std::pair{"0001", "0"}, {"0002", "6"}, {"0003", "12"}, {"0004", "18"}}) {
        const std::vector<uint8_t> flown = readPixels8(seq / (std::string("frame.") + frame + ".png"));
        const fs::path still = dir_ / (std::string("at") + hours + ".png");
        const RunResult r = runGrotto("render " + world.string() + " --camera c --size 48x32 --time-of-day " + hours + " -o " + still.string());
        ASSERT_EQ(r.exitCode, 0) << r.err;
        EXPECT_LE(worstDifference(flown, readPixels8(still)), 1) << "frame " << frame << " against " << hours << " h";
        means.push_back(mean(flown));
    }
    const RunResult info = runGrotto("info " + world.string());
    EXPECT_NE(info.out.find("path           p: 2 keys over 1 s, 1 shot, a day from 0 to 24 h"), std::string::npos) << info.out;
    // Midnight is dark, noon the brightest; at the equinox 6 and 18 h are sunrise and sunset.
    EXPECT_LT(means[0], 0.1 * means[2]);
    EXPECT_LT(means[1], 0.8 * means[2]);
    EXPECT_LT(means[3], 0.8 * means[2]);
    EXPECT_GT(means[1], means[0]);
}

TEST_F(CliTimeOfDay, TheViewersHourIsTheHourRenderLights) {
    REQUIRE_XVFB();
    const fs::path world = writeDayWorld();
    const fs::path script = writeText("dusk.json", R"({"actions": [
        {"frame": 0, "set": {"lighting.sun.from": "day", "lighting.day.time": 17.25}}, {"frame": 3, "screenshot": "dusk.png"}]})");
    const RunResult v = runGrotto("view " + world.string() + " --size 48x32 --script " + script.string() + " --frames 4", kUnderXvfb);
    ASSERT_EQ(v.exitCode, 0) << v.err;
    const fs::path still = dir_ / "still.png";
    const RunResult r = runGrotto("render " + world.string() + " --camera c --size 48x32 --time-of-day 17.25 -o " + still.string());
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const std::vector<uint8_t> shown = readPixels8(dir_ / "dusk.png"), rendered = readPixels8(still);
    EXPECT_LE(worstDifference(shown, rendered), 1);
    // Not the world's own fixed sun: the hour changed the image.
    const fs::path noon = dir_ / "noon.png";
    ASSERT_EQ(runGrotto("render " + world.string() + " --camera c --size 48x32 -o " + noon.string()).exitCode, 0);
    EXPECT_GT(worstDifference(shown, readPixels8(noon)), 16);
}

TEST_F(CliTimeOfDay, AWorldsDayOutOfRangeIsRefusedByName) {
    for (const auto& [field, lighting] :
         {std::pair{"lighting.day.time", R"("lighting": {"sun": {"from": "day"}, "day": {"time": 25}},)"},
          {"lighting.day.latitude", R"("lighting": {"day": {"latitude": -91}},)"},
          {"lighting.day.day_of_year", R"("lighting": {"day": {"day_of_year": 0}},)"},
          {"lighting.sun.from", R"("lighting": {"sun": {"from": "moon"}},)"}}) {
        expectRefused(render(writeDayWorld(lighting)), field, out());
    }
    expectRefused(render(writeDayWorld()) + " --time-of-day -1", "--time-of-day", out());
}

}  // namespace
}  // namespace grotto::test
