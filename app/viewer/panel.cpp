#include "app/viewer/panel.h"

#include <imgui.h>

#include <algorithm>
#include <cstdio>

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

}  // namespace

voxel::json drawPanel(PanelState& s) {
    voxel::json patch = voxel::json::object();
    const voxel::WorldDesc& d = *s.desc;
    ImGui::SetNextWindowPos(ImVec2(8, 8), ImGuiCond_FirstUseEver);
    ImGui::SetNextWindowSize(ImVec2(340, 0), ImGuiCond_FirstUseEver);
    ImGui::SetNextWindowBgAlpha(0.85f);
    ImGui::Begin("grotto");
    ImGui::PushItemWidth(-150.0f);  // room for the longest label
    auto aoDetails = [&] {
        // The values in effect (preset, world file, changes), each control writing its world-file key.
        const AoOptions& ao = *s.ao;
        const gpu::GtaoSettings& g = ao.gtao;
        std::string method = d.ao.method, quality = d.ao.quality;
        if (combo("method", method, {"gtao", "voxel", "hybrid", "ssao", "hbao", "off"})) patch["ao"]["method"] = method;
        if (combo("preset", quality, {"low", "medium", "high", "ultra"})) patch["ao"]["quality"] = quality;
        auto slider = [&](const char* label, const char* key, float value, float lo, float hi) {
            if (ImGui::SliderFloat(label, &value, lo, hi, "%.3g", lo > 0.0f ? ImGuiSliderFlags_Logarithmic : 0))
                patch["ao"][key] = value;
        };
        auto whole = [&](const char* label, const char* key, uint32_t value, int lo, int hi) {
            int v = int(value);
            if (ImGui::SliderInt(label, &v, lo, hi)) patch["ao"][key] = v;
        };
        slider("radius", "radius", g.radius, g.radius / 16.0f, g.radius * 16.0f);
        whole("temporal history", "temporal_history", g.temporalHistory, 0, 64);
        whole("denoise passes", "denoise", g.denoisePasses, 0, 4);
        if (method == "voxel" || method == "hybrid") whole("rays", "rays", ao.voxelRays, 1, 64);
        if (!ImGui::TreeNode("estimator and denoise")) return;
        whole("slices", "slices", g.sliceCount, 1, 32);
        whole("steps", "steps", g.stepsPerSlice, 1, 32);
        slider("thin occluder", "thin_occluder", g.thinOccluderCompensation, 0.0f, 0.7f);
        slider("radius multiplier", "radius_multiplier", g.radiusMultiplier, 0.3f, 3.0f);
        slider("falloff range", "falloff_range", g.falloffRange, 0.0f, 1.0f);
        slider("distribution power", "sample_distribution_power", g.sampleDistributionPower, 1.0f, 3.0f);
        slider("final value power", "final_value_power", g.finalValuePower, 0.5f, 5.0f);
        slider("depth MIP offset", "depth_mip_offset", g.depthMipSamplingOffset, 0.0f, 30.0f);
        slider("denoise blur beta", "denoise_blur_beta", g.denoiseBlurBeta, 0.0f, 10.0f);
        slider("strength", "strength", g.strength, 0.0f, 1.0f);
        ImGui::TreePop();
    };
    if (ImGui::CollapsingHeader("AO", ImGuiTreeNodeFlags_DefaultOpen)) aoDetails();
    if (ImGui::CollapsingHeader("Lighting")) {
        const voxel::Lighting& l = d.lighting;
        float dir[3] = {l.sunDirection.x, l.sunDirection.y, l.sunDirection.z};
        if (ImGui::SliderFloat3("sun direction", dir, -1.0f, 1.0f) && (dir[0] || dir[1] || dir[2]))
            patch["lighting"]["sun"]["direction"] = {dir[0], dir[1], dir[2]};
        float sun = l.sunIntensity, ambient = l.ambientIntensity, exposure = l.exposure, angle = l.sunAngle;
        if (ImGui::SliderFloat("sun", &sun, 0.0f, 4.0f)) patch["lighting"]["sun"]["intensity"] = sun;
        if (ImGui::SliderFloat("sun angle", &angle, 0.0f, 30.0f)) patch["lighting"]["sun"]["angle"] = angle;
        bool shadows = l.sunShadows;
        if (ImGui::Checkbox("sun shadows", &shadows)) patch["lighting"]["sun"]["shadows"] = shadows;
        if (ImGui::SliderFloat("ambient", &ambient, 0.0f, 4.0f)) patch["lighting"]["ambient"]["intensity"] = ambient;
        if (ImGui::SliderFloat("exposure", &exposure, 0.05f, 4.0f)) patch["lighting"]["exposure"] = exposure;
    }
    if (ImGui::CollapsingHeader("View", ImGuiTreeNodeFlags_DefaultOpen)) {
        combo("show", s.view, kViews);
        float scale = float(s.renderScale);
        if (ImGui::SliderFloat("render scale", &scale, 0.25f, 1.0f, "%.2f")) s.renderScale = scale;
        float lodBias = float(d.detail.lodBias);
        bool occlusion = d.detail.occlusionCulling;
        if (ImGui::SliderFloat("lod bias (px)", &lodBias, 0.0f, 16.0f, "%.2f")) patch["detail"]["lod_bias"] = lodBias;
        if (ImGui::Checkbox("occlusion culling", &occlusion)) patch["detail"]["occlusion_culling"] = occlusion;
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
        combo("left click", s.editMode, {"none", "dig", "place", "paint"});
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
    }
    if (!s.message.empty()) ImGui::TextWrapped("%s", s.message.c_str());
    ImGui::PopItemWidth();
    ImGui::End();
    return patch;
}

}  // namespace grotto::viewer
