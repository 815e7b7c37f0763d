// A --script's actions, frame by frame; a bad one is refused naming the script's
// file and the action's field, as the file readers refuse theirs.
#include "app/viewer/viewer_internal.h"

#include "grotto/error.h"

#include <algorithm>

namespace grotto::viewer {
void Viewer::applyScript() {
    if (!script_) return;
    for (const ScriptAction& a : script_->at(frame_)) {
        // The field errors name: "frame 8 set" (a script's frame, its verb).
        const std::string where = "frame " + std::to_string(a.frame) + " " + verbName(a.kind);
        switch (a.kind) {
        case ScriptAction::Kind::Key:
            if (isHeld(a.key)) scriptKeys_[scriptKeyName(a.key)] = a.down;
            else pressHotkey(a.key);
            break;
        case ScriptAction::Kind::Look: scriptLook_ += a.vec; break;
        case ScriptAction::Kind::Wheel: scriptWheel_ += a.wheel; break;
        case ScriptAction::Kind::Set:
            for (const auto& [key, value] : a.settings) {
                const std::string field = where + "." + key;
                if (key == "view") setView(value, field);
                else if (key == "play") playFromScript(value, field);
                else if (key.rfind("edit.", 0) == 0) setEdit(key, value, field);
                else applyPatch(voxel::settingPatch(key, value), script_->file(), where);
            }
            break;
        case ScriptAction::Kind::Resize:
            window_.setSize(uint32_t(a.vec.x), uint32_t(a.vec.y));
            waitForSize();
            break;
        case ScriptAction::Kind::Minimize: window_.minimize(); waitForSize(); break;
        case ScriptAction::Kind::Restore: window_.restore(); waitForSize(); break;
        case ScriptAction::Kind::Camera: jumpTo(a.camera); break;
        case ScriptAction::Kind::Screenshot: pendingShot_ = a.path; break;
        case ScriptAction::Kind::Record: recordKey(); break;
        case ScriptAction::Kind::SavePath: savePath(a.path); break;
        case ScriptAction::Kind::Click: click(a.vec, a.button == MouseButton::Left); break;
        case ScriptAction::Kind::Undo: undo(); break;
        case ScriptAction::Kind::SaveWorld: saveWorld(a.path); break;
        }
    }
}

// A script's setting that is the viewer's own, refused as the file readers do.
void Viewer::refuse(const std::string& field, const std::string& what, const std::string& hint) const {
    throw Error(script_->file().string(), "field '" + field + "': " + what, hint);
}

void Viewer::setView(const nlohmann::json& value, const std::string& field) {
    const std::string v = value.is_string() ? value.get<std::string>() : "";
    if (std::find(kViews.begin(), kViews.end(), v) == kViews.end())
        refuse(field, "unknown view " + value.dump(),
               "accepted: final, ao, raw, spatial, temporal, history, edges, normal, depth, shadow, light");
    panel_.view = v;
}

// The edit brush, as the panel sets it: edit.mode (none, dig, place, paint, light),
// edit.radius (voxels, 0.5 to 64), edit.material (1 to 255).
void Viewer::setEdit(const std::string& key, const nlohmann::json& v, const std::string& field) {
    if (key == "edit.mode") {
        const std::string m = v.is_string() ? v.get<std::string>() : "";
        if (m != "none" && m != "dig" && m != "place" && m != "paint" && m != "light")
            refuse(field, "unknown mode " + v.dump(), "accepted: none, dig, place, paint, light");
        panel_.editMode = m;
    } else if (key == "edit.radius") {
        if (!v.is_number() || !(v.get<double>() >= 0.5 && v.get<double>() <= 64.0))
            refuse(field, "value " + v.dump() + " is out of range", "accepted: 0.5 to 64 (voxels)");
        panel_.brushRadius = v.get<double>();
    } else if (key == "edit.material") {
        if (!v.is_number_integer() || v.get<int>() < 1 || v.get<int>() > 255)
            refuse(field, "value " + v.dump() + " is out of range", "accepted: whole numbers 1 to 255");
        panel_.material = v.get<int>();
    } else {
        refuse(field, "unknown setting", "edit.mode, edit.radius, edit.material");
    }
}

void Viewer::playFromScript(const nlohmann::json& v, const std::string& field) {
    const std::string name = v.is_string() ? v.get<std::string>() : "";
    if (!desc_.paths.count(name)) {
        std::string known;
        for (const std::string& p : panel_.paths) known += (known.empty() ? "" : ", ") + p;
        refuse(field, "no path " + v.dump() + " in the world",
               "the world's paths: " + (known.empty() ? std::string("none") : known));
    }
    playPath(name);
}

}  // namespace grotto::viewer
