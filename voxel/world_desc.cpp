#include "voxel/world_desc.h"

#include "common/error.h"
#include "common/file_kind.h"
#include "voxel/grid_block.h"
#include "voxel/json_reader.h"

#include <glm/geometric.hpp>
#include <nlohmann/json.hpp>

#include <cmath>

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

glm::vec3 color(Reader& r, const std::string& key, glm::vec3 fallback) {
    return glm::vec3(r.vec3(key, glm::dvec3(fallback), 0.0, 1e3));
}

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

void parseLighting(Reader r, Lighting& l) {
    if (r.has("sun")) {
        Reader s = r.child("sun");
        glm::dvec3 d = s.vec3("direction", glm::dvec3(l.sunDirection));
        if (glm::length(d) < 1e-9) s.fail("direction", "must not be zero");
        l.sunDirection = glm::vec3(glm::normalize(d));
        l.sunColor = color(s, "color", l.sunColor);
        l.sunIntensity = float(s.number("intensity", l.sunIntensity, 0.0, 1e3));
        l.sunShadows = s.boolean("shadows", l.sunShadows);
        l.sunAngle = float(s.number("angle", l.sunAngle, 0.0, 30.0));
    }
    if (r.has("ambient")) {
        Reader a = r.child("ambient");
        l.ambientColor = color(a, "color", l.ambientColor);
        l.ambientIntensity = float(a.number("intensity", l.ambientIntensity, 0.0, 1e3));
    }
    if (r.has("sky")) {
        Reader s = r.child("sky");
        l.skyZenith = color(s, "zenith", l.skyZenith);
        l.skyHorizon = color(s, "horizon", l.skyHorizon);
    }
    l.exposure = float(r.number("exposure", l.exposure, 1e-3, 1e3));
    const std::string toneMap = r.string("tone_map", l.toneMap == ToneMap::Filmic ? "filmic" : "linear");
    if (toneMap != "filmic" && toneMap != "linear") r.fail("tone_map", "unknown tone map '" + toneMap + "'", "accepted: filmic, linear");
    l.toneMap = toneMap == "filmic" ? ToneMap::Filmic : ToneMap::Linear;
}

void parseDetail(Reader r, Detail& d) {
    d.lodBias = r.number("lod_bias", d.lodBias, 0.0, 64.0);
    d.occlusionCulling = r.boolean("occlusion_culling", d.occlusionCulling);
}

void parseAo(Reader r, AoDesc& ao) {
    ao.method = r.string("method", ao.method);
    if (ao.method != "gtao" && ao.method != "ssao" && ao.method != "hbao" && ao.method != "voxel" &&
        ao.method != "hybrid" && ao.method != "off")
        r.fail("method", "unknown AO method '" + ao.method + "'", "accepted: gtao, voxel, hybrid, ssao, hbao, off");
    ao.quality = r.string("quality", ao.quality);
    if (ao.quality != "low" && ao.quality != "medium" && ao.quality != "high" && ao.quality != "ultra" &&
        ao.quality != "custom")
        r.fail("quality", "unknown AO quality '" + ao.quality + "'", "accepted: low, medium, high, ultra, custom");
    auto opt = [&](const char* key, std::optional<double>& v, double lo, double hi) {
        if (r.has(key)) v = r.number(key, 0.0, lo, hi);
    };
    auto optInt = [&](const char* key, std::optional<int>& v, int lo, int hi) {
        if (r.has(key)) v = int(r.integer(key, 0, lo, hi));
    };
    opt("radius", ao.radius, 1e-15, 1e15);  // what the shaders' floats hold (engine/ao_settings.h)
    opt("radius_multiplier", ao.radiusMultiplier, 0.3, 3.0);
    opt("falloff_range", ao.falloffRange, 0.0, 1.0);
    opt("sample_distribution_power", ao.sampleDistributionPower, 1.0, 3.0);
    opt("thin_occluder", ao.thinOccluder, 0.0, 0.7);
    opt("final_value_power", ao.finalValuePower, 0.5, 5.0);
    opt("depth_mip_offset", ao.depthMipOffset, 0.0, 30.0);
    opt("strength", ao.strength, 0.0, 1.0);
    opt("max_distance", ao.maxDistance, 0.0, 1e7);
    opt("denoise_blur_beta", ao.denoiseBlurBeta, 0.0, 10.0);
    optInt("slices", ao.slices, 1, 32);
    optInt("steps", ao.steps, 1, 32);
    optInt("denoise", ao.denoisePasses, 0, 4);
    optInt("temporal_history", ao.temporalHistory, 0, 64);
    optInt("rays", ao.rays, 1, 64);
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
            mat.albedo = glm::vec3(mr.vec3("albedo", glm::dvec3(mat.albedo), 0.0, 1.0));
            mat.ao = float(mr.number("ao", mat.ao, 0.0, 1.0));
            w.materials.push_back(mat);
        }
    }
    if (r.has("lighting")) parseLighting(r.child("lighting"), w.lighting);
    if (r.has("ao")) parseAo(r.child("ao"), w.ao);
    if (r.has("detail")) parseDetail(r.child("detail"), w.detail);
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
    requireInputFile(path, "give a world .json or a .vdb grid file");
    if (path.extension() == ".vdb") {
        WorldDesc w;
        w.source = path;
        w.gridFile = path;
        w.materials = defaultMaterials();
        return w;
    }
    const json doc = readJsonFile(path, "a world file is a JSON object with at least \"grid\": {\"file\": ...}");
    return parseWorld(path, doc);
}

void applySettingsPatch(WorldDesc& desc, const json& patch, const fs::path& file, const std::string& field) {
    WorldDesc changed = desc;  // kept only when all of the patch is good
    {
        Reader r(file, patch, field);
        if (r.has("lighting")) parseLighting(r.child("lighting"), changed.lighting);
        if (r.has("ao")) parseAo(r.child("ao"), changed.ao);
        if (r.has("detail")) parseDetail(r.child("detail"), changed.detail);
    }  // closing the reader refuses unknown fields
    desc = std::move(changed);
}

}  // namespace grotto::voxel
