// The "objects" array of a world file, read strictly (docs/worlds.md).
#include "voxel/object_desc.h"

#include "voxel/grid_block.h"
#include "voxel/json_reader.h"
#include "voxel/world_desc.h"

#include <glm/geometric.hpp>

#include <cmath>
#include <set>

namespace grotto::voxel {
namespace fs = std::filesystem;
namespace {

glm::dquat parseRotation(Reader& k) {
    const bool quaternion = k.has("quaternion"), angle = k.has("angle_degrees"), axis = k.has("axis");
    if (quaternion && (angle || axis))
        k.fail("quaternion", "given with 'angle_degrees'/'axis'", "give one rotation: a quaternion, or an angle and an axis");
    if (quaternion) return k.quaternion("quaternion");
    if (angle != axis) k.fail(angle ? "axis" : "angle_degrees", "missing", "'angle_degrees' and 'axis' come together");
    if (!angle) return glm::dquat(1.0, 0.0, 0.0, 0.0);
    const double degrees = k.number("angle_degrees", 0.0, -1e6, 1e6);
    const glm::dvec3 a = k.vec3("axis", glm::dvec3(0.0, 1.0, 0.0));
    if (glm::length(a) < 1e-9) k.fail("axis", "must not be zero");
    return glm::angleAxis(glm::radians(degrees), glm::normalize(a));
}

std::vector<ObjectKey> parseKeys(Reader& o) {
    if (!o.has("keys")) o.fail("keys", "missing", "give at least one key: {\"time\": 0, \"position\": [x, y, z]}");
    const json& keys = o.at("keys");
    if (!keys.is_array() || keys.empty()) o.fail("keys", "expected a non-empty array of keys");
    std::vector<ObjectKey> out;
    for (size_t i = 0; i < keys.size(); ++i) {
        Reader k(o.fileName(), keys[i], o.field("keys[" + std::to_string(i) + "]"));
        ObjectKey key;
        if (!k.has("time")) k.fail("time", "missing");
        if (!k.has("position")) k.fail("position", "missing", "where the pivot is at this time, world units");
        key.time = k.number("time", 0.0, 0.0, 1e9);
        key.position = k.vec3("position", key.position);
        key.rotation = parseRotation(k);
        if (!out.empty() && !(key.time > out.back().time))
            k.fail("time", "must exceed the previous key's time", "keys are listed in strictly increasing time");
        out.push_back(key);
    }
    return out;
}

void parseGenerator(Reader g, ObjectDesc& d) {
    if (!g.has("kind")) g.fail("kind", "missing");
    d.generator = g.string("kind", "");
    const std::vector<std::string>& kinds = worldKinds();
    bool known = d.generator == "box";
    std::string list = "box";
    for (const std::string& k : kinds) known |= k == d.generator, list += ", " + k;
    if (!known) g.fail("kind", "unknown generator '" + d.generator + "'", "accepted: " + list);
    d.generatorOptions.voxelSize = g.number("voxel_size", 1.0, 1e-4, 1e6);
    if (d.generator == "box") {
        if (!g.has("size")) g.fail("size", "missing", "the box's extent in voxels: [x, y, z]");
        const glm::dvec3 s = g.vec3("size", glm::dvec3(0.0), 1.0, 4096.0);
        if (s != glm::floor(s)) g.fail("size", "expected whole numbers of voxels");
        d.boxSize = glm::ivec3(s);
        d.material = int(g.integer("material", d.material, 1, 255));
        return;
    }
    d.generatorOptions.seed = uint32_t(g.integer("seed", d.generatorOptions.seed, 0, 4294967295));
    d.generatorOptions.size = int(g.integer("size", 0, 0, 4096));
    if (d.generator == "mesh") {
        if (!g.has("mesh")) g.fail("mesh", "missing", "the OBJ or PLY to voxelise, relative to the world file");
        const std::string m = g.string("mesh", "");
        d.generatorOptions.meshFile = (fs::path(m).is_absolute() ? fs::path(m) : g.fileName().parent_path() / m).string();
    }
}

ObjectDesc parseObject(Reader& o, const fs::path& file, size_t index, size_t palette) {
    ObjectDesc d;
    d.name = o.string("name", "object" + std::to_string(index + 1));
    const bool grid = o.has("grid"), generator = o.has("generator");
    if (grid == generator)
        o.fail(grid ? "generator" : "grid", grid ? "given with 'grid'" : "missing",
               "an object's voxels come from a \"grid\": {\"file\": ...} or a \"generator\": {\"kind\": ...}");
    if (grid)
        readGridBlock(o.child("grid"), file, d);
    else
        parseGenerator(o.child("generator"), d);
    if (size_t(d.material) > palette)
        throw Error(file.string(), "field '" + o.field(grid ? "grid.material" : "generator.material") + "': id " +
                                       std::to_string(d.material) + " has no entry in 'materials'",
                    "the palette has " + std::to_string(palette) + " materials");
    d.pivot = o.vec3("pivot", d.pivot);
    d.keys = parseKeys(o);
    return d;
}

}  // namespace

std::vector<ObjectDesc> parseObjects(Reader& r, const fs::path& file, size_t palette) {
    const json& list = r.at("objects");
    if (!list.is_array() || list.size() > kMaxObjects)
        r.fail("objects", "expected an array of at most " + std::to_string(kMaxObjects) + " objects");
    std::vector<ObjectDesc> out;
    std::set<std::string> names;
    for (size_t i = 0; i < list.size(); ++i) {
        ObjectDesc d;
        {
            Reader o(file, list[i], "objects[" + std::to_string(i) + "]");
            d = parseObject(o, file, i, palette);
            if (!names.insert(d.name).second) o.fail("name", "'" + d.name + "' names an earlier object too");
        }  // unknown fields are refused here
        out.push_back(std::move(d));
    }
    return out;
}

}  // namespace grotto::voxel
