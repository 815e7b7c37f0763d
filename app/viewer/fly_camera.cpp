#include "app/viewer/fly_camera.h"

#include "grotto/error.h"
#include "engine/camera.h"

#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

#include <algorithm>
#include <cmath>

namespace grotto::viewer {

FlyCamera::FlyCamera(const voxel::CameraDesc& start, double speed) {
    if (!(speed > 0.0) || !std::isfinite(speed))
        throw Error::internal("FlyCamera", "speed " + std::to_string(speed) + " is not a positive finite number");
    speed_ = std::clamp(speed, kMinFlySpeed, kMaxFlySpeed);
    jumpTo(start);
}

void FlyCamera::jumpTo(const voxel::CameraDesc& c) {
    position_ = c.position;
    fovDegrees_ = c.fovDegrees;
    nearPlane_ = c.nearPlane;
    farPlane_ = c.farPlane;
    lookAt(c.target);
}

void FlyCamera::lookAt(const glm::dvec3& target) {
    const glm::dvec3 d = target - position_;
    const double horizontal = std::hypot(d.x, d.z), length = std::hypot(horizontal, d.y);  // no underflow
    if (!(length > 0.0) || !std::isfinite(length)) return;  // no direction: keep the current one
    if (horizontal > 1e-9 * length) {
        yaw_ = std::atan2(d.x, -d.z);
    } else {
        // Straight up or down: the heading makeCamera gives (lookAtBasis's fallback
        // right vector), so the desc looks the same here and in a render.
        const glm::dvec3 r = lookAtBasis(glm::dvec3(0.0), glm::dvec3(0.0, d.y > 0.0 ? 1.0 : -1.0, 0.0))[0];
        yaw_ = std::atan2(r.z, r.x);  // right = (cos yaw, 0, sin yaw)
    }
    const double limit = glm::radians(kMaxPitchDegrees);
    pitch_ = std::clamp(std::atan2(d.y, horizontal), -limit, limit);
}

void FlyCamera::turn(glm::dvec2 look) {
    if (!std::isfinite(look.x) || !std::isfinite(look.y)) return;
    const double perPixel = glm::radians(kLookDegreesPerPixel), limit = glm::radians(kMaxPitchDegrees);
    // Wrapped to [-pi, pi] so a long session never loses precision in the angle.
    yaw_ = std::remainder(yaw_ + look.x * perPixel, 2.0 * glm::pi<double>());
    pitch_ = std::clamp(pitch_ - look.y * perPixel, -limit, limit);  // mouse down looks down
}

glm::dvec3 FlyCamera::forward() const {
    return {std::sin(yaw_) * std::cos(pitch_), std::sin(pitch_), -std::cos(yaw_) * std::cos(pitch_)};
}

glm::dvec3 FlyCamera::right() const { return {std::cos(yaw_), 0.0, std::sin(yaw_)}; }

void FlyCamera::update(const FlyInput& in, double dt) {
    turn(in.look);
    if (std::isfinite(in.wheel))
        speed_ = std::clamp(speed_ * std::pow(kWheelSpeedFactor, in.wheel), kMinFlySpeed, kMaxFlySpeed);
    glm::dvec3 move(0.0);
    if (in.forward) move += forward();
    if (in.back) move -= forward();
    if (in.right) move += right();
    if (in.left) move -= right();
    if (in.up) move.y += 1.0;
    if (in.down) move.y -= 1.0;
    const double length = glm::length(move);
    if (!(dt > 0.0) || !std::isfinite(dt) || length < 1e-9) return;  // nothing held, or opposite keys cancel
    const double distance = speed_ * (in.fast ? kFastFactor : 1.0) * dt;
    // Added to the double position in one step: no float on the way, so the move
    // is as exact at 1e6 units as at the origin.
    position_ += move * (distance / length);
}

void FlyCamera::orbit(const glm::dvec3& pivot, glm::dvec2 look) {
    const double distance = glm::length(position_ - pivot);
    if (!(distance > 0.0)) {  // at the pivot: nothing to turn about, so look around in place
        turn(look);
        return;
    }
    lookAt(pivot);
    turn(look);
    position_ = pivot - forward() * distance;
}

voxel::CameraDesc FlyCamera::desc() const {
    return {.position = position_, .target = position_ + forward(), .fovDegrees = fovDegrees_,
            .nearPlane = nearPlane_, .farPlane = farPlane_};
}

}  // namespace grotto::viewer
