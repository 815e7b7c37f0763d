#pragma once
// Writes glTF files with an animated camera the way Blender exports one (a
// camera node, maybe under a parent, animated by TRS channels), for the tests of
// the path import: the tests know every sampler, so they know where the camera is.
#include <tiny_gltf.h>

#include <glm/gtc/quaternion.hpp>
#include <glm/vec3.hpp>

#include <cstring>
#include <filesystem>
#include <string>
#include <vector>

namespace grotto::test {

struct GltfSampler {
    std::string path;           // translation, rotation, scale
    std::string interpolation;  // STEP, LINEAR, CUBICSPLINE
    std::vector<float> times;
    std::vector<float> values;  // 3 or 4 per element; CUBICSPLINE: in-tangent, value, out-tangent per key
    int node = 1;               // 0: the parent, 1: the camera
};

struct GltfCameraScene {
    glm::vec3 parentTranslation{0.0f};
    glm::quat parentRotation{1.0f, 0.0f, 0.0f, 0.0f};
    double parentScale = 1.0;  // uniform
    double yfov = 0.8, znear = 0.1, zfar = 0.0;  // zfar 0: infinite
    std::vector<GltfSampler> samplers;
    std::string assetVersion = "2.0";
    std::string bufferUri;  // .gltf: the buffer in a file of this name, relative to it; empty: embedded
};

inline int addFloats(tinygltf::Model& m, const std::vector<float>& values, int type, size_t count) {
    std::vector<unsigned char>& data = m.buffers[0].data;
    tinygltf::BufferView view;
    view.buffer = 0;
    view.byteOffset = data.size();
    view.byteLength = values.size() * 4;
    data.resize(data.size() + values.size() * 4);
    std::memcpy(data.data() + view.byteOffset, values.data(), values.size() * 4);
    m.bufferViews.push_back(view);
    tinygltf::Accessor a;
    a.bufferView = int(m.bufferViews.size() - 1);
    a.componentType = TINYGLTF_COMPONENT_TYPE_FLOAT;
    a.type = type;
    a.count = count;
    if (type == TINYGLTF_TYPE_SCALAR && !values.empty()) {
        a.minValues = {values.front()};
        a.maxValues = {values.back()};
    }
    m.accessors.push_back(a);
    return int(m.accessors.size() - 1);
}

inline tinygltf::Model gltfCameraModel(const GltfCameraScene& s) {
    tinygltf::Model m;
    m.asset.version = s.assetVersion;
    if (!s.samplers.empty()) {  // glTF has no empty buffers
        m.buffers.resize(1);
        m.buffers[0].uri = s.bufferUri;
    }
    tinygltf::Camera cam;
    cam.type = "perspective";
    cam.name = "shot";
    cam.perspective.yfov = s.yfov;
    cam.perspective.znear = s.znear;
    cam.perspective.zfar = s.zfar;
    cam.perspective.aspectRatio = 16.0 / 9.0;
    m.cameras.push_back(cam);
    tinygltf::Node parent, camera;
    parent.name = "rig";
    parent.translation = {s.parentTranslation.x, s.parentTranslation.y, s.parentTranslation.z};
    parent.rotation = {s.parentRotation.x, s.parentRotation.y, s.parentRotation.z, s.parentRotation.w};
    if (s.parentScale != 1.0) parent.scale = {s.parentScale, s.parentScale, s.parentScale};
    parent.children = {1};
    camera.name = "Camera";
    camera.camera = 0;
    m.nodes = {parent, camera};
    tinygltf::Scene scene;
    scene.nodes = {0};
    m.scenes.push_back(scene);
    tinygltf::Animation anim;
    anim.name = "CameraAction";
    for (const GltfSampler& g : s.samplers) {
        const int width = g.path == "rotation" ? 4 : 3;
        tinygltf::AnimationSampler sampler;
        sampler.input = addFloats(m, g.times, TINYGLTF_TYPE_SCALAR, g.times.size());
        sampler.output = addFloats(m, g.values, width == 4 ? TINYGLTF_TYPE_VEC4 : TINYGLTF_TYPE_VEC3, g.values.size() / size_t(width));
        sampler.interpolation = g.interpolation;
        anim.samplers.push_back(sampler);
        tinygltf::AnimationChannel channel;
        channel.sampler = int(anim.samplers.size() - 1);
        channel.target_node = g.node;
        channel.target_path = g.path;
        anim.channels.push_back(channel);
    }
    if (!anim.channels.empty()) m.animations.push_back(anim);
    return m;
}

// Writes the scene as .glb or .gltf (by the name's extension).
inline bool writeGltfCamera(const GltfCameraScene& s, const std::filesystem::path& file) {
    const tinygltf::Model m = gltfCameraModel(s);
    tinygltf::TinyGLTF writer;
    const bool binary = file.extension() == ".glb";
    return writer.WriteGltfSceneToFile(&m, file.string(), true, s.bufferUri.empty(), !binary, binary);
}

}  // namespace grotto::test
