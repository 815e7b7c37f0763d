#pragma once
// The viewer's camera controller: WASD flight and mouse look, or orbiting a point.
// Everything is double precision, so a camera far from the origin moves as exactly
// as one near it; the renderer makes it camera-relative.
#include "voxel/world_desc.h"

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

namespace grotto::viewer {

// One frame's input.
struct FlyInput {
    bool forward = false, back = false, left = false, right = false, up = false, down = false;
    bool fast = false;     // shift: 4x speed
    glm::dvec2 look{0.0};  // mouse motion in pixels while looking (x right, y down)
    double wheel = 0.0;    // notches; each multiplies the speed by 1.25 (up) or divides it
};

inline constexpr double kLookDegreesPerPixel = 0.15;
inline constexpr double kMaxPitchDegrees = 89.0;  // short of straight up/down, where yaw is undefined
inline constexpr double kWheelSpeedFactor = 1.25;
inline constexpr double kFastFactor = 4.0;
// The wheel stops at these speeds (world units per second): a spun wheel never
// leaves a speed that rounds to nothing or overflows.
inline constexpr double kMinFlySpeed = 1e-4, kMaxFlySpeed = 1e8;

// A roll-free camera: a position, a yaw about world Y and a pitch within
// +-kMaxPitchDegrees. Yaw 0 looks down -Z; positive yaw turns right (toward +X).
class FlyCamera {
public:
    // speed: world units per second, clamped to [kMinFlySpeed, kMaxFlySpeed];
    // throws grotto::Error (internal) unless positive and finite.
    FlyCamera(const voxel::CameraDesc& start, double speed);

    // Takes position, direction, fov and planes from `c`; keeps the speed. A
    // target at the position keeps the current direction.
    void jumpTo(const voxel::CameraDesc& c);
    // Flies: forward/back along the view direction, left/right along the view's
    // (horizontal) right, up/down along world Y; several at once share the speed.
    // Look turns first, so the move goes where the frame looks. dt in seconds.
    void update(const FlyInput& in, double dt);
    // Turns the camera about `pivot` by `look` pixels (kLookDegreesPerPixel),
    // keeping its distance and ending up looking at the pivot.
    void orbit(const glm::dvec3& pivot, glm::dvec2 look);

    // target = position + forward (unit); fov and planes as given.
    voxel::CameraDesc desc() const;
    double speed() const { return speed_; }
    const glm::dvec3& position() const { return position_; }
    glm::dvec3 forward() const;  // unit view direction
    glm::dvec3 right() const;    // unit, horizontal

private:
    void lookAt(const glm::dvec3& target);  // yaw and pitch toward target, pitch clamped
    void turn(glm::dvec2 look);             // mouse pixels to yaw and pitch

    glm::dvec3 position_{0.0};
    double yaw_ = 0.0, pitch_ = 0.0;  // radians
    double speed_;
    double fovDegrees_ = 60.0, nearPlane_ = 0.05, farPlane_ = 0.0;
};

}  // namespace grotto::viewer
