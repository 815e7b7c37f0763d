// The settings table's promise: every lighting, AO and detail setting is accepted
// at both ends of its range and refused just outside, alike in a world file, on
// the command line and in a viewer script, each refusal an input error naming the
// setting (its key, or its flag). And the viewer keeps the command line's AO
// settings when the panel or a script changes another.
#include "app/options.h"
#include "app/viewer/settings_patch.h"
#include "app/viewer/view_script.h"
#include "tests/input_error_checks.h"
#include "tests/test_util.h"
#include "voxel/settings_table.h"
#include "voxel/world.h"

#include <CLI/CLI.hpp>
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <set>

namespace grotto {
namespace {

namespace fs = std::filesystem;
using voxel::Setting;
using voxel::SettingType;
using Json = nlohmann::ordered_json;

// A step beyond a bound, large enough to survive the float the shaders hold.
double beyond(double bound, double direction) {
    return bound + direction * (bound != 0.0 ? std::abs(bound) * 1e-3 : 1e-3);
}

// Values each setting must accept and refuse, as a world file writes them.
struct Probe {
    std::vector<Json> good, bad;
};

Probe probe(const Setting& s) {
    const double lo = s.lo, hi = s.hi;
    switch (s.type) {
    case SettingType::Number: return {{lo, hi}, {beyond(lo, -1), beyond(hi, 1)}};
    case SettingType::Whole: return {{int64_t(lo), int64_t(hi)}, {int64_t(lo) - 1, int64_t(hi) + 1}};
    case SettingType::Bool: return {{true, false}, {"maybe"}};
    case SettingType::Choice: {
        Probe p{{}, {"nonsense"}};
        for (std::string_view c : s.choices) p.good.push_back(std::string(c));
        return p;
    }
    case SettingType::Color:
        return {{Json::array({lo, lo, lo}), Json::array({hi, hi, hi})},
                {Json::array({beyond(lo, -1), lo, lo}), Json::array({hi, hi, beyond(hi, 1)})}};
    case SettingType::Direction:
        return {{Json::array({lo, 0, 0}), Json::array({0, 0, hi})},
                {Json::array({beyond(lo, -1), 0, 0}), Json::array({0, 0, beyond(hi, 1)}), Json::array({0, 0, 0})}};
    }
    return {};
}

std::string text(const Json& value) {
    if (value.is_string()) return value.get<std::string>();
    if (value.is_number_float()) {
        char t[40];
        std::snprintf(t, sizeof t, "%.17g", value.get<double>());
        return t;
    }
    return value.dump();
}

class SettingsTable : public ::testing::Test {
protected:
    fs::path write(const std::string& name, const std::string& content) {
        const fs::path file = dir_ / name;
        std::ofstream(file) << content;
        return file;
    }

    // A world file setting `s` to `value`, loaded, its AO resolved as every command does.
    void loadWorld(const Setting& s, const Json& value) {
        Json doc = {{"grid", {{"file", "none.vdb"}}}};
        doc.merge_patch(voxel::settingPatch(std::string(s.key), value));
        const fs::path file = write("world.json", doc.dump());
        const voxel::WorldDesc desc = voxel::loadWorldDesc(file);
        aoOptionsFor(desc.ao, 1.0, file.string());
    }

    // A flag that takes no value (--ao-full-res) has none to get wrong.
    static bool bareFlag(const Setting& s) {
        CLI::App cmd;
        app::AoFlags flags;
        app::addAoFlags(&cmd, flags);
        return cmd.get_option(std::string(s.flag))->get_expected_min() == 0;
    }

    // `grotto render` given the setting's flag (and `value`, unless it is a bare flag).
    void runFlag(const Setting& s, const Json& value) {
        CLI::App cmd;
        app::AoFlags flags;
        app::addAoFlags(&cmd, flags);
        std::vector<std::string> args = {std::string(s.flag)};
        if (!bareFlag(s)) args.push_back(text(value));
        std::reverse(args.begin(), args.end());  // CLI11 takes them last first
        try {
            cmd.parse(args);
        } catch (const CLI::ParseError& e) {  // exit code 2, the message naming the flag
            throw Error(s.flag.data(), e.what());
        }
        app::resolveAo(world_, flags);
        app::resolveDetail(world_, flags);
    }

    // A viewer script setting the key, applied as the viewer applies it.
    void runScript(const Setting& s, const Json& value) {
        const Json script = {{"actions", Json::array({{{"frame", 0}, {"set", {{std::string(s.key), value}}}}})}};
        const fs::path file = write("script.json", script.dump());
        const viewer::ViewScript loaded = viewer::ViewScript::load(file);
        for (const viewer::ScriptAction& a : loaded.actions())
            for (const auto& [key, v] : a.settings) {
                voxel::WorldDesc desc = world_.desc();
                viewer::applyViewerPatch(desc, voxel::settingPatch(key, v), world_.voxelSize(), file, "frame 0 set");
            }
    }

    test::ScratchDir dir_;
    const uint8_t floor_[4] = {1, 1, 1, 1};
    voxel::World world_ = voxel::World::fromDense({2, 1, 2}, floor_, 1.0, glm::dvec3(0.0));
};

TEST_F(SettingsTable, EveryRangeHoldsInAWorldFileOnTheCommandLineAndInAScript) {
    size_t checked = 0;
    for (const Setting& s : voxel::settingsTable()) {
        const Probe p = probe(s);
        const std::string key(s.key), flag(s.flag);
        for (const Json& v : p.good) {
            EXPECT_NO_THROW(loadWorld(s, v)) << key << " = " << v.dump();
            EXPECT_NO_THROW(runScript(s, v)) << key << " = " << v.dump();
            if (!flag.empty()) EXPECT_NO_THROW(runFlag(s, v)) << flag << " " << text(v);
        }
        for (const Json& v : p.bad) {
            SCOPED_TRACE(key + " = " + v.dump());
            test::inputErrorOf([&] { loadWorld(s, v); }, {key});
            test::inputErrorOf([&] { runScript(s, v); }, {key});
            if (!flag.empty() && !bareFlag(s)) test::inputErrorOf([&] { runFlag(s, v); }, {flag});
            ++checked;
        }
    }
    EXPECT_GE(checked, voxel::settingsTable().size()) << "every setting has values to refuse";
}

// One row per setting: keys, flags and manifest keys are each named once; the
// defaults lie within the ranges, and so do the panel's sliders.
TEST_F(SettingsTable, RowsAreUniqueAndTheirDefaultsAndSlidersInRange) {
    std::set<std::string_view> keys, flags, manifest;
    for (const Setting& s : voxel::settingsTable()) {
        EXPECT_TRUE(keys.insert(s.key).second) << s.key;
        if (!s.flag.empty()) EXPECT_TRUE(flags.insert(s.flag).second) << s.flag;
        if (!s.manifest.empty()) EXPECT_TRUE(manifest.insert(s.manifest).second) << s.manifest;
        EXPECT_EQ(voxel::findSetting(s.key), &s);
        if (s.type != SettingType::Number && s.type != SettingType::Whole) continue;
        const double v = voxel::settingNumber(s, voxel::WorldDesc{}, {}, {});
        EXPECT_TRUE(v >= s.lo && v <= s.hi) << s.key << " default " << v;
        const auto [lo, hi] = voxel::uiRange(s);
        if (!s.uiRelative) EXPECT_TRUE(lo >= s.lo && hi <= s.hi && lo < hi) << s.key;
    }
    EXPECT_EQ(voxel::findSetting("ao.temporal"), nullptr);
}

// The command line's AO settings stay in what the viewer shows and saves when
// the panel or a script changes another setting (they were dropped).
TEST_F(SettingsTable, ViewerKeepsTheCommandLinesAoSettingsAcrossAPatch) {
    CLI::App cmd;
    app::AoFlags flags;
    app::addAoFlags(&cmd, flags);
    cmd.parse(std::vector<std::string>{"--ao-full-res", "3", "--temporal", "0.45", "--thin-occluder"});
    voxel::WorldDesc desc = world_.desc();
    desc.ao = app::aoDescWithFlags(desc.ao, flags);
    const AoOptions before = app::resolveAo(world_, flags);
    const AoOptions after = viewer::applyViewerPatch(desc, voxel::settingPatch("lighting.exposure", 0.8),
                                                     world_.voxelSize(), "panel", "panel");
    EXPECT_FLOAT_EQ(after.estimator.thinOccluder, 0.45f);
    EXPECT_EQ(after.chain.temporalHistory, 3u);
    EXPECT_TRUE(after.chain.fullResolution);
    EXPECT_EQ(app::aoSettingsJson(after), app::aoSettingsJson(before));
    EXPECT_FLOAT_EQ(desc.lighting.exposure, 0.8f);
}

}  // namespace
}  // namespace grotto

namespace grotto {
namespace {

// A manifest records what decides the pixels and nothing else: VBAO's thickness
// for VBAO only, the tracing methods' rays for them only.
TEST(SettingsManifest, RecordsEachMethodsOwnSettingsOnly) {
    AoOptions gtao;
    using app::aoSettingsJson;
    const nlohmann::json g = aoSettingsJson(gtao);
    EXPECT_FALSE(g.contains("thickness"));
    EXPECT_FALSE(g.contains("thickness_value"));
    EXPECT_FALSE(g.contains("rays"));
    AoOptions vbao;
    vbao.method = AoMethod::Vbao;
    const nlohmann::json v = aoSettingsJson(vbao);
    EXPECT_EQ(v.value("thickness", ""), "voxels");
    EXPECT_TRUE(v.contains("thickness_value"));
    EXPECT_FALSE(v.contains("rays"));
    AoOptions voxel;
    voxel.method = AoMethod::Voxel;
    EXPECT_TRUE(aoSettingsJson(voxel).contains("rays"));
    EXPECT_FALSE(aoSettingsJson(voxel).contains("thickness"));
}

}  // namespace
}  // namespace grotto
