#include "voxel/world_desc.h"

#include "grotto/error.h"
#include "common/file_kind.h"
#include "common/overloaded.h"
#include "voxel/grid_block.h"
#include "voxel/json_reader.h"
#include "voxel/settings_table.h"
#include "voxel/vox_world.h"

#include <glm/geometric.hpp>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <type_traits>

namespace grotto::voxel {
namespace fs = std::filesystem;

const char* solidRuleName(SolidRule rule) {
    switch (rule) {
        case SolidRule::Auto: return "auto";
        case SolidRule::LevelSet: return "level_set";
        case SolidRule::Fog: return "fog";
        case SolidRule::Mask: return "mask";
        case SolidRule::Int32: return "int32";
    }
    return "?";
}

std::vector<Material> defaultMaterials() {
    return {{"stone", {0.55f, 0.55f, 0.52f}}, {"grass", {0.30f, 0.55f, 0.22f}},
            {"wood", {0.55f, 0.38f, 0.22f}},  {"brick", {0.62f, 0.30f, 0.24f}},
            {"sand", {0.80f, 0.72f, 0.52f}},  {"plaster", {0.85f, 0.83f, 0.78f}},
            {"slate", {0.32f, 0.34f, 0.38f}}, {"moss", {0.42f, 0.50f, 0.30f}}};
}

SolidRule parseSolidRule(Reader& r, const std::string& key) {
    std::string s = r.string(key, "auto");
    for (SolidRule rule : {SolidRule::Auto, SolidRule::LevelSet, SolidRule::Fog, SolidRule::Mask,
                           SolidRule::Int32})
        if (s == solidRuleName(rule)) return rule;
    r.fail(key, "unknown solid rule '" + s + "'", "accepted: auto, level_set, fog, mask, int32");
}

namespace {

CameraDesc parseCamera(Reader r) {
    CameraDesc c;
    c.position = r.vec3("position", c.position);
    c.target = r.vec3("target", c.target);
    c.fovDegrees = r.number("fov", c.fovDegrees, 1.0, 170.0);
    c.nearPlane = r.number("near", c.nearPlane, 1e-4, 10.0);
    c.farPlane = r.number("far", c.farPlane, 0.0, 1e7);
    if (!r.has("position")) r.fail("position", "missing");
    if (!r.has("target")) r.fail("target", "missing");
    if (glm::length(c.target - c.position) < 1e-9)
        r.fail("target", "equals position", "a camera must look somewhere");
    if (c.farPlane != 0.0 && c.farPlane <= c.nearPlane)
        r.fail("far", "must exceed 'near' (or be 0 for an infinite far plane)");
    return c;
}

// A choice's value, refused naming the row's accepted values when it is none of them.
size_t choiceIndex(Reader& r, const std::string& name, const Setting& s, const std::string& value) {
    const auto it = std::find(s.choices.begin(), s.choices.end(), value);
    if (it == s.choices.end())
        r.fail(name, "unknown " + settingLabel(s) + " '" + value + "'", "accepted: " + acceptedText(s));
    return size_t(it - s.choices.begin());
}

// Field `name` of `r` into the setting's place in `w`, checked against its row.
void readSetting(Reader& r, const std::string& name, const Setting& s, WorldDesc& w) {
    std::visit(Overloaded{
                   [&](std::string AoDesc::*m) {
                       w.ao.*m = r.string(name, w.ao.*m);
                       choiceIndex(r, name, s, w.ao.*m);
                   },
                   [&](std::optional<double> AoDesc::*m) {
                       if (r.has(name)) w.ao.*m = r.number(name, 0.0, s.lo, s.hi);
                   },
                   [&](std::optional<int> AoDesc::*m) {
                       if (r.has(name)) w.ao.*m = int(r.integer(name, 0, int64_t(s.lo), int64_t(s.hi)));
                   },
                   [&](std::optional<bool> AoDesc::*m) {
                       if (r.has(name)) w.ao.*m = r.boolean(name, false);
                   },
                   [&](float Lighting::*m) { w.lighting.*m = float(r.number(name, w.lighting.*m, s.lo, s.hi)); },
                   [&](bool Lighting::*m) { w.lighting.*m = r.boolean(name, w.lighting.*m); },
                   [&](glm::vec3 Lighting::*m) {
                       const bool direction = s.type == SettingType::Direction;
                       const glm::dvec3 v = r.vec3(name, glm::dvec3(w.lighting.*m), s.lo, s.hi, direction ? Reader::kAxes : Reader::kChannels);
                       if (direction && glm::length(v) < 1e-9) r.fail(name, "must not be zero");
                       w.lighting.*m = glm::vec3(direction ? glm::normalize(v) : v);
                   },
                   [&]<class E>(E Lighting::*m) requires std::is_enum_v<E> {
                       const std::string v = r.string(name, std::string(s.choices[size_t(w.lighting.*m)]));
                       w.lighting.*m = E(choiceIndex(r, name, s, v));
                   },
                   [&](double Detail::*m) { w.detail.*m = r.number(name, w.detail.*m, s.lo, s.hi); },
                   [&](bool Detail::*m) { w.detail.*m = r.boolean(name, w.detail.*m); },
               },
               s.desc);
}

// The settings under `block` ("" for a world file's top level, "lighting",
// "lighting.sun", ...) from `r`, in the table's order; nested blocks that are
// present are read where their first setting comes.
void readSettings(Reader& r, const std::string& block, WorldDesc& w) {
    const std::string prefix = block.empty() ? "" : block + ".";
    std::vector<std::string> nested;
    for (const Setting& s : settingsTable()) {
        if (!s.key.starts_with(prefix)) continue;
        const std::string rest(s.key.substr(prefix.size()));
        const size_t dot = rest.find('.');
        if (dot == std::string::npos) {
            readSetting(r, rest, s, w);
            continue;
        }
        const std::string child = rest.substr(0, dot);
        if (std::find(nested.begin(), nested.end(), child) != nested.end()) continue;
        nested.push_back(child);
        if (!r.has(child)) continue;
        Reader c = r.child(child);
        readSettings(c, prefix + child, w);
    }
}

// A path inline, or the name of a path .json beside the world file.
CameraPathDesc parsePathEntry(const fs::path& file, const json& entry, const std::string& field) {
    if (!entry.is_string()) {
        CameraPathDesc p;
        {
            Reader r(file, entry, field);
            p = parseCameraPath(r, file, field);
        }  // r refuses unknown fields here, before p is returned (clang leaks a returned object if a destructor throws)
        return p;
    }
    const std::string name = entry.get<std::string>();
    const fs::path pathFile = fs::path(name).is_absolute() ? fs::path(name) : file.parent_path() / name;
    std::error_code ec;
    if (name.empty() || !fs::is_regular_file(pathFile, ec))
        throw Error(file.string(), "field '" + field + "': names no path file '" + pathFile.string() + "'",
                    "give a path object, or a path .json beside the world file");
    return loadCameraPath(pathFile);
}

WorldDesc parseWorld(const fs::path& file, const json& doc) {
    WorldDesc w;
    w.source = file;
    w.materials = defaultMaterials();
    Reader r(file, doc, "");
    if (!r.has("grid")) r.fail("grid", "missing", "name the .vdb file: \"grid\": {\"file\": ...}");
    readGridBlock(r.child("grid"), file, w);
    if (r.has("materials")) {
        const json& m = r.at("materials");
        if (!m.is_array() || m.empty() || m.size() > 255)
            r.fail("materials", "expected an array of 1 to 255 materials");
        w.materials.clear();
        for (size_t i = 0; i < m.size(); ++i) {
            Reader mr(file, m[i], "materials[" + std::to_string(i) + "]");
            Material mat;
            mat.name = mr.string("name", "material" + std::to_string(i + 1));
            mat.albedo = glm::vec3(mr.vec3("albedo", glm::dvec3(mat.albedo), 0.0, 1.0, Reader::kChannels));
            mat.ao = float(mr.number("ao", mat.ao, 0.0, 1.0));
            if (mr.has("emission")) {
                Reader er = mr.child("emission");
                mat.emissionColor = glm::vec3(er.vec3("color", glm::dvec3(mat.emissionColor), 0.0, 1.0, Reader::kChannels));
                mat.emissionIntensity = float(er.number("intensity", 1.0, 0.0, kMaxEmissionIntensity));
            }
            w.materials.push_back(mat);
        }
    }
    if (isVoxFile(w.gridFile)) {
        // A MagicaVoxel model: its palette unless the file gives materials; its
        // colour indices are the material ids.
        if (w.rule != SolidRule::Auto && w.rule != SolidRule::Int32)
            r.fail("grid.rule", std::string("'") + solidRuleName(w.rule) + "' does not apply to a .vox model",
                   "a .vox model's voxels are solid, its colour indices the material ids");
        w.rule = SolidRule::Int32;
        if (!r.has("materials")) w.materials = voxMaterials(readVoxFile(w.gridFile));
    }
    readSettings(r, "", w);  // lighting, ao, detail
    std::string firstCamera;  // in file order: the default unless 'default_camera' says otherwise
    if (r.has("cameras")) {
        const json& cams = r.at("cameras");
        if (!cams.is_object()) r.fail("cameras", "expected an object of named cameras");
        for (auto& [name, cam] : cams.items()) {
            w.cameras[name] = parseCamera(Reader(file, cam, "cameras." + name));
            if (firstCamera.empty()) firstCamera = name;
        }
    }
    if (r.has("paths")) {
        const json& paths = r.at("paths");
        if (!paths.is_object()) r.fail("paths", "expected an object of named paths");
        for (auto& [name, path] : paths.items())
            w.paths[name] = parsePathEntry(file, path, "paths." + name);
    }
    if (r.has("objects")) w.objects = parseObjects(r, file, w.materials.size());
    w.defaultCamera = r.string("default_camera", firstCamera);
    if (!w.defaultCamera.empty() && !w.cameras.count(w.defaultCamera))
        r.fail("default_camera", "names no camera '" + w.defaultCamera + "'");
    w.memoryBudgetBytes = size_t(r.integer("memory_budget_mib", int64_t(w.memoryBudgetBytes >> 20), 1, 1 << 20)) << 20;
    return w;
}

}  // namespace

WorldDesc loadWorldDesc(const fs::path& path) {
    requireInputFile(path, "give a world .json, a .vdb grid file or a MagicaVoxel .vox model");
    if (path.extension() == ".vdb") {
        WorldDesc w;
        w.source = path;
        w.gridFile = path;
        w.materials = defaultMaterials();
        return w;
    }
    if (isVoxFile(path)) {
        WorldDesc w;
        w.source = path;
        w.gridFile = path;
        w.rule = SolidRule::Int32;
        w.materials = voxMaterials(readVoxFile(path));
        return w;
    }
    const json doc = readJsonFile(path, "a world file is a JSON object with at least \"grid\": {\"file\": ...}");
    return parseWorld(path, doc);
}

void applySettingsPatch(WorldDesc& desc, const json& patch, const fs::path& file, const std::string& field) {
    WorldDesc changed = desc;  // kept only when all of the patch is good
    {
        Reader r(file, patch, field);
        if (patch.contains("ao") && patch["ao"].contains("quality")) resetPresetShaped(changed.ao);
        readSettings(r, "", changed);
    }  // closing the reader refuses unknown fields
    desc = std::move(changed);
}

json settingPatch(const std::string& key, const nlohmann::json& value) {
    json patch = json::parse(value.dump());
    std::string k = key;
    for (size_t dot; (dot = k.rfind('.')) != std::string::npos; k = k.substr(0, dot))
        patch = json{{k.substr(dot + 1), patch}};
    return json{{k, patch}};
}

}  // namespace grotto::voxel
