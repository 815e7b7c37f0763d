#include "voxel/daylight.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <array>
#include <cmath>

namespace grotto::voxel {
namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kDegree = kPi / 180.0;
constexpr double kSunRadiusDeg = 0.2665;

// Daytime zenith scales follow Preetham's zenith luminance at turbidity 2.5,
// relative to the sun at 30 degrees (0.435 at the horizon, 0.52 at 5, 0.70 at
// 15); twilight's keys are dimmer and bluer overhead, warmer along the horizon,
// but compress the real range (the sky's luminance falls about 1000 times by
// -6 degrees, here 30 times) so twilight lasts; by -18 the sky is 1/300 of the
// day's: dark at a day's exposure, seen at a night's.
constexpr std::array<SkyKey, 8> kKeys{{
    {-18.0, {{0.002, 0.0025, 0.004}, {0.002, 0.0022, 0.003}}},
    {-12.0, {{0.006, 0.008, 0.014}, {0.008, 0.008, 0.011}}},
    {-6.0, {{0.03, 0.035, 0.06}, {0.07, 0.05, 0.05}}},
    {-2.0, {{0.15, 0.16, 0.24}, {0.35, 0.22, 0.15}}},
    {0.0, {{0.40, 0.42, 0.48}, {0.70, 0.45, 0.28}}},
    {5.0, {{0.50, 0.52, 0.56}, {0.85, 0.66, 0.48}}},
    {15.0, {{0.69, 0.70, 0.72}, {0.95, 0.88, 0.80}}},
    {30.0, {{1.0, 1.0, 1.0}, {1.0, 1.0, 1.0}}},
}};

// Linear in `t` between the logarithms of a and b.
glm::dvec3 logLerp(const glm::dvec3& a, const glm::dvec3& b, double t) {
    return glm::exp(glm::log(a) * (1.0 - t) + glm::log(b) * t);
}

}  // namespace

double solarDeclination(double day) { return -23.44 * std::cos(2.0 * kPi * (day + 10.0) / 365.0); }

glm::dvec3 sunDirectionAt(const SunPath& path, double hours) {
    const double phi = path.latitude * kDegree, d = solarDeclination(path.day) * kDegree;
    const double h = 15.0 * (hours - 12.0) * kDegree;
    const double up = std::sin(phi) * std::sin(d) + std::cos(phi) * std::cos(d) * std::cos(h);
    const double east = -std::cos(d) * std::sin(h);
    const double north = std::cos(phi) * std::sin(d) - std::sin(phi) * std::cos(d) * std::cos(h);
    const double a = path.north * kDegree;
    const glm::dvec3 northAxis(std::sin(a), 0.0, -std::cos(a)), eastAxis(std::cos(a), 0.0, std::sin(a));
    return glm::normalize(east * eastAxis + north * northAxis + glm::dvec3(0.0, up, 0.0));
}

Daylight daylightHours(const SunPath& path) {
    const double c = -std::tan(path.latitude * kDegree) * std::tan(solarDeclination(path.day) * kDegree);
    if (c <= -1.0) return {0.0, 24.0};
    if (c >= 1.0) return {12.0, 12.0};
    const double halfDay = std::acos(c) / kDegree / 15.0;
    return {12.0 - halfDay, 12.0 + halfDay};
}

double sunPositionHour(const SunPath& path, int position, int count) {
    const Daylight d = daylightHours(path);
    return d.rise + (d.set - d.rise) * double(position) / double(count - 1);
}

SunPositionSpan sunPositionSpan(const SunPath& path, double hours, int count) {
    const Daylight d = daylightHours(path);
    const double at = d.set > d.rise ? std::clamp((hours - d.rise) / (d.set - d.rise), 0.0, 1.0) * (count - 1) : 0.0;
    const int before = std::min(int(at), count - 2);
    return {before, at - before, !(hours >= d.rise && hours <= d.set)};
}

double elevationDegrees(const glm::dvec3& towardSun) { return std::asin(std::clamp(towardSun.y, -1.0, 1.0)) / kDegree; }

double discAboveHorizon(double elevationDeg) {
    const double d = std::clamp(elevationDeg / kSunRadiusDeg, -1.0, 1.0);
    // The disc (radius 1, centre at height d) above the line: all of it but the
    // circular segment below, acos(d) - d sqrt(1 - d^2) of its area pi.
    return 1.0 - (std::acos(d) - d * std::sqrt(1.0 - d * d)) / kPi;
}

namespace {

// Kasten and Young's relative air mass; 0.99971 at the zenith, not quite 1.
double airMass(double elevationDeg) {
    const double e = std::max(elevationDeg, 0.0);
    return 1.0 / (std::sin(e * kDegree) + 0.50572 * std::pow(e + 6.07995, -1.6364));
}

}  // namespace

glm::dvec3 airTransmittance(double elevationDeg) {
    const glm::dvec3 tau(0.125, 0.206, 0.386);
    return glm::exp(-tau * (airMass(elevationDeg) - airMass(90.0)));
}

std::span<const SkyKey> defaultSkyKeys() { return kKeys; }

SkyGradient skyAt(const SkyGradient& day, double elevationDeg, std::span<const SkyKey> keys) {
    SkyGradient scale = keys.front().scale;
    if (elevationDeg >= keys.back().elevation) {
        scale = keys.back().scale;
    } else if (elevationDeg > keys.front().elevation) {
        const auto next = std::upper_bound(keys.begin(), keys.end(), elevationDeg,
                                           [](double e, const SkyKey& k) { return e < k.elevation; });
        const SkyKey& lo = *(next - 1);
        const double t = (elevationDeg - lo.elevation) / (next->elevation - lo.elevation);
        scale = {logLerp(lo.scale.zenith, next->scale.zenith, t), logLerp(lo.scale.horizon, next->scale.horizon, t)};
    }
    return {day.zenith * scale.zenith, day.horizon * scale.horizon};
}

SunPath sunPathOf(const Lighting& l) {
    return {.latitude = double(l.latitude), .day = double(l.dayOfYear), .north = double(l.north)};
}

Lighting lightingInEffect(const Lighting& l) {
    if (l.sunFrom != SunSource::Day) return l;
    Lighting now = l;
    now.sunFrom = SunSource::Direction;
    const glm::dvec3 toward = sunDirectionAt(sunPathOf(l), double(l.timeOfDay));
    const double elevation = elevationDegrees(toward);
    now.sunDirection = glm::vec3(toward);
    now.sunColor = glm::vec3(glm::dvec3(l.sunColor) * airTransmittance(elevation) * discAboveHorizon(elevation));
    const SkyGradient unit{glm::dvec3(1.0), glm::dvec3(1.0)};
    const SkyGradient scale = skyAt(unit, elevation);
    now.skyZenith = glm::vec3(glm::dvec3(l.skyZenith) * scale.zenith);
    now.skyHorizon = glm::vec3(glm::dvec3(l.skyHorizon) * scale.horizon);
    now.ambientColor = glm::vec3(glm::dvec3(l.ambientColor) * scale.zenith);
    return now;
}

}  // namespace grotto::voxel
