#include "voxel/gltf/gltf_camera.h"

#include "common/printable.h"
#include "grotto/error.h"
#include "voxel/gltf/gltf_file.h"

#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/mat4x4.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <optional>

namespace grotto::voxel {
namespace fs = std::filesystem;

namespace {

enum class Property { Translation, Rotation, Scale };
enum class Interpolation { Step, Linear, Cubic };

// One animated property of one node: its sampler's keys as read.
struct Channel {
    int node = -1;
    Property property = Property::Translation;
    Interpolation interpolation = Interpolation::Linear;
    std::vector<float> times;
    std::vector<float> values;  // per key: width floats; CUBICSPLINE: in-tangent, value, out-tangent
    int width = 3;

    glm::dvec4 at(size_t key, int part) const {  // part 0: in-tangent, 1: value, 2: out-tangent
        const size_t element = interpolation == Interpolation::Cubic ? key * 3 + size_t(part) : key;
        glm::dvec4 v(0.0);
        for (int c = 0; c < width; ++c) v[c] = values[element * size_t(width) + size_t(c)];
        return v;
    }

    // The value at `time`; `before`: the limit from the left, where STEP jumps.
    glm::dvec4 sample(double time, bool before) const {
        const size_t n = times.size();
        if (time <= times.front()) return at(0, 1);
        if (time > times.back() || (time == times.back() && !(before && interpolation == Interpolation::Step)))
            return at(n - 1, 1);
        // times[k] <= time < times[k + 1] (or time == times[k + 1] from the left)
        size_t k = size_t(std::upper_bound(times.begin(), times.end(), time,
                                           [](double t, float key) { return t < double(key); }) -
                          times.begin()) - 1;
        if (before && k > 0 && double(times[k]) == time) --k;
        k = std::min(k, n - 2);
        const double t0 = times[k], t1 = times[k + 1], span = t1 - t0;
        const double u = std::clamp((time - t0) / span, 0.0, 1.0);
        switch (interpolation) {
            case Interpolation::Step: return at(k, 1);
            case Interpolation::Linear:
                if (property == Property::Rotation) {
                    const glm::dvec4 a = at(k, 1), b = at(k + 1, 1);
                    const glm::dquat q = glm::slerp(glm::dquat(a.w, a.x, a.y, a.z), glm::dquat(b.w, b.x, b.y, b.z), u);
                    return {q.x, q.y, q.z, q.w};
                }
                return glm::mix(at(k, 1), at(k + 1, 1), u);
            case Interpolation::Cubic: {
                // glTF's cubic Hermite spline: tangents scaled by the key interval.
                const double u2 = u * u, u3 = u2 * u;
                const glm::dvec4 v = (2 * u3 - 3 * u2 + 1) * at(k, 1) + (u3 - 2 * u2 + u) * span * at(k, 2) +
                                     (-2 * u3 + 3 * u2) * at(k + 1, 1) + (u3 - u2) * span * at(k + 1, 0);
                if (property != Property::Rotation) return v;
                const double len = glm::length(v);
                return len > 0.0 ? v / len : at(k, 1);
            }
        }
        return at(k, 1);
    }
};

// A node's transform when nothing animates it.
struct NodeRest {
    glm::dvec3 translation{0.0}, scale{1.0};
    glm::dquat rotation{1.0, 0.0, 0.0, 0.0};
    std::optional<glm::dmat4> matrix;  // a node given by its matrix (glTF: never animated)
};

glm::dquat quatFrom(const glm::dvec4& v) { return glm::normalize(glm::dquat(v.w, v.x, v.y, v.z)); }

// The rotation angle from a to b, well conditioned near 0 (acos of the dot product is not).
double angleBetween(const glm::dquat& a, glm::dquat b) {
    if (glm::dot(a, b) < 0.0) b = -b;
    const glm::dvec4 d(a.x - b.x, a.y - b.y, a.z - b.z, a.w - b.w), s(a.x + b.x, a.y + b.y, a.z + b.z, a.w + b.w);
    return 4.0 * std::atan2(glm::length(d), glm::length(s));
}

}  // namespace

struct GltfCameraAnimation::Data {
    std::string file;
    std::string camera;  // the camera's node, as errors name it
    std::vector<int> chain;  // root first, the camera's node last
    std::vector<NodeRest> rest;  // per chain entry
    std::vector<Channel> channels;
    std::vector<std::vector<size_t>> channelsAt;  // per chain entry: its channels
    std::vector<double> times;
    double fov = 60.0, nearPlane = 0.05, farPlane = 0.0;

    [[noreturn]] void fail(const std::string& what, const std::string& hint = {}) const { throw Error(file, what, hint); }
};

namespace {

using Data = GltfCameraAnimation::Data;

std::string nodeName(const tinygltf::Model& m, int node) {
    const std::string& n = m.nodes[size_t(node)].name;
    return "node " + std::to_string(node) + (n.empty() ? "" : " '" + printableExcerpt(n, 60) + "'");
}

// Each node's parent, refusing a child listed twice or a cycle.
std::vector<int> parents(const tinygltf::Model& m, const Data& d) {
    std::vector<int> parent(m.nodes.size(), -1);
    for (size_t i = 0; i < m.nodes.size(); ++i)
        for (int c : m.nodes[i].children) {
            if (c < 0 || size_t(c) >= m.nodes.size())
                d.fail("node " + std::to_string(i) + " has child " + std::to_string(c) + ", which does not exist");
            if (parent[size_t(c)] != -1 || size_t(c) == i)
                d.fail(nodeName(m, c) + " has more than one parent", "glTF nodes form a tree");
            parent[size_t(c)] = int(i);
        }
    return parent;
}

// Far deeper than any scene a tool writes; bounds the work per pose.
constexpr size_t kMaxNodeDepth = 1024;

std::vector<int> chainTo(int node, const std::vector<int>& parent, const tinygltf::Model& m, const Data& d) {
    std::vector<int> chain;
    for (int n = node; n != -1; n = parent[size_t(n)]) {
        if (chain.size() > m.nodes.size()) d.fail(nodeName(m, node) + "'s ancestors form a cycle", "glTF nodes form a tree");
        if (chain.size() >= kMaxNodeDepth)
            d.fail(nodeName(m, node) + " has more than " + std::to_string(kMaxNodeDepth) + " ancestors");
        chain.push_back(n);
    }
    std::reverse(chain.begin(), chain.end());
    return chain;
}

NodeRest restOf(const tinygltf::Node& n, const Data& d, const std::string& name) {
    NodeRest r;
    auto finite = [&](const std::vector<double>& v, size_t size, const char* field) {
        if (v.empty()) return false;
        if (v.size() != size) d.fail(name + " '" + field + "' has " + std::to_string(v.size()) + " numbers, expected " + std::to_string(size));
        for (double x : v)
            if (!std::isfinite(x)) d.fail(name + " '" + field + "' holds a number that is not finite");
        return true;
    };
    if (finite(n.matrix, 16, "matrix")) {
        glm::dmat4 m;
        for (int c = 0; c < 4; ++c)
            for (int row = 0; row < 4; ++row) m[c][row] = n.matrix[size_t(c * 4 + row)];
        r.matrix = m;
    }
    if (finite(n.translation, 3, "translation")) r.translation = {n.translation[0], n.translation[1], n.translation[2]};
    if (finite(n.scale, 3, "scale")) r.scale = {n.scale[0], n.scale[1], n.scale[2]};
    if (finite(n.rotation, 4, "rotation")) {
        const glm::dvec4 q(n.rotation[0], n.rotation[1], n.rotation[2], n.rotation[3]);
        if (glm::length(q) < 1e-12) d.fail(name + " 'rotation' is zero");
        r.rotation = quatFrom(q);
    }
    return r;
}

Channel readChannel(const tinygltf::Model& m, const tinygltf::Animation& anim, const tinygltf::AnimationChannel& c,
                    const std::string& where, const Data& d) {
    Channel ch;
    ch.node = c.target_node;
    if (c.target_path == "translation") ch.property = Property::Translation;
    else if (c.target_path == "rotation") ch.property = Property::Rotation, ch.width = 4;
    else if (c.target_path == "scale") ch.property = Property::Scale;
    else d.fail(where + " animates '" + printableExcerpt(c.target_path, 40) + "' of a camera's node", "a camera moves by translation, rotation and scale");
    if (c.sampler < 0 || size_t(c.sampler) >= anim.samplers.size()) d.fail(where + " names sampler " + std::to_string(c.sampler) + ", which does not exist");
    const tinygltf::AnimationSampler& s = anim.samplers[size_t(c.sampler)];
    if (s.interpolation == "STEP") ch.interpolation = Interpolation::Step;
    else if (s.interpolation == "LINEAR" || s.interpolation.empty()) ch.interpolation = Interpolation::Linear;
    else if (s.interpolation == "CUBICSPLINE") ch.interpolation = Interpolation::Cubic;
    else d.fail(where + "'s sampler has interpolation '" + printableExcerpt(s.interpolation, 40) + "'", "accepted: STEP, LINEAR, CUBICSPLINE");
    ch.times = gltfFloats(m, s.input, 1, d.file, where + " input");
    ch.values = gltfFloats(m, s.output, ch.width, d.file, where + " output");
    if (ch.times.empty()) d.fail(where + "'s sampler has no keys");
    for (size_t i = 0; i < ch.times.size(); ++i) {
        if (ch.times[i] < 0.0f || ch.times[i] > 1e7f) d.fail(where + " key " + std::to_string(i) + " has time " + std::to_string(ch.times[i]), "accepted: 0 to 1e7 seconds");
        if (i > 0 && !(ch.times[i] > ch.times[i - 1])) d.fail(where + " key " + std::to_string(i) + "'s time does not come after the previous key's", "key times must increase strictly");
    }
    const size_t per = ch.interpolation == Interpolation::Cubic ? 3 : 1;
    if (ch.values.size() != ch.times.size() * per * size_t(ch.width))
        d.fail(where + "'s sampler has " + std::to_string(ch.values.size() / size_t(ch.width)) + " output values for " +
               std::to_string(ch.times.size()) + " key times");
    if (ch.property == Property::Rotation)
        for (size_t k = 0; k < ch.times.size(); ++k)
            if (glm::length(ch.at(k, 1)) < 1e-12) d.fail(where + " key " + std::to_string(k) + " has a zero rotation");
    return ch;
}

// The camera node named, or the first with a camera that `animation` (or any
// animation, when none is named) moves; else the first camera node.
int findCameraNode(const tinygltf::Model& m, const GltfCameraChoice& choice, const std::vector<int>& parent, const Data& d) {
    std::vector<int> cameras;
    for (size_t i = 0; i < m.nodes.size(); ++i) {
        const int cam = m.nodes[i].camera;
        if (cam < 0) continue;
        if (size_t(cam) >= m.cameras.size()) d.fail(nodeName(m, int(i)) + " names camera " + std::to_string(cam) + ", which does not exist");
        if (choice.camera.empty() || m.nodes[i].name == choice.camera || m.cameras[size_t(cam)].name == choice.camera)
            cameras.push_back(int(i));
    }
    if (cameras.empty())
        d.fail(choice.camera.empty() ? "has no camera" : "has no camera named '" + choice.camera + "'",
               "export the scene with its cameras (Blender: Include > Cameras)");
    std::vector<char> animated(m.nodes.size(), 0);
    for (const tinygltf::Animation& a : m.animations)
        if (choice.animation.empty() || a.name == choice.animation)
            for (const tinygltf::AnimationChannel& c : a.channels)
                if (c.target_node >= 0 && size_t(c.target_node) < m.nodes.size()) animated[size_t(c.target_node)] = 1;
    for (int node : cameras)
        for (int n : chainTo(node, parent, m, d))
            if (animated[size_t(n)]) return node;
    return cameras.front();
}

}  // namespace

GltfCameraAnimation::GltfCameraAnimation(const fs::path& path, const GltfCameraChoice& choice)
    : d_(std::make_unique<Data>()) {
    Data& d = *d_;
    d.file = path.string();
    const tinygltf::Model m = readGltf(path);
    const std::vector<int> parent = parents(m, d);
    const int node = findCameraNode(m, choice, parent, d);
    d.camera = nodeName(m, node);
    d.chain = chainTo(node, parent, m, d);
    for (int n : d.chain) d.rest.push_back(restOf(m.nodes[size_t(n)], d, nodeName(m, n)));
    std::vector<int> chainIndex(m.nodes.size(), -1);  // a node's place in the chain, -1 off it
    for (size_t i = 0; i < d.chain.size(); ++i) chainIndex[size_t(d.chain[i])] = int(i);
    auto onChain = [&](int n) { return n >= 0 && size_t(n) < m.nodes.size() && chainIndex[size_t(n)] >= 0; };

    const tinygltf::Camera& cam = m.cameras[size_t(m.nodes[size_t(node)].camera)];
    const std::string camName = "camera " + std::to_string(m.nodes[size_t(node)].camera) + (cam.name.empty() ? "" : " '" + printableExcerpt(cam.name, 60) + "'");
    if (cam.type != "perspective") d.fail(camName + " is '" + printableExcerpt(cam.type, 40) + "'", "a path needs a perspective camera");
    d.fov = cam.perspective.yfov * 180.0 / std::numbers::pi;
    if (!(d.fov >= 1.0 && d.fov <= 170.0)) d.fail(camName + " 'yfov' is " + std::to_string(cam.perspective.yfov) + " radians", "accepted: 1 to 170 degrees");
    d.nearPlane = cam.perspective.znear;
    if (!(d.nearPlane >= 1e-4 && d.nearPlane <= 10.0)) d.fail(camName + " 'znear' is " + std::to_string(d.nearPlane), "accepted: 1e-4 to 10");
    d.farPlane = cam.perspective.zfar;
    if (d.farPlane != 0.0 && !(d.farPlane > d.nearPlane && d.farPlane <= 1e7))
        d.fail(camName + " 'zfar' is " + std::to_string(d.farPlane), "accepted: more than znear, up to 1e7; or none for an infinite far plane");

    // The animation: the one named, else the first that moves the camera's chain.
    const tinygltf::Animation* chosen = nullptr;
    for (const tinygltf::Animation& a : m.animations) {
        if (!choice.animation.empty() && a.name != choice.animation) continue;
        for (const tinygltf::AnimationChannel& c : a.channels)
            if (onChain(c.target_node) && c.target_path != "weights") chosen = &a;
        if (chosen) break;
    }
    if (!chosen)
        d.fail(choice.animation.empty() ? nodeName(m, node) + " (the camera) is not animated"
                                        : "has no animation '" + choice.animation + "' that moves " + nodeName(m, node),
               "a path needs the camera's node, or a parent, animated over at least two key times");
    const size_t index = size_t(chosen - m.animations.data());
    std::vector<std::string> animatedProperties;  // "node/path", each once (as glTF requires)
    size_t keys = 0;
    d.channelsAt.resize(d.chain.size());
    for (size_t i = 0; i < chosen->channels.size(); ++i) {
        const tinygltf::AnimationChannel& c = chosen->channels[i];
        if (!onChain(c.target_node) || c.target_path == "weights") continue;  // morph weights move no camera
        const std::string where = "animation " + std::to_string(index) + " channel " + std::to_string(i);
        const size_t at = size_t(chainIndex[size_t(c.target_node)]);
        if (d.rest[at].matrix)
            d.fail(where + " animates " + nodeName(m, c.target_node) + ", which is given by a matrix", "glTF animates only nodes given by translation, rotation and scale");
        const std::string property = std::to_string(c.target_node) + "/" + c.target_path;
        if (std::find(animatedProperties.begin(), animatedProperties.end(), property) != animatedProperties.end())
            d.fail(where + " animates '" + printableExcerpt(c.target_path, 40) + "' of " + nodeName(m, c.target_node) + " again", "glTF animates each property of a node once per animation");
        animatedProperties.push_back(property);
        // The keys are bounded before any is read: channels may share one huge sampler.
        if (c.sampler >= 0 && size_t(c.sampler) < chosen->samplers.size()) {
            const int input = chosen->samplers[size_t(c.sampler)].input;
            if (input >= 0 && size_t(input) < m.accessors.size()) keys += m.accessors[size_t(input)].count;
        }
        if (keys > kMaxAnimationKeys)
            d.fail("the camera's samplers hold more than " + std::to_string(kMaxAnimationKeys) + " keys");
        d.channelsAt[at].push_back(d.channels.size());
        d.channels.push_back(readChannel(m, *chosen, c, where, d));
        d.times.insert(d.times.end(), d.channels.back().times.begin(), d.channels.back().times.end());
    }
    std::sort(d.times.begin(), d.times.end());
    d.times.erase(std::unique(d.times.begin(), d.times.end()), d.times.end());
    if (d.times.size() < 2) d.fail(nodeName(m, node) + " (the camera) moves at one key time only", "a path needs at least two key times");
}

GltfCameraAnimation::~GltfCameraAnimation() = default;
GltfCameraAnimation::GltfCameraAnimation(GltfCameraAnimation&&) noexcept = default;

double GltfCameraAnimation::fovDegrees() const { return d_->fov; }
double GltfCameraAnimation::nearPlane() const { return d_->nearPlane; }
double GltfCameraAnimation::farPlane() const { return d_->farPlane; }
const std::vector<double>& GltfCameraAnimation::keyTimes() const { return d_->times; }

GltfCameraAnimation::Pose GltfCameraAnimation::pose(double time, bool before) const {
    glm::dmat4 world(1.0);
    for (size_t i = 0; i < d_->chain.size(); ++i) {
        const NodeRest& rest = d_->rest[i];
        if (rest.matrix) {
            world = world * *rest.matrix;
            continue;
        }
        glm::dvec3 t = rest.translation, s = rest.scale;
        glm::dquat r = rest.rotation;
        for (size_t k : d_->channelsAt[i]) {
            const Channel& c = d_->channels[k];
            const glm::dvec4 v = c.sample(time, before);
            if (c.property == Property::Translation) t = glm::dvec3(v);
            else if (c.property == Property::Scale) s = glm::dvec3(v);
            else r = quatFrom(v);
        }
        world = world * glm::translate(glm::dmat4(1.0), t) * glm::mat4_cast(r) * glm::scale(glm::dmat4(1.0), s);
    }
    for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 4; ++r)
            if (!std::isfinite(world[c][r])) d_->fail("the camera's transform at " + std::to_string(time) + " s is not finite");
    // The camera's frame without scale, shear or mirror: Gram-Schmidt from its Z
    // and Y, so it looks where the node's -Z does, up its Y.
    const glm::dvec3 z = glm::dvec3(world[2]), y = glm::dvec3(world[1]);
    if (glm::length(z) < 1e-12 || glm::length(glm::cross(z, y)) < 1e-12)
        d_->fail("the camera's transform at " + std::to_string(time) + " s is degenerate (a zero scale)");
    const glm::dvec3 back = glm::normalize(z);
    const glm::dvec3 up = glm::normalize(y - glm::dot(y, back) * back);
    const glm::dvec3 right = glm::cross(up, back);
    Pose p;
    p.position = glm::dvec3(world[3]);
    p.rotation = glm::normalize(glm::quat_cast(glm::dmat3(right, up, back)));
    return p;
}

namespace {

struct Sampled {
    double time;
    GltfCameraAnimation::Pose pose;
};

// A path file's ranges hold for an imported path too: what `path import` writes
// must read back, and flythrough must not render from 1e300.
void requireInPathRange(const Data& d, const glm::dvec3& p, double time, size_t key) {
    const double m = kMaxPathCoordinate;
    if (std::abs(p.x) <= m && std::abs(p.y) <= m && std::abs(p.z) <= m) return;
    char text[160];
    std::snprintf(text, sizeof text, " (the camera) is at (%g, %g, %g) at %g s, path key %zu", p.x, p.y, p.z, time, key);
    char hint[96];
    std::snprintf(hint, sizeof hint, "accepted: coordinates %g to %g, as in a path file's 'position'", -m, m);
    d.fail(d.camera + text, hint);
}

GltfCameraAnimation::Pose between(const GltfCameraAnimation::Pose& a, const GltfCameraAnimation::Pose& b, double u) {
    return {glm::mix(a.position, b.position, u), glm::slerp(a.rotation, b.rotation, u)};
}

}  // namespace

CameraPathDesc GltfCameraAnimation::path() const {
    const std::vector<double>& times = d_->times;
    double extent = 0.0;
    {
        glm::dvec3 lo(1e300), hi(-1e300);
        for (double t : times) {
            const glm::dvec3 p = pose(t).position;
            lo = glm::min(lo, p), hi = glm::max(hi, p);
        }
        extent = glm::length(hi - lo);
    }
    const double positionTolerance = kPathPositionTolerance * std::max(extent, 1e-3);
    auto close = [&](const Pose& a, const Pose& b) {
        return glm::length(a.position - b.position) <= positionTolerance &&
               angleBetween(a.rotation, b.rotation) <= kPathRotationTolerance;
    };
    CameraPathDesc path;
    path.source = d_->file;
    path.interpolation = PathInterpolation::Linear;
    path.fovDegrees = d_->fov;
    path.nearPlane = d_->nearPlane;
    path.farPlane = d_->farPlane;
    auto emit = [&](double time, const Pose& p, bool cut) {
        if (path.keys.size() >= kMaxImportedPathKeys)
            d_->fail("the camera's animation needs more than " + std::to_string(kMaxImportedPathKeys) + " path keys",
                     "bake fewer, smoother keys");
        requireInPathRange(*d_, p.position, time, path.keys.size());
        PathKey k;
        k.time = time;
        k.position = p.position;
        k.rotation = p.rotation;
        k.cut = cut;
        path.keys.push_back(k);
    };
    // Keys inside (a, b) until straight lines and slerp follow the animation.
    auto refine = [&](auto& self, const Sampled& a, const Sampled& b, int depth) -> void {
        if (depth >= 12) return;
        bool straight = true;
        for (double u : {0.25, 0.5, 0.75})
            straight = straight && close(pose(a.time + u * (b.time - a.time)), between(a.pose, b.pose, u));
        if (straight) return;
        const Sampled mid{0.5 * (a.time + b.time), pose(0.5 * (a.time + b.time))};
        self(self, a, mid, depth + 1);
        emit(mid.time, mid.pose, false);
        self(self, mid, b, depth + 1);
    };
    emit(times[0], pose(times[0]), false);
    for (size_t i = 0; i + 1 < times.size(); ++i) {
        const Sampled a{times[i], pose(times[i])}, end{times[i + 1], pose(times[i + 1], true)};
        const size_t before = path.keys.size();
        refine(refine, a, end, 0);
        const Pose after = pose(times[i + 1]);
        const bool jump = !close(end.pose, after);
        const bool still = path.keys.size() == before && close(a.pose, end.pose);
        if (!jump) {
            emit(end.time, after, false);
        } else {
            // A STEP jump: the shot so far ends just before it (or holds still), then a cut.
            if (!still) emit(end.time - (end.time - a.time) * 1e-6, end.pose, false);
            emit(end.time, after, true);
        }
    }
    return path;
}

CameraPathDesc importGltfCameraPath(const fs::path& file, const GltfCameraChoice& choice) {
    return GltfCameraAnimation(file, choice).path();
}

}  // namespace grotto::voxel
