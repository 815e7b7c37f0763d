// Box arithmetic and the one-line names of edits.
#include "voxel/edit.h"

#include <glm/common.hpp>

#include <cstdio>

namespace grotto {

IndexBox IndexBox::merged(const IndexBox& o) const {
    if (empty()) return o;
    if (o.empty()) return *this;
    return {glm::min(min, o.min), glm::max(max, o.max)};
}

WorldBox WorldBox::merged(const WorldBox& o) const {
    if (empty()) return o;
    if (o.empty()) return *this;
    return {glm::min(min, o.min), glm::max(max, o.max)};
}

}  // namespace grotto

namespace grotto::voxel {

namespace {

std::string triple(glm::ivec3 v) {
    return "(" + std::to_string(v.x) + ", " + std::to_string(v.y) + ", " + std::to_string(v.z) + ")";
}

std::string triple(glm::dvec3 v) {
    char buf[96];
    std::snprintf(buf, sizeof buf, "(%g, %g, %g)", v.x, v.y, v.z);
    return buf;
}

}  // namespace

std::string describe(const Edit& e) {
    std::string s = e.op == Edit::Op::Fill ? "fill" : e.op == Edit::Op::Carve ? "carve" : "paint";
    if (e.shape == Edit::Shape::Sphere) {
        char r[32];
        std::snprintf(r, sizeof r, "%g", e.radius);
        s += " sphere at " + triple(e.centre) + " r " + r;
    } else if (e.box.min == e.box.max) {
        s += " voxel " + triple(e.box.min);
    } else {
        s += " box " + triple(e.box.min) + " to " + triple(e.box.max);
    }
    if (e.op != Edit::Op::Carve) s += " material " + std::to_string(e.material);
    return s;
}

}  // namespace grotto::voxel
