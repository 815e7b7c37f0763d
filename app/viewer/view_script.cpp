#include "app/viewer/view_script.h"

#include "grotto/error.h"
#include "voxel/json_reader.h"

#include <glm/common.hpp>

#include <algorithm>
#include <cmath>
#include <initializer_list>
#include <optional>

namespace grotto::viewer {
namespace fs = std::filesystem;

namespace {

using voxel::json;
using voxel::Reader;
using Kind = ScriptAction::Kind;

template <class T>
using Names = std::initializer_list<std::pair<const char*, T>>;

constexpr Names<Kind> kVerbs = {
    {"key", Kind::Key},       {"look", Kind::Look},         {"wheel", Kind::Wheel},   {"set", Kind::Set},
    {"resize", Kind::Resize}, {"minimize", Kind::Minimize}, {"restore", Kind::Restore}, {"camera", Kind::Camera},
    {"record", Kind::Record}, {"save_path", Kind::SavePath}, {"click", Kind::Click},  {"screenshot", Kind::Screenshot},
    {"undo", Kind::Undo},     {"save_world", Kind::SaveWorld}};
constexpr Names<ScriptKey> kKeys = {{"W", ScriptKey::W},     {"A", ScriptKey::A},         {"S", ScriptKey::S},
                                    {"D", ScriptKey::D},     {"Q", ScriptKey::Q},         {"E", ScriptKey::E},
                                    {"SHIFT", ScriptKey::Shift}, {"F12", ScriptKey::F12}, {"R", ScriptKey::R},
                                    {"TAB", ScriptKey::Tab}};
constexpr Names<MouseButton> kButtons = {{"left", MouseButton::Left}, {"right", MouseButton::Right},
                                         {"middle", MouseButton::Middle}};

// Frames: as many as a camera path may have (app/options.h, kMaxPathFrames).
constexpr double kMaxFrame = 1'000'000;
// Window sizes: what `render --size` accepts (app/options.cpp, parseSize).
constexpr double kMaxWindowSide = 16384;
// Far beyond any real mouse or wheel, near enough that a typo is caught.
constexpr double kMaxLookPixels = 1e6, kMaxWheelNotches = 1e3;

template <class T>
std::string accepted(Names<T> names) {
    std::string s;
    for (const auto& [name, value] : names) s += (s.empty() ? "" : ", ") + std::string(name);
    return s;
}

template <class T>
const char* nameOf(Names<T> names, T value) {
    for (const auto& [name, v] : names)
        if (v == value) return name;
    return "?";
}

// The value a name in `key` stands for; anything else fails naming the field.
template <class T>
T lookup(Reader& r, const std::string& key, const std::string& what, Names<T> names, const std::string& fallback) {
    const std::string name = r.string(key, fallback);
    for (const auto& [n, value] : names)
        if (name == n) return value;
    r.fail(key, "unknown " + what + " '" + name + "'", "accepted: " + accepted(names));
}

// "minimize": true and the like: a verb with nothing to say but itself.
void requireTrue(Reader& r, const char* verb) {
    if (!r.boolean(verb, false)) r.fail(verb, "expected true", "leave the action out rather than set it false");
}

void readKey(Reader& r, ScriptAction& a) {
    a.key = lookup(r, "key", "key", kKeys, "");
    if (isHeld(a.key)) {
        if (!r.has("down")) r.fail("down", "missing", "true when the key goes down, false when it comes up");
        a.down = r.boolean("down", true);
    } else if (!r.boolean("down", true)) {
        r.fail("down", "false for a hotkey", "a hotkey is pressed: leave 'down' out");
    }
}

void readSettings(Reader& r, ScriptAction& a) {
    const json& set = r.at("set");
    const char* example = "name -> value, e.g. {\"ao.method\": \"voxel\"}";
    if (!set.is_object()) r.fail("set", "expected an object of settings", example);
    if (set.empty()) r.fail("set", "has no settings", example);
    for (const auto& [name, value] : set.items()) a.settings.emplace_back(name, nlohmann::json(value));
}

// A file to write: relative names are relative to the script, not the working directory.
fs::path outputPath(Reader& r, const char* verb) {
    const std::string name = r.string(verb, "");
    if (name.empty()) r.fail(verb, "expected a file name", "relative names are relative to the script's directory");
    return r.file().parent_path() / name;
}

struct FrameOrder {
    bool operator()(const ScriptAction& a, uint32_t frame) const { return a.frame < frame; }
    bool operator()(uint32_t frame, const ScriptAction& a) const { return frame < a.frame; }
    bool operator()(const ScriptAction& a, const ScriptAction& b) const { return a.frame < b.frame; }
};

// One action, or nothing when it names no verb (the caller reports that once the
// Reader has refused any unknown field, which says more).
std::optional<ScriptAction> readAction(Reader& r) {
    ScriptAction a;
    if (!r.has("frame")) r.fail("frame", "missing", "the frame the action happens at, counted from 0");
    a.frame = uint32_t(r.integer("frame", 0, 0, int64_t(kMaxFrame)));
    const char* verb = nullptr;
    for (const auto& [name, kind] : kVerbs)
        if (r.has(name)) {
            if (verb) r.fail(name, std::string("given with '") + verb + "'", "an action does one thing");
            verb = name;
            a.kind = kind;
        }
    const bool down = r.has("down"), button = r.has("button");
    if (!verb) return std::nullopt;
    if (down && a.kind != Kind::Key) r.fail("down", std::string("given with '") + verb + "'", "only a 'key' action takes 'down'");
    if (button && a.kind != Kind::Click)
        r.fail("button", std::string("given with '") + verb + "'", "only a 'click' action takes 'button'");
    switch (a.kind) {
    case Kind::Key: readKey(r, a); break;
    case Kind::Look: a.vec = r.vec<2>("look", {}, -kMaxLookPixels, kMaxLookPixels); break;
    case Kind::Wheel: a.wheel = r.number("wheel", 0, -kMaxWheelNotches, kMaxWheelNotches); break;
    case Kind::Set: readSettings(r, a); break;
    case Kind::Resize:
        a.vec = r.vec<2>("resize", {}, 1, kMaxWindowSide, {"width", "height"});
        if (a.vec != glm::floor(a.vec)) r.fail("resize", "expected whole numbers", "[width, height] in pixels");
        break;
    case Kind::Minimize:
    case Kind::Restore:
    case Kind::Record:
    case Kind::Undo: requireTrue(r, verb); break;
    case Kind::Camera:
        a.camera = r.string("camera", "");
        if (a.camera.empty()) r.fail("camera", "expected a camera name", "one of the world's named cameras");
        break;
    case Kind::SavePath:
    case Kind::SaveWorld:
    case Kind::Screenshot: a.path = outputPath(r, verb); break;
    case Kind::Click:
        a.vec = r.vec<2>("click", {}, 0, kMaxWindowSide);
        a.button = lookup(r, "button", "button", kButtons, "left");
        break;
    }
    return a;
}

}  // namespace

const char* scriptKeyName(ScriptKey key) { return nameOf(kKeys, key); }
bool isHeld(ScriptKey key) { return key != ScriptKey::F12 && key != ScriptKey::R && key != ScriptKey::Tab; }
const char* verbName(Kind kind) { return nameOf(kVerbs, kind); }

ViewScript ViewScript::load(const fs::path& file) {
    const json doc = voxel::readJsonFile(file, "a script is a JSON object {\"actions\": [{\"frame\": 0, \"key\": \"W\", \"down\": true}, ...]}");
    ViewScript script;
    script.file_ = file;
    {
        Reader r(file, doc, "");
        if (!r.has("actions")) r.fail("actions", "missing", "a list of actions, each with a frame");
        const json& list = r.at("actions");
        if (!list.is_array() || list.empty()) r.fail("actions", "expected a non-empty array of actions");
        for (size_t i = 0; i < list.size(); ++i) {
            const std::string field = "actions[" + std::to_string(i) + "]";
            std::optional<ScriptAction> a;
            {
                Reader ar(file, list[i], field);
                a = readAction(ar);
            }  // ar refuses unknown fields here
            if (!a) throw Error(file.string(), "field '" + field + "': no action", "one of: " + accepted(kVerbs));
            script.actions_.push_back(std::move(*a));
        }
    }  // r refuses unknown top-level fields here
    std::stable_sort(script.actions_.begin(), script.actions_.end(), FrameOrder{});
    return script;
}

std::span<const ScriptAction> ViewScript::at(uint32_t frame) const {
    const auto [first, last] = std::equal_range(actions_.begin(), actions_.end(), frame, FrameOrder{});
    return {first, last};
}

}  // namespace grotto::viewer
