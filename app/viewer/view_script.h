#pragma once
// `grotto view --script FILE`: what a scripted viewer run does, frame by frame.
// Scripts are timed in the viewer's frames (0-based), not seconds, so a run is
// the same on any machine. Parsed as strictly as world files: one line naming the
// file and field, exit code 2, on anything unknown or out of range.
#include <glm/vec2.hpp>
#include <nlohmann/json.hpp>

#include <cstdint>
#include <filesystem>
#include <span>
#include <string>
#include <utility>
#include <vector>

namespace grotto::viewer {

// W A S D Q E and Shift are held: they go down and come up. The hotkeys
// (F12 screenshot, R record a path key, Tab toggle the panel) are pressed.
enum class ScriptKey { W, A, S, D, Q, E, Shift, F12, R, Tab };
const char* scriptKeyName(ScriptKey key);  // as scripts write it: "W", "SHIFT", "F12", "TAB"
bool isHeld(ScriptKey key);

enum class MouseButton { Left, Right, Middle };

struct ScriptAction {
    enum class Kind { Key, Look, Wheel, Set, Resize, Minimize, Restore, Camera, Record, SavePath, Click, Screenshot,
                      Undo, SaveWorld };
    uint32_t frame = 0;  // the viewer's frame counter, 0-based
    Kind kind = Kind::Key;
    ScriptKey key = ScriptKey::W;  // Key
    bool down = true;              // Key: held keys go down (true) or up; hotkeys are always pressed
    glm::dvec2 vec{0.0};           // Look: pixels (x right, y down); Resize: width, height (whole,
                                   // 1..16384); Click: window pixel
    double wheel = 0.0;            // Wheel: notches, positive up
    std::vector<std::pair<std::string, nlohmann::json>> settings;  // Set: name -> value, in file order,
                                                                   // unchecked (the viewer knows the names)
    std::string camera;            // Camera: a named camera of the world
    std::filesystem::path path;    // SavePath, SaveWorld (.json or .vdb: both are written), Screenshot: relative ones joined to the script's directory
    MouseButton button = MouseButton::Left;  // Click
};
// The verb as scripts write it: "key", "save_path", ...
const char* verbName(ScriptAction::Kind kind);

class ViewScript {
public:
    // Throws grotto::Error (input) naming the file and the field.
    static ViewScript load(const std::filesystem::path& file);

    // That frame's actions in file order (empty when none).
    std::span<const ScriptAction> at(uint32_t frame) const;
    // The last frame any action names (0 for a default-made, empty script).
    uint32_t lastFrame() const { return actions_.empty() ? 0 : actions_.back().frame; }
    // Every action, sorted by frame; file order within a frame.
    const std::vector<ScriptAction>& actions() const { return actions_; }
    const std::filesystem::path& file() const { return file_; }

private:
    std::filesystem::path file_;
    std::vector<ScriptAction> actions_;  // load refuses an empty script
};

}  // namespace grotto::viewer
