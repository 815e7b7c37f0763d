#include "voxel/object_pose.h"

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>

namespace grotto::voxel {

bool ObjectDesc::moves() const {
    for (const ObjectKey& k : keys)
        if (k.position != keys.front().position || k.rotation != keys.front().rotation) return true;
    return false;
}

glm::dmat4 ObjectPose::worldFromLocal(glm::dvec3 offset) const {
    glm::dmat4 m = glm::mat4_cast(rotation);
    m[3] = glm::dvec4(position - offset - rotation * pivot, 1.0);
    return m;
}

ObjectPose objectPose(const ObjectDesc& object, double time) {
    ObjectPose pose;
    pose.pivot = object.pivot;
    const std::vector<ObjectKey>& k = object.keys;
    if (k.empty()) return pose;
    if (!(time > k.front().time)) {
        pose.position = k.front().position, pose.rotation = k.front().rotation;
        return pose;
    }
    if (time >= k.back().time) {
        pose.position = k.back().position, pose.rotation = k.back().rotation;
        return pose;
    }
    const auto next = std::upper_bound(k.begin(), k.end(), time, [](double t, const ObjectKey& key) { return t < key.time; });
    const ObjectKey& a = *(next - 1);
    const ObjectKey& b = *next;
    const double s = (time - a.time) / (b.time - a.time);
    pose.position = a.position + (b.position - a.position) * s;
    pose.rotation = glm::normalize(glm::slerp(a.rotation, b.rotation, s));
    return pose;
}

std::vector<ObjectPose> objectPoses(const std::vector<ObjectDesc>& objects, double time) {
    std::vector<ObjectPose> poses;
    poses.reserve(objects.size());
    for (const ObjectDesc& o : objects) poses.push_back(objectPose(o, time));
    return poses;
}

}  // namespace grotto::voxel
