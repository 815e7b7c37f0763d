#pragma once
// The sun and sky at a time of day: where the sun stands over a day at a
// latitude, how the air it shines through dims and reddens it, and the sky
// gradient that follows it from noon to night. Pure functions of the hour.
//
// World axes: y up; north is `SunPath::north` degrees from -z toward +x (0:
// north is -z and east is +x, as a map drawn looking down).
#include "grotto/settings.h"

#include <glm/vec3.hpp>

#include <span>

namespace grotto::voxel {

// The day's path of the sun.
struct SunPath {
    double latitude = 45.0;  // degrees, -90 (south pole) to 90
    double day = 80.0;       // day of the year, 1 to 365 (80: the March equinox)
    double north = 0.0;      // degrees from -z toward +x
    bool operator==(const SunPath&) const = default;
};

// The sun's declination on `day` in degrees: -23.44 cos(360 (day + 10) / 365),
// the circular-orbit approximation (within 1.5 degrees of the ephemeris all year).
double solarDeclination(double day);

// Unit vector toward the sun at `hours` of local solar time (12: noon), from
// the hour angle h = 15 (hours - 12) degrees, latitude phi and declination d:
//   up    = sin phi sin d + cos phi cos d cos h
//   east  = -cos d sin h
//   north = cos phi sin d - sin phi cos d cos h
// Below the horizon too (up < 0): the night's sun, which lights nothing.
glm::dvec3 sunDirectionAt(const SunPath& path, double hours);

// The hours of local solar time the sun's centre is above a flat horizon on the
// path's day: h0 = acos(-tan phi tan d) either side of noon, {0, 24} in a polar
// day and {12, 12} in a polar night.
struct Daylight {
    double rise = 0.0, set = 24.0;
};
Daylight daylightHours(const SunPath& path);

// The day's sun positions a face cache keeps (docs/face-cache.md, "The day's
// sun"): `count` (>= 2) evenly spaced in hour from sunrise to sunset, the first
// at sunrise and the last at sunset, and the hour of each.
double sunPositionHour(const SunPath& path, int position, int count);
// Where the hour `hours` falls among them: the position at or before it (0 to
// count - 2) and how far on toward the next (0 to 1), clamped to the day;
// `beyond`: the hour lies before sunrise or after sunset.
struct SunPositionSpan {
    int before = 0;
    double toward = 0.0;
    bool beyond = false;
};
SunPositionSpan sunPositionSpan(const SunPath& path, double hours, int count);

// The sun's elevation above the horizon in degrees, for a unit direction.
double elevationDegrees(const glm::dvec3& towardSun);

// The share of the sun's disc (angular radius 0.2665 degrees) above a flat
// horizon at `elevation` degrees: 0 below -0.2665, 1 above +0.2665, the circular
// segment's area between. The sun fades out as it sets, not at once.
double discAboveHorizon(double elevationDeg);

// The clear air's transmittance of the sun's beam per RGB channel at `elevation`
// degrees, relative to the sun at the zenith (1 there): exp(-tau (m - m_zenith)) with
// the relative air mass m of Kasten and Young (1989),
//   m = 1 / (sin e + 0.50572 (e + 6.07995)^-1.6364),
// and optical depths tau = (0.125, 0.206, 0.386) for red, green and blue:
// Rayleigh scattering at 680, 550 and 440 nm plus a light aerosol (Angstrom
// beta 0.05, alpha 1.3). At 10 degrees the beam is (0.56, 0.39, 0.17) of the
// zenith's; at the horizon (m = 38) red keeps 1%, blue nothing.
glm::dvec3 airTransmittance(double elevationDeg);

// A sky gradient: the colours at the zenith and on the horizon, the two the
// cached sky light is weighted by (so re-colouring it needs no rays).
struct SkyGradient {
    glm::dvec3 zenith{0.0}, horizon{0.0};
};

// One key of the sky over the day: its gradient, times the world's own, when
// the sun stands at `elevation` degrees.
struct SkyKey {
    double elevation;
    SkyGradient scale;
};

// The default keys, from night (-18 degrees, astronomical twilight's end) to
// high sun (30 degrees and up: the world's own gradient).
std::span<const SkyKey> defaultSkyKeys();

// The world's gradient `day` (its sky at high sun) at a sun `elevation`
// degrees: each colour times the keys' scale, interpolated linearly in
// elevation and in the logarithm of each channel (the sky dims by orders of
// magnitude through twilight); held beyond the first and last keys.
SkyGradient skyAt(const SkyGradient& day, double elevationDeg, std::span<const SkyKey> keys = defaultSkyKeys());

// The day's path a lighting states (its latitude, day of the year and north).
SunPath sunPathOf(const Lighting& lighting);

// The light in effect: `lighting` itself for a fixed sun; for the day's sun
// (SunSource::Day), a fixed sun at its time: the direction on the path; the
// colour times airTransmittance and discAboveHorizon (so 0 at night); the sky
// gradient by skyAt; the constant ambient by the sky's zenith scale. What the
// renderer, the bake and the path tracer all light with.
Lighting lightingInEffect(const Lighting& lighting);

}  // namespace grotto::voxel
