// `grotto view --script` files: every verb read, actions sorted by frame in file
// order, output paths beside the script, and each kind of bad input refused in
// one line naming the file and the field.
#include "app/viewer/view_script.h"
#include "grotto/error.h"
#include "tests/input_error_checks.h"
#include "tests/test_util.h"

#include <gtest/gtest.h>

#include <fstream>

namespace grotto::viewer {
namespace {

namespace fs = std::filesystem;
using Kind = ScriptAction::Kind;

class ViewScriptFiles : public ::testing::Test {
protected:
    fs::path write(const std::string& name, const std::string& text) {
        const fs::path file = dir_ / name;
        fs::create_directories(file.parent_path());
        std::ofstream(file) << text;
        return file;
    }
    // A script of these actions (a JSON array's contents).
    fs::path script(const std::string& name, const std::string& actions) {
        return write(name, "{\"actions\": [" + actions + "]}");
    }
    // Loading `file` throws an input error, in one line, starting with the file's
    // name and naming each of `mentions`.
    std::string expectError(const fs::path& file, const std::vector<std::string>& mentions) {
        const std::string what = test::inputErrorOf([&] { ViewScript::load(file); }, mentions);
        EXPECT_EQ(what.rfind(file.string() + ": ", 0), 0u) << what;
        return what;
    }
    test::ScratchDir dir_;
};

TEST_F(ViewScriptFiles, ReadsEveryVerb) {
    const fs::path file = script("every.json", R"(
        {"frame": 0, "key": "W", "down": true},
        {"frame": 1, "key": "SHIFT", "down": false},
        {"frame": 2, "key": "F12"},
        {"frame": 3, "key": "TAB", "down": true},
        {"frame": 4, "look": [12.5, -3]},
        {"frame": 5, "wheel": -1.5},
        {"frame": 6, "set": {"view": "ao", "ao.method": "voxel", "ao.temporal": 8, "lighting.exposure": 0.8, "x": [1, {"b": 2, "a": 1}]}},
        {"frame": 7, "resize": [640, 360]},
        {"frame": 8, "minimize": true},
        {"frame": 9, "restore": true},
        {"frame": 10, "camera": "table"},
        {"frame": 11, "record": true},
        {"frame": 12, "save_path": "out/path.json"},
        {"frame": 13, "click": [320, 180.5], "button": "right"},
        {"frame": 14, "click": [0, 0]},
        {"frame": 15, "screenshot": "shot.png"},
        {"frame": 16, "undo": true},
        {"frame": 17, "save_world": "edited.vdb"})");
    const ViewScript s = ViewScript::load(file);
    const std::vector<ScriptAction>& a = s.actions();
    ASSERT_EQ(a.size(), 18u);
    for (uint32_t i = 0; i < a.size(); ++i) EXPECT_EQ(a[i].frame, i);
    EXPECT_EQ(s.lastFrame(), 17u);
    EXPECT_EQ(s.file(), file);

    EXPECT_EQ(a[0].kind, Kind::Key);
    EXPECT_EQ(a[0].key, ScriptKey::W);
    EXPECT_TRUE(a[0].down);
    EXPECT_EQ(a[1].key, ScriptKey::Shift);
    EXPECT_FALSE(a[1].down);
    EXPECT_EQ(a[2].key, ScriptKey::F12);
    EXPECT_TRUE(a[2].down) << "a hotkey is pressed";
    EXPECT_EQ(a[3].key, ScriptKey::Tab);
    EXPECT_EQ(a[4].kind, Kind::Look);
    EXPECT_EQ(a[4].vec, glm::dvec2(12.5, -3));
    EXPECT_EQ(a[5].kind, Kind::Wheel);
    EXPECT_EQ(a[5].wheel, -1.5);

    EXPECT_EQ(a[6].kind, Kind::Set);
    ASSERT_EQ(a[6].settings.size(), 5u);
    const char* names[] = {"view", "ao.method", "ao.temporal", "lighting.exposure", "x"};  // file order
    for (size_t i = 0; i < 5; ++i) EXPECT_EQ(a[6].settings[i].first, names[i]);
    EXPECT_EQ(a[6].settings[0].second, "ao");
    EXPECT_EQ(a[6].settings[1].second, "voxel");
    EXPECT_EQ(a[6].settings[2].second, 8);
    EXPECT_TRUE(a[6].settings[2].second.is_number_integer());
    EXPECT_EQ(a[6].settings[3].second, 0.8);
    EXPECT_EQ(a[6].settings[4].second, nlohmann::json::parse(R"([1, {"a": 1, "b": 2}])"));

    EXPECT_EQ(a[7].kind, Kind::Resize);
    EXPECT_EQ(a[7].vec, glm::dvec2(640, 360));
    EXPECT_EQ(a[8].kind, Kind::Minimize);
    EXPECT_EQ(a[9].kind, Kind::Restore);
    EXPECT_EQ(a[10].kind, Kind::Camera);
    EXPECT_EQ(a[10].camera, "table");
    EXPECT_EQ(a[11].kind, Kind::Record);
    EXPECT_EQ(a[12].kind, Kind::SavePath);
    EXPECT_EQ(a[12].path, dir_.path / "out/path.json");
    EXPECT_EQ(a[13].kind, Kind::Click);
    EXPECT_EQ(a[13].vec, glm::dvec2(320, 180.5));
    EXPECT_EQ(a[13].button, MouseButton::Right);
    EXPECT_EQ(a[14].button, MouseButton::Left) << "left unless the script says";
    EXPECT_EQ(a[15].kind, Kind::Screenshot);
    EXPECT_EQ(a[15].path, dir_.path / "shot.png");
    EXPECT_EQ(a[16].kind, Kind::Undo);
    EXPECT_EQ(a[17].kind, Kind::SaveWorld);
    EXPECT_EQ(a[17].path, dir_.path / "edited.vdb");

    // Names back as scripts write them.
    for (const ScriptAction& x : a) EXPECT_NE(std::string(verbName(x.kind)), "?");
    EXPECT_STREQ(verbName(Kind::SavePath), "save_path");
    EXPECT_STREQ(scriptKeyName(ScriptKey::Shift), "SHIFT");
    EXPECT_TRUE(isHeld(ScriptKey::Q));
    EXPECT_FALSE(isHeld(ScriptKey::R));
}

TEST_F(ViewScriptFiles, SortsByFrameKeepingFileOrderWithinAFrame) {
    const ViewScript s = ViewScript::load(script("order.json", R"(
        {"frame": 30, "key": "W", "down": false},
        {"frame": 5, "look": [1, 0]},
        {"frame": 30, "screenshot": "a.png"},
        {"frame": 0, "key": "W", "down": true},
        {"frame": 5, "wheel": 1},
        {"frame": 30, "camera": "b"},
        {"frame": 5, "look": [2, 0]})"));
    const std::vector<ScriptAction>& a = s.actions();
    ASSERT_EQ(a.size(), 7u);
    const uint32_t frames[] = {0, 5, 5, 5, 30, 30, 30};
    for (size_t i = 0; i < a.size(); ++i) EXPECT_EQ(a[i].frame, frames[i]) << i;
    EXPECT_EQ(s.lastFrame(), 30u);

    const std::span<const ScriptAction> five = s.at(5);
    ASSERT_EQ(five.size(), 3u);
    EXPECT_EQ(five[0].vec.x, 1.0);
    EXPECT_EQ(five[1].kind, Kind::Wheel);
    EXPECT_EQ(five[2].vec.x, 2.0);
    const std::span<const ScriptAction> thirty = s.at(30);
    ASSERT_EQ(thirty.size(), 3u);
    EXPECT_EQ(thirty[0].kind, Kind::Key);
    EXPECT_EQ(thirty[1].kind, Kind::Screenshot);
    EXPECT_EQ(thirty[2].kind, Kind::Camera);
    EXPECT_EQ(s.at(0).size(), 1u);
    EXPECT_TRUE(s.at(1).empty());
    EXPECT_TRUE(s.at(31).empty());
}

TEST_F(ViewScriptFiles, OutputPathsAreRelativeToTheScript) {
    const fs::path absolute = dir_.path / "elsewhere" / "shot.exr";
    const fs::path file = script("runs/ci/script.json", R"({"frame": 0, "save_path": "out/path.json"},
        {"frame": 1, "screenshot": "../shot.png"}, {"frame": 2, "screenshot": ")" + absolute.string() + R"("})");
    const ViewScript s = ViewScript::load(file);
    EXPECT_EQ(s.actions()[0].path, dir_.path / "runs/ci/out/path.json");
    EXPECT_EQ(s.actions()[1].path, dir_.path / "runs/ci/../shot.png");
    EXPECT_EQ(s.actions()[2].path, absolute);
}

TEST_F(ViewScriptFiles, RefusesBadInputNamingFileAndField) {
    // The whole line, as world and path files word it.
    const fs::path p = script("key.json", R"({"frame": 0, "key": "W", "down": true}, {"frame": 1, "key": "P", "down": true})");
    EXPECT_EQ(expectError(p, {}), p.string() + ": field 'actions[1].key': unknown key 'P' (accepted: W, A, S, D, Q, E, SHIFT, F12, R, TAB)");

    // The file itself.
    expectError(dir_ / "absent.json", {"absent.json", "no such file"});
    expectError(write("malformed.json", R"({"actions": [{"frame": 0, )"), {"malformed.json", "malformed JSON"});
    expectError(write("overflow.json", R"({"actions": [{"frame": 0, "look": [1e999, 0]}]})"), {"overflow.json", "1e999"});
    expectError(write("missing.json", R"({})"), {"missing.json", "field 'actions': missing"});
    expectError(write("notarray.json", R"({"actions": {"frame": 0}})"), {"notarray.json", "field 'actions'", "non-empty array"});
    expectError(write("empty.json", R"({"actions": []})"), {"empty.json", "field 'actions'", "non-empty array"});
    expectError(write("toplevel.json", R"({"actions": [{"frame": 0, "record": true}], "fps": 60})"),
                {"toplevel.json", "field 'fps': unknown field", "known fields: actions"});
    expectError(script("notobject.json", R"({"frame": 0, "record": true}, 7)"), {"notobject.json", "field 'actions[1]': expected an object"});

    // Frames: present, whole, from 0.
    expectError(script("noframe.json", R"({"record": true})"), {"noframe.json", "field 'actions[0].frame': missing"});
    expectError(script("negframe.json", R"({"frame": -1, "record": true})"), {"negframe.json", "actions[0].frame", "out of range"});
    expectError(script("fracframe.json", R"({"frame": 2.5, "record": true})"), {"fracframe.json", "actions[0].frame", "whole number"});
    expectError(script("strframe.json", R"({"frame": "3", "record": true})"), {"strframe.json", "actions[0].frame", "finite number"});
    expectError(script("farframe.json", R"({"frame": 1e7, "record": true})"), {"farframe.json", "actions[0].frame", "out of range"});

    // One verb per action, and only the fields it takes.
    expectError(script("noverb.json", R"({"frame": 0})"), {"noverb.json", "field 'actions[0]': no action", "key, look"});
    expectError(script("noverbdown.json", R"({"frame": 0, "down": true})"), {"noverbdown.json", "field 'actions[0]': no action"});
    expectError(script("twoverbs.json", R"({"frame": 0, "look": [1, 1], "wheel": 1})"),
                {"twoverbs.json", "field 'actions[0].wheel': given with 'look'"});
    expectError(script("unknown.json", R"({"frame": 0, "jump": true})"), {"unknown.json", "field 'actions[0].jump': unknown field", "screenshot"});
    expectError(script("unknown2.json", R"({"frame": 0, "record": true, "note": "x"})"), {"unknown2.json", "field 'actions[0].note': unknown field"});
    expectError(script("downlook.json", R"({"frame": 0, "look": [1, 1], "down": true})"),
                {"downlook.json", "field 'actions[0].down': given with 'look'"});
    expectError(script("buttonkey.json", R"({"frame": 0, "key": "W", "down": true, "button": "left"})"),
                {"buttonkey.json", "field 'actions[0].button': given with 'key'"});

    // Keys.
    expectError(script("lower.json", R"({"frame": 0, "key": "w", "down": true})"), {"lower.json", "actions[0].key", "unknown key 'w'"});
    expectError(script("keytype.json", R"({"frame": 0, "key": 87, "down": true})"), {"keytype.json", "actions[0].key", "expected a string"});
    expectError(script("nodown.json", R"({"frame": 0, "key": "A"})"), {"nodown.json", "field 'actions[0].down': missing"});
    expectError(script("downtype.json", R"({"frame": 0, "key": "A", "down": 1})"), {"downtype.json", "actions[0].down", "true or false"});
    expectError(script("hotup.json", R"({"frame": 0, "key": "F12", "down": false})"), {"hotup.json", "actions[0].down", "hotkey"});

    // Look and wheel: finite numbers in range.
    expectError(script("look3.json", R"({"frame": 0, "look": [1, 2, 3]})"), {"look3.json", "actions[0].look", "array of 2 numbers"});
    expectError(script("lookstr.json", R"({"frame": 0, "look": ["1", 2]})"), {"lookstr.json", "actions[0].look", "look[0] (x) is not a finite number"});
    expectError(script("lookfar.json", R"({"frame": 0, "look": [0, 1e300]})"), {"lookfar.json", "actions[0].look", "out of range"});
    expectError(script("wheelfar.json", R"({"frame": 0, "wheel": 1e9})"), {"wheelfar.json", "actions[0].wheel", "out of range"});
    expectError(script("wheelnull.json", R"({"frame": 0, "wheel": null})"), {"wheelnull.json", "actions[0].wheel", "finite number"});

    // Window sizes as `render --size` takes them; clicks inside that.
    expectError(script("resize0.json", R"({"frame": 0, "resize": [0, 360]})"), {"resize0.json", "actions[0].resize", "1 to 16384"});
    expectError(script("resizebig.json", R"({"frame": 0, "resize": [640, 16385]})"), {"resizebig.json", "actions[0].resize", "resize[1] (height) = 16385 is out of range", "1 to 16384"});
    expectError(script("resizefrac.json", R"({"frame": 0, "resize": [640.5, 360]})"), {"resizefrac.json", "actions[0].resize", "whole numbers"});
    expectError(script("resize1.json", R"({"frame": 0, "resize": 640})"), {"resize1.json", "actions[0].resize", "array of 2"});
    expectError(script("clickneg.json", R"({"frame": 0, "click": [-1, 5]})"), {"clickneg.json", "actions[0].click", "out of range"});
    expectError(script("button.json", R"({"frame": 0, "click": [1, 5], "button": "back"})"),
                {"button.json", "field 'actions[0].button': unknown button 'back'", "left, right, middle"});

    // The rest of the verbs.
    expectError(script("setarray.json", R"({"frame": 0, "set": ["ao.method", "voxel"]})"), {"setarray.json", "actions[0].set", "object"});
    expectError(script("setempty.json", R"({"frame": 0, "set": {}})"), {"setempty.json", "actions[0].set", "no settings"});
    expectError(script("minfalse.json", R"({"frame": 0, "minimize": false})"), {"minfalse.json", "actions[0].minimize", "expected true"});
    expectError(script("recordnum.json", R"({"frame": 0, "record": 1})"), {"recordnum.json", "actions[0].record", "true or false"});
    expectError(script("camempty.json", R"({"frame": 0, "camera": ""})"), {"camempty.json", "actions[0].camera", "camera name"});
    expectError(script("shotempty.json", R"({"frame": 0, "screenshot": ""})"), {"shotempty.json", "actions[0].screenshot", "file name"});
    expectError(script("savenum.json", R"({"frame": 0, "save_path": 3})"), {"savenum.json", "actions[0].save_path", "expected a string"});
}

}  // namespace
}  // namespace grotto::viewer
