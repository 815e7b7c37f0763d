#include "voxel/edit_track.h"

#include "voxel/world.h"

#include <cmath>

namespace grotto::voxel {
namespace {

// [i, j, k]: whole numbers within the supported voxel index range.
glm::ivec3 voxelIndex(Reader& r, const std::string& key) {
    const json& v = r.at(key);
    const std::string accepted = "an array of 3 whole numbers [i, j, k] (voxel indices), each within +-2^30";
    if (!v.is_array() || v.size() != 3) r.fail(key, "expected " + accepted);
    glm::ivec3 out;
    for (int i = 0; i < 3; ++i) {
        const std::string component = key + "[" + std::to_string(i) + "] (" + "ijk"[i] + ")";
        if (!v[i].is_number_integer()) r.fail(key, component + " is not a whole number", accepted);
        const int64_t c = v[i].get<int64_t>();
        if (c < -kMaxVoxelIndex || c >= kMaxVoxelIndex) r.fail(key, component + " = " + v[i].dump() + " is out of range", accepted);
        out[i] = int(c);
    }
    return out;
}

// Exactly one of the shapes: "voxel", "voxels" {min, max} or "sphere" {centre, radius}.
void readShape(Reader& r, Edit& e) {
    const bool voxel = r.has("voxel"), voxels = r.has("voxels"), sphere = r.has("sphere");
    if (int(voxel) + int(voxels) + int(sphere) != 1)
        r.fail(voxel || voxels || sphere ? "sphere" : "voxel", voxel || voxels || sphere ? "more than one shape" : "missing",
               "each edit gives one shape: \"voxel\": [i, j, k], \"voxels\": {\"min\": [i, j, k], \"max\": [i, j, k]} "
               "or \"sphere\": {\"centre\": [x, y, z], \"radius\": r}");
    if (voxel) {
        e.shape = Edit::Shape::Box;
        e.box.min = e.box.max = voxelIndex(r, "voxel");
    } else if (voxels) {
        Reader b = r.child("voxels");
        if (!b.has("min")) b.fail("min", "missing", "the box's first voxel [i, j, k]");
        if (!b.has("max")) b.fail("max", "missing", "the box's last voxel [i, j, k] (inclusive)");
        e.shape = Edit::Shape::Box;
        e.box = {voxelIndex(b, "min"), voxelIndex(b, "max")};
        if (e.box.empty()) b.fail("max", "is below 'min' on an axis", "max >= min on every axis (both inclusive)");
    } else {
        Reader s = r.child("sphere");
        if (!s.has("centre")) s.fail("centre", "missing", "the centre [x, y, z], world units");
        if (!s.has("radius")) s.fail("radius", "missing", "the radius, world units");
        e.shape = Edit::Shape::Sphere;
        e.centre = s.vec3("centre", glm::dvec3(0.0));
        e.radius = s.number("radius", 1.0, 1e-9, 1e9);
    }
}

TimedEdit parseEdit(Reader r) {
    TimedEdit t;
    t.field = r.field("");
    if (!r.has("time")) r.fail("time", "missing", "seconds from the start of the path");
    t.time = r.number("time", 0.0, 0.0, 1e7);
    const std::string op = r.string("op", "");
    if (op == "fill") t.edit.op = Edit::Op::Fill;
    else if (op == "carve") t.edit.op = Edit::Op::Carve;
    else if (op == "paint") t.edit.op = Edit::Op::Paint;
    else r.fail("op", op.empty() ? "missing" : "'" + op + "' is not an edit", "accepted: fill, carve, paint");
    readShape(r, t.edit);
    if (t.edit.op == Edit::Op::Carve) {
        if (r.has("material")) r.fail("material", "given with 'carve'", "a carve empties voxels: leave 'material' out");
    } else {
        if (!r.has("material")) r.fail("material", "missing", "the material id the " + op + " gives, 1 to 255");
        t.edit.material = int(r.integer("material", 1, 1, 255));
    }
    return t;
}

}  // namespace

std::vector<TimedEdit> parseEditTrack(Reader& path, const std::string& key, const std::string& field) {
    const json& edits = path.at(key);
    if (!edits.is_array()) path.fail(key, "expected an array of edits");
    std::vector<TimedEdit> out;
    for (size_t i = 0; i < edits.size(); ++i) {
        const std::string name = (field.empty() ? "" : field + ".") + key + "[" + std::to_string(i) + "]";
        out.push_back(parseEdit(Reader(path.file(), edits[i], name)));
        if (i > 0 && out[i].time < out[i - 1].time)
            throw Error(path.file().string(), "field '" + name + ".time': " + Reader::format(out[i].time) +
                                                  " comes before the previous edit's " + Reader::format(out[i - 1].time),
                        "edit times must not decrease (edits at the same time apply in file order)");
    }
    return out;
}

}  // namespace grotto::voxel
