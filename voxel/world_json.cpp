// Writes each block as its reader (world_desc.cpp, object_desc.cpp,
// camera_path_desc.cpp, edit_track.cpp) reads it; WorldSave's round trip
// checks that they agree.
#include "voxel/world_json.h"

#include "common/overloaded.h"
#include "voxel/settings_table.h"

#include <algorithm>
#include <charconv>
#include <optional>
#include <type_traits>

namespace grotto::voxel {
namespace fs = std::filesystem;
namespace {

// A float as the shortest decimal that reads back as it (0.62, not 0.6200000047683716).
double decimal(float f) {
    char text[32];
    const char* end = std::to_chars(text, text + sizeof text, f).ptr;
    double d = f;
    std::from_chars(text, end, d);
    return d;
}

json triple(glm::dvec3 v) { return json::array({v.x, v.y, v.z}); }
json triple(glm::ivec3 v) { return json::array({v.x, v.y, v.z}); }
json triple(glm::vec3 v) { return json::array({decimal(v.x), decimal(v.y), decimal(v.z)}); }
json quaternion(const glm::dquat& q) { return json::array({q.x, q.y, q.z, q.w}); }  // [x, y, z, w]

// `file` as a world file in `dir` names it: relative to `dir` where a relative path reaches it.
std::string fileFrom(const fs::path& dir, const fs::path& file) {
    std::error_code ec;
    const fs::path absolute = fs::absolute(file, ec).lexically_normal();
    const fs::path base = fs::absolute(dir.empty() ? fs::path(".") : dir, ec).lexically_normal();
    const fs::path relative = absolute.lexically_relative(base);
    return (relative.empty() ? absolute : relative).generic_string();
}

template <typename Desc>
json gridBlock(const Desc& d, const fs::path& dir) {
    json g = {{"file", fileFrom(dir, d.gridFile)}};
    if (!d.gridName.empty()) g["name"] = d.gridName;
    g["rule"] = solidRuleName(d.rule);
    g["threshold"] = d.threshold;
    g["material"] = d.material;
    return g;
}

json cameraJson(const CameraDesc& c) {
    return {{"position", triple(c.position)}, {"target", triple(c.target)}, {"fov", c.fovDegrees},
            {"near", c.nearPlane}, {"far", c.farPlane}};
}

// The settings' value as its reader reads it back; nullopt for an AO setting left to the preset.
std::optional<json> settingJson(const Setting& s, const WorldDesc& d) {
    return std::visit(Overloaded{
                          [&](std::string AoDesc::*m) -> std::optional<json> { return d.ao.*m; },
                          [&](auto AoDesc::*m) -> std::optional<json> {
                              if (!(d.ao.*m)) return std::nullopt;
                              return *(d.ao.*m);
                          },
                          [&](float Lighting::*m) -> std::optional<json> { return decimal(d.lighting.*m); },
                          [&](bool Lighting::*m) -> std::optional<json> { return d.lighting.*m; },
                          [&](glm::vec3 Lighting::*m) -> std::optional<json> { return triple(d.lighting.*m); },
                          [&]<class E>(E Lighting::*m) -> std::optional<json> requires std::is_enum_v<E> {
                              return std::string(s.choices[size_t(d.lighting.*m)]);
                          },
                          [&](double Detail::*m) -> std::optional<json> { return d.detail.*m; },
                          [&](bool Detail::*m) -> std::optional<json> { return d.detail.*m; },
                      },
                      s.desc);
}

// The "lighting", "ao" and "detail" blocks into `j`, in the table's order.
void writeSettings(const WorldDesc& d, json& j) {
    for (const Setting& s : settingsTable()) {
        std::optional<json> value = settingJson(s, d);
        if (!value) continue;
        json* block = &j;
        std::string_view key = s.key;
        for (size_t dot; (dot = key.find('.')) != std::string_view::npos; key = key.substr(dot + 1))
            block = &(*block)[std::string(key.substr(0, dot))];
        (*block)[std::string(key)] = std::move(*value);
    }
}

json editJson(const TimedEdit& t) {
    const Edit& e = t.edit;
    json j = {{"time", t.time},
              {"op", e.op == Edit::Op::Fill ? "fill" : e.op == Edit::Op::Carve ? "carve" : "paint"}};
    if (e.shape == Edit::Shape::Sphere)
        j["sphere"] = {{"centre", triple(e.centre)}, {"radius", e.radius}};
    else if (e.box.min == e.box.max)
        j["voxel"] = triple(e.box.min);
    else
        j["voxels"] = {{"min", triple(e.box.min)}, {"max", triple(e.box.max)}};
    if (e.op != Edit::Op::Carve) j["material"] = e.material;
    return j;
}

json pathJson(const CameraPathDesc& p) {
    json j = json::object();
    if (p.interpolation == PathInterpolation::Linear) j["interpolation"] = "linear";
    if (p.constantSpeed) j["constant_speed"] = true;
    if (p.fovDegrees) j["fov"] = *p.fovDegrees;
    if (p.nearPlane) j["near"] = *p.nearPlane;
    if (p.farPlane) j["far"] = *p.farPlane;
    j["keys"] = json::array();
    for (const PathKey& k : p.keys) {
        json key = {{"time", k.time}, {"position", triple(k.position)}};
        if (k.target) key["target"] = triple(*k.target);
        if (k.rotation) key["quaternion"] = quaternion(*k.rotation);
        if (k.fovDegrees) key["fov"] = *k.fovDegrees;
        if (k.cut) key["cut"] = true;
        j["keys"].push_back(key);
    }
    if (!p.edits.empty()) {
        j["edits"] = json::array();
        for (const TimedEdit& t : p.edits) j["edits"].push_back(editJson(t));
    }
    return j;
}

json objectJson(const ObjectDesc& o, const fs::path& dir) {
    json j = {{"name", o.name}};
    if (o.generator.empty()) {
        j["grid"] = gridBlock(o, dir);
    } else {
        const GeneratorOptions& g = o.generatorOptions;
        json generator = {{"kind", o.generator}, {"voxel_size", g.voxelSize}};
        if (o.generator == "box") {
            generator["size"] = triple(o.boxSize);
            generator["material"] = o.material;
        } else {
            generator["seed"] = g.seed;
            generator["size"] = g.size;
            if (o.generator == "mesh") generator["mesh"] = fileFrom(dir, g.meshFile);
        }
        j["generator"] = generator;
    }
    j["pivot"] = triple(o.pivot);
    j["keys"] = json::array();
    for (const ObjectKey& k : o.keys)
        j["keys"].push_back({{"time", k.time}, {"position", triple(k.position)}, {"quaternion", quaternion(k.rotation)}});
    return j;
}

}  // namespace

json worldFileJson(const WorldDesc& d, const fs::path& dir) {
    json j = {{"grid", gridBlock(d, dir)}};
    if (!d.materials.empty()) {
        j["materials"] = json::array();
        for (const Material& m : d.materials) {
            json entry = {{"name", m.name}, {"albedo", triple(m.albedo)}, {"ao", decimal(m.ao)}};
            if (m.emissionIntensity > 0.0f)
                entry["emission"] = {{"color", triple(m.emissionColor)}, {"intensity", decimal(m.emissionIntensity)}};
            j["materials"].push_back(entry);
        }
    }
    writeSettings(d, j);  // lighting, ao, detail
    if (!d.cameras.empty()) {
        j["cameras"] = json::object();
        for (const auto& [name, c] : d.cameras) j["cameras"][name] = cameraJson(c);
    }
    j["default_camera"] = d.defaultCamera;  // "" = framed from the bounds, even when there are cameras
    if (!d.paths.empty()) {
        j["paths"] = json::object();
        for (const auto& [name, p] : d.paths) j["paths"][name] = pathJson(p);
    }
    if (!d.objects.empty()) {
        j["objects"] = json::array();
        for (const ObjectDesc& o : d.objects) j["objects"].push_back(objectJson(o, dir));
    }
    j["memory_budget_mib"] = std::max<size_t>(1, d.memoryBudgetBytes >> 20);
    return j;
}

json cameraPathJson(const CameraPathDesc& path) { return pathJson(path); }

}  // namespace grotto::voxel
