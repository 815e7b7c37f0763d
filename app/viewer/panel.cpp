#include "app/viewer/panel.h"

#include "common/overloaded.h"
#include "voxel/settings_table.h"

#include <imgui.h>

#include <algorithm>
#include <cstdio>
#include <type_traits>

namespace grotto::viewer {
namespace {

// A combo over `options`; true (with `value` changed) when another was picked.
bool combo(const char* label, std::string& value, const std::vector<std::string>& options) {
    bool changed = false;
    if (ImGui::BeginCombo(label, value.c_str())) {
        for (const std::string& o : options)
            if (ImGui::Selectable(o.c_str(), o == value) && o != value) value = o, changed = true;
        ImGui::EndCombo();
    }
    return changed;
}

// A file name to edit in place.
void inputPath(const char* label, std::string& path) {
    char buffer[1024];
    std::snprintf(buffer, sizeof buffer, "%s", path.c_str());
    if (ImGui::InputText(label, buffer, sizeof buffer)) path = buffer;
}

// A choice's value now, as the world file names it.
std::string choiceOf(const voxel::Setting& row, const voxel::WorldDesc& d) {
    return std::visit(Overloaded{[&](std::string voxel::AoDesc::*m) { return d.ao.*m; },
                                 [&]<class E>(E voxel::Lighting::*m) requires std::is_enum_v<E> {
                                     return std::string(row.choices[size_t(d.lighting.*m)]);
                                 },
                                 [](auto) { return std::string(); }},
                      row.desc);
}

// The control of one setting, showing its value in effect; the new value when it was changed.
voxel::json control(const voxel::Setting& row, const PanelState& s) {
    const voxel::WorldDesc& d = *s.desc;
    const std::string label = voxel::settingLabel(row);
    auto [lo, hi] = voxel::uiRange(row);
    switch (row.type) {
    case voxel::SettingType::Choice: {
        std::string v = choiceOf(row, d);
        if (combo(label.c_str(), v, {row.choices.begin(), row.choices.end()})) return v;
        break;
    }
    case voxel::SettingType::Number: {
        float v = float(voxel::settingNumber(row, d, s.ao->estimator, s.ao->chain));
        if (row.uiRelative) lo *= v, hi *= v;
        if (ImGui::SliderFloat(label.c_str(), &v, float(lo), float(hi), "%.3g", lo > 0.0 ? ImGuiSliderFlags_Logarithmic : 0))
            return v;
        break;
    }
    case voxel::SettingType::Whole: {
        int v = int(voxel::settingNumber(row, d, s.ao->estimator, s.ao->chain));
        if (ImGui::SliderInt(label.c_str(), &v, int(lo), int(hi))) return v;
        break;
    }
    case voxel::SettingType::Bool: {
        bool v = voxel::settingNumber(row, d, s.ao->estimator, s.ao->chain) != 0.0;
        if (ImGui::Checkbox(label.c_str(), &v)) return v;
        break;
    }
    case voxel::SettingType::Color:
    case voxel::SettingType::Direction: {
        const glm::vec3 now = d.lighting.*std::get<glm::vec3 voxel::Lighting::*>(row.desc);
        float v[3] = {now.x, now.y, now.z};
        const bool changed = row.type == voxel::SettingType::Color
                                 ? ImGui::ColorEdit3(label.c_str(), v, ImGuiColorEditFlags_Float | ImGuiColorEditFlags_HDR)
                                 : ImGui::SliderFloat3(label.c_str(), v, float(lo), float(hi)) && (v[0] || v[1] || v[2]);
        if (changed) return {v[0], v[1], v[2]};
        break;
    }
    }
    return {};
}

// A control for each setting of `block` ("lighting", "ao", "detail"), changes
// added to `patch` under their world-file keys.
void settingControls(std::string_view block, const PanelState& s, voxel::json& patch) {
    const std::string method = s.ao->enabled ? aoMethodName(s.ao->method) : "off";
    for (const voxel::Setting& row : voxel::settingsTable()) {
        if (row.key.substr(0, row.key.find('.')) != block || !voxel::usedBy(row, method)) continue;
        const voxel::json value = control(row, s);
        if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s (%s)", row.help.data(), row.key.data());
        if (!value.is_null()) patch.merge_patch(voxel::settingPatch(std::string(row.key), value));
    }
}

}  // namespace

voxel::json drawPanel(PanelState& s) {
    voxel::json patch = voxel::json::object();
    const voxel::WorldDesc& d = *s.desc;
    ImGui::SetNextWindowPos(ImVec2(8, 8), ImGuiCond_FirstUseEver);
    ImGui::SetNextWindowSize(ImVec2(340, 0), ImGuiCond_FirstUseEver);
    ImGui::SetNextWindowBgAlpha(0.85f);
    ImGui::Begin("grotto");
    ImGui::PushItemWidth(-150.0f);  // room for the longest label
    if (ImGui::CollapsingHeader("AO", ImGuiTreeNodeFlags_DefaultOpen)) settingControls("ao", s, patch);
    if (ImGui::CollapsingHeader("Lighting")) settingControls("lighting", s, patch);
    if (ImGui::CollapsingHeader("View", ImGuiTreeNodeFlags_DefaultOpen)) {
        combo("show", s.view, kViews);
        float scale = float(s.renderScale);
        if (ImGui::SliderFloat("render scale", &scale, 0.25f, 1.0f, "%.2f")) s.renderScale = scale;
        settingControls("detail", s, patch);
        for (const std::string& c : s.cameras) {
            if (ImGui::Button(c.c_str())) s.jumpTo = c;
            ImGui::SameLine();
        }
        ImGui::NewLine();
        for (const std::string& p : s.paths) {
            if (ImGui::Button(("play " + p).c_str())) s.play = p;
            ImGui::SameLine();
        }
        if (!s.paths.empty()) ImGui::NewLine();
        if (!s.playing.empty()) ImGui::Text("playing %s (any flight key stops it)", s.playing.c_str());
        if (ImGui::Button("screenshot (F12)")) s.screenshot = true;
        ImGui::Text("fly speed %.3g /s (wheel)", s.speed);
    }
    if (ImGui::CollapsingHeader("Edit")) {
        combo("left click", s.editMode, {"none", "dig", "place", "paint", "light"});
        float radius = float(s.brushRadius);
        if (ImGui::SliderFloat("brush radius", &radius, 0.5f, 64.0f, "%.1f voxels", ImGuiSliderFlags_Logarithmic))
            s.brushRadius = radius;
        ImGui::SliderInt("material", &s.material, 1, std::max(int(d.materials.size()), 1));
        if (ImGui::Button("undo (ctrl+Z)")) s.undo = true;
        ImGui::SameLine();
        if (ImGui::Button("save world")) s.saveWorld = true;
        inputPath("##world", s.saveWorldAs);
    }
    if (ImGui::CollapsingHeader("Record")) {
        ImGui::Text("%zu keys", s.recordedKeys);
        if (ImGui::Button("add key (R)")) s.record = true;
        ImGui::SameLine();
        if (ImGui::Button("save path")) s.savePath = true;
        inputPath("##path", s.savePathAs);
    }
    if (ImGui::CollapsingHeader("Timings", ImGuiTreeNodeFlags_DefaultOpen)) {
        std::vector<float> ms(s.frameMs.begin(), s.frameMs.end());
        const float last = ms.empty() ? 0.0f : ms.back();
        char overlay[64];
        std::snprintf(overlay, sizeof overlay, "%.1f ms (%.1f fps)", last, last > 0 ? 1000.0f / last : 0.0f);
        ImGui::PlotLines("frame", ms.data(), int(ms.size()), 0, overlay, 0.0f,
                         ms.empty() ? 1.0f : *std::max_element(ms.begin(), ms.end()) * 1.2f, ImVec2(0, 60));
        for (const auto& [name, t] : s.stats.passMs) ImGui::Text("%-10s %7.2f ms", name.c_str(), t);
        ImGui::Text("quads drawn %llu of %llu", (unsigned long long)s.stats.quadsDrawn, (unsigned long long)s.quads);
        const CullingStats& c = s.stats.culling;
        ImGui::Text("clusters hidden %u of %u; chunks at levels %u %u %u %u", c.clustersHidden, c.clustersInView,
                    c.chunksAtLevel[0], c.chunksAtLevel[1], c.chunksAtLevel[2], c.chunksAtLevel[3]);
        ImGui::Text("solid voxels %llu", (unsigned long long)s.activeVoxels);
        if (s.lightBaked < 1.0)
            ImGui::Text("full light baking: %.0f%% (the sky's light until then)", 100.0 * s.lightBaked);
    }
    if (!s.message.empty()) ImGui::TextWrapped("%s", s.message.c_str());
    ImGui::PopItemWidth();
    ImGui::End();
    return patch;
}

}  // namespace grotto::viewer
