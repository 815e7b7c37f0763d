#include "engine/camera_path.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace grotto {

namespace {
constexpr int kArcSamples = 128;  // per segment; polyline error ~ (curvature * step)^2 / 24
}

CameraPath::CameraPath(const voxel::CameraPathDesc& desc, const voxel::CameraDesc& defaults)
    : duration_(desc.keys.back().time),
      nearPlane_(desc.nearPlane.value_or(defaults.nearPlane)),
      farPlane_(desc.farPlane.value_or(defaults.farPlane)) {
    const std::span<const voxel::PathKey> keys(desc.keys);
    const double defaultFov = desc.fovDegrees.value_or(defaults.fovDegrees);
    size_t first = 0;
    for (size_t i = 1; i <= keys.size(); ++i)
        if (i == keys.size() || keys[i].cut) {
            shots_.emplace_back(keys.subspan(first, i - first), desc, defaultFov);
            first = i;
        }
}

CameraPath::Shot::Shot(std::span<const voxel::PathKey> keys, const voxel::CameraPathDesc& desc, double defaultFov)
    : linear_(desc.interpolation == voxel::PathInterpolation::Linear), constantSpeed_(desc.constantSpeed) {
    std::vector<glm::dvec3> points;
    std::vector<glm::dquat> rotations;
    std::vector<double> fovs;
    for (const voxel::PathKey& k : keys) {
        times_.push_back(k.time);
        points.push_back(k.position);
        rollFree_ = rollFree_ && k.target.has_value();
        rotations.push_back(k.rotation ? *k.rotation : glm::quat_cast(lookAtBasis(k.position, *k.target)));
        fovs.push_back(k.fovDegrees.value_or(defaultFov));
    }
    if (keys.size() == 1) {
        still_ = {points[0], glm::mat3_cast(rotations[0]), fovs[0]};
        return;
    }
    if (linear_) {
        points_ = std::move(points);
        keyRotations_ = std::move(rotations);
        fovs_ = std::move(fovs);
        return;
    }
    curve_ = spline::CentripetalCurve(points);
    rotations_ = spline::RotationSpline(rotations);
    const std::vector<double>& knots = curve_.knots();
    // Keys at their times: a C1 monotone map from time to curve parameter, so the
    // composed position stays C1 in time and never runs backwards.
    timeToCurve_ = spline::MonotoneCubic(times_, knots);
    fov_ = spline::MonotoneCubic(knots, fovs);
    if (!constantSpeed_) return;
    arcKnot_.push_back(knots.front());
    arcLength_.push_back(0.0);
    glm::dvec3 last = curve_(knots.front());
    for (size_t k = 0; k + 1 < knots.size(); ++k)
        for (int i = 1; i <= kArcSamples; ++i) {
            const double s = knots[k] + (knots[k + 1] - knots[k]) * i / kArcSamples;
            const glm::dvec3 p = curve_(s);
            arcKnot_.push_back(s);
            arcLength_.push_back(arcLength_.back() + glm::length(p - last));
            last = p;
        }
}

double CameraPath::Shot::curveParameter(double time) const {
    if (!constantSpeed_ || arcLength_.back() <= 0.0) return timeToCurve_(time);
    const double span = times_.back() - times_.front();
    const double length = arcLength_.back() * std::clamp((time - times_.front()) / span, 0.0, 1.0);
    size_t i = size_t(std::lower_bound(arcLength_.begin(), arcLength_.end(), length) - arcLength_.begin());
    if (i == 0) return arcKnot_.front();
    i = std::min(i, arcLength_.size() - 1);
    const double piece = arcLength_[i] - arcLength_[i - 1];
    const double f = piece > 0.0 ? (length - arcLength_[i - 1]) / piece : 1.0;
    return arcKnot_[i - 1] + f * (arcKnot_[i] - arcKnot_[i - 1]);
}

size_t CameraPath::shotAt(double time) const {
    size_t shot = 0;
    while (shot + 1 < shots_.size() && shots_[shot + 1].start() <= time) ++shot;
    return shot;
}

CameraPose CameraPath::pose(double time) const { return shots_[shotAt(time)].pose(time); }

CameraPose CameraPath::Shot::linearPose(double time) const {
    const size_t k = std::clamp(size_t(std::upper_bound(times_.begin(), times_.end(), time) - times_.begin()),
                                size_t(1), times_.size() - 1) - 1;
    const double u = std::clamp((time - times_[k]) / (times_[k + 1] - times_[k]), 0.0, 1.0);
    CameraPose pose;
    pose.position = glm::mix(points_[k], points_[k + 1], u);
    pose.basis = glm::mat3_cast(glm::slerp(keyRotations_[k], keyRotations_[k + 1], u));  // the short arc
    if (rollFree_) pose.basis = lookAtBasis(pose.position, pose.position - pose.basis[2]);
    pose.fovDegrees = fovs_[k] + (fovs_[k + 1] - fovs_[k]) * u;
    return pose;
}

CameraPose CameraPath::Shot::pose(double time) const {
    if (times_.size() == 1) return still_;
    if (linear_) return linearPose(time);
    const double s = curveParameter(time);
    CameraPose pose;
    pose.position = curve_(s);
    const auto [k, u] = curve_.locate(s);
    pose.basis = glm::mat3_cast(rotations_(k, u));
    // Squad between roll-free rotations is not quite roll-free: keep only its view direction.
    if (rollFree_) pose.basis = lookAtBasis(pose.position, pose.position - pose.basis[2]);
    pose.fovDegrees = fov_(s);
    return pose;
}

Camera CameraPath::camera(double time, uint32_t width, uint32_t height) const {
    const CameraPose p = pose(time);
    Camera c;
    c.position = p.position;
    c.basis = p.basis;
    c.fovY = glm::radians(p.fovDegrees);
    c.nearPlane = nearPlane_;
    c.farPlane = farPlane_;
    c.width = width;
    c.height = height;
    return c;
}

int64_t CameraPath::frameCount(double fps) const {
    // The small slack keeps a path of exactly n/fps seconds at n + 1 frames despite rounding.
    const double n = std::floor(duration() * fps + 1e-9) + 1.0;
    return n < 9e18 ? int64_t(n) : std::numeric_limits<int64_t>::max();
}

}  // namespace grotto
