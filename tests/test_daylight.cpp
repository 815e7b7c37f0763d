// The sun over a day and the sky that follows it (voxel/daylight.h), against
// the spherical astronomy's closed forms: the noon elevation 90 - |phi - d|,
// sunrise at cos h0 = -tan phi tan d in the azimuth cos A = sin d / cos phi,
// the day's length, and the air mass at the horizon.
#include "voxel/daylight.h"

#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include <cmath>

namespace grotto::voxel {
namespace {

constexpr double kDegree = 3.14159265358979323846 / 180.0;

TEST(Daylight, DeclinationReachesTheTropicsAtTheSolsticesAndNoughtAtTheEquinoxes) {
    EXPECT_NEAR(solarDeclination(172), 23.44, 0.01);  // June 21
    EXPECT_NEAR(solarDeclination(355), -23.44, 0.01);  // December 21
    EXPECT_LT(std::abs(solarDeclination(80)), 1.0);     // March 21
    EXPECT_LT(std::abs(solarDeclination(266)), 1.5);    // September 23
}

TEST(Daylight, TheNoonSunStandsAtNinetyLessTheLatitudeFromTheDeclination) {
    for (double latitude : {-70.0, -35.0, 0.0, 23.0, 51.5, 80.0})
        for (double day : {1.0, 80.0, 172.0, 300.0}) {
            const SunPath path{.latitude = latitude, .day = day};
            const glm::dvec3 s = sunDirectionAt(path, 12.0);
            const double d = solarDeclination(day);
            EXPECT_NEAR(elevationDegrees(s), 90.0 - std::abs(latitude - d), 1e-9) << latitude << " " << day;
            // North of the sun's latitude it stands due south (+z with north -z), and due north south of it.
            if (std::abs(latitude - d) > 1e-3) {
                EXPECT_NEAR(s.x, 0.0, 1e-12);
                EXPECT_EQ(s.z > 0.0, latitude > d) << latitude << " " << day;
            }
        }
}

TEST(Daylight, TheSunRisesWhereAndWhenTheClosedFormsSay) {
    for (double latitude : {0.0, 30.0, 51.5, -45.0})
        for (double day : {80.0, 172.0, 355.0}) {
            const SunPath path{.latitude = latitude, .day = day};
            const double phi = latitude * kDegree, d = solarDeclination(day) * kDegree;
            const double h0 = std::acos(-std::tan(phi) * std::tan(d)) / kDegree;  // degrees of hour angle
            const glm::dvec3 rise = sunDirectionAt(path, 12.0 - h0 / 15.0);
            EXPECT_NEAR(rise.y, 0.0, 1e-12) << latitude << " " << day;
            // Azimuth from north (-z) toward east (+x).
            const double azimuth = std::atan2(rise.x, -rise.z) / kDegree;
            EXPECT_NEAR(azimuth, std::acos(std::sin(d) / std::cos(phi)) / kDegree, 1e-9) << latitude << " " << day;
            // The afternoon mirrors the morning across the meridian.
            const glm::dvec3 morning = sunDirectionAt(path, 9.25), afternoon = sunDirectionAt(path, 14.75);
            EXPECT_NEAR(morning.x, -afternoon.x, 1e-12);
            EXPECT_NEAR(morning.y, afternoon.y, 1e-12);
            EXPECT_NEAR(morning.z, afternoon.z, 1e-12);
            EXPECT_GT(morning.x, 0.0) << "the morning sun is in the east";
        }
}

TEST(Daylight, DaysLastEighteenAndAHalfHoursAtSixtyNorthInJune) {
    // Hours with the sun up, counted minute by minute, against daylightHours' closed form.
    auto hoursUp = [](const SunPath& path) {
        int up = 0;
        const int steps = 24 * 600;
        for (int k = 0; k < steps; ++k) up += sunDirectionAt(path, 24.0 * (k + 0.5) / steps).y > 0.0;
        return 24.0 * up / steps;
    };
    auto length = [](const SunPath& path) { return daylightHours(path).set - daylightHours(path).rise; };
    const double d = solarDeclination(172) * kDegree;
    const double expected = 2.0 * std::acos(-std::tan(60.0 * kDegree) * std::tan(d)) / kDegree / 15.0;
    EXPECT_NEAR(expected, 18.5, 0.1);
    for (const SunPath& path : {SunPath{.latitude = 60.0, .day = 172.0}, SunPath{.latitude = 0.0, .day = 172.0},
                                SunPath{.latitude = -35.0, .day = 20.0}})
        EXPECT_NEAR(length(path), hoursUp(path), 0.01) << path.latitude;
    EXPECT_NEAR(length({.latitude = 60.0, .day = 172.0}), expected, 1e-9);
    EXPECT_NEAR(sunDirectionAt({.latitude = 60.0, .day = 172.0}, daylightHours({.latitude = 60.0, .day = 172.0}).rise).y, 0.0, 1e-12);
    EXPECT_NEAR(hoursUp({.latitude = 80.0, .day = 172.0}), 24.0, 1e-9) << "the midnight sun";
    EXPECT_EQ(length({.latitude = 80.0, .day = 172.0}), 24.0);
    EXPECT_NEAR(hoursUp({.latitude = 80.0, .day = 355.0}), 0.0, 1e-9) << "the polar night";
    EXPECT_EQ(length({.latitude = 80.0, .day = 355.0}), 0.0);
}

TEST(Daylight, NorthTurnsThePathAboutTheVertical) {
    const SunPath path{.latitude = 40.0, .day = 120.0}, turned{.latitude = 40.0, .day = 120.0, .north = 90.0};
    for (double hours : {7.0, 12.0, 16.5}) {
        const glm::dvec3 a = sunDirectionAt(path, hours), b = sunDirectionAt(turned, hours);
        // North -z becomes +x: a point (x, z) turns to (-z, x).
        EXPECT_NEAR(b.x, -a.z, 1e-12);
        EXPECT_NEAR(b.z, a.x, 1e-12);
        EXPECT_NEAR(b.y, a.y, 1e-12);
    }
}

TEST(Daylight, TheDiscSetsOverItsOwnDiameter) {
    EXPECT_EQ(discAboveHorizon(-1.0), 0.0);
    EXPECT_NEAR(discAboveHorizon(-0.2665), 0.0, 1e-12);
    EXPECT_NEAR(discAboveHorizon(0.0), 0.5, 1e-12);
    EXPECT_NEAR(discAboveHorizon(0.2665), 1.0, 1e-12);
    EXPECT_EQ(discAboveHorizon(10.0), 1.0);
    // Half the radius up: all but the segment below the chord at half the radius.
    const double segment = (std::acos(0.5) - 0.5 * std::sqrt(0.75)) / 3.14159265358979323846;
    EXPECT_NEAR(discAboveHorizon(0.2665 / 2.0), 1.0 - segment, 1e-12);
    for (double e = -0.3; e < 0.3; e += 0.01) EXPECT_LE(discAboveHorizon(e), discAboveHorizon(e + 0.01));
}

TEST(Daylight, TheAirDimsAndReddensTheLowSun) {
    const glm::dvec3 zenith = airTransmittance(90.0);
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(zenith[c], 1.0, 1e-12);
    // Kasten and Young's air mass at the horizon: 37.9.
    const glm::dvec3 horizon = airTransmittance(0.0);
    EXPECT_NEAR(std::log(horizon.r) / -0.125 + 1.0, 37.92, 0.05);
    EXPECT_NEAR(horizon.r, 0.0099, 0.0005);
    glm::dvec3 before = horizon;
    for (double e = 1.0; e <= 90.0; e += 1.0) {
        const glm::dvec3 t = airTransmittance(e);
        for (int c = 0; c < 3; ++c) EXPECT_GT(t[c], before[c]) << e;
        EXPECT_GT(before.r / before.b, t.r / t.b) << "redder lower, at " << e;
        before = t;
    }
    const glm::dvec3 ten = airTransmittance(10.0);
    EXPECT_NEAR(ten.r, 0.56, 0.01);
    EXPECT_NEAR(ten.g, 0.39, 0.01);
    EXPECT_NEAR(ten.b, 0.17, 0.01);
}

TEST(Daylight, TheSkyDimsFromHighSunToNightThroughItsKeys) {
    const SkyGradient day{{0.28, 0.45, 0.78}, {0.75, 0.82, 0.92}};
    auto luminance = [](const glm::dvec3& c) { return 0.2126 * c.r + 0.7152 * c.g + 0.0722 * c.b; };
    for (double e : {30.0, 45.0, 90.0}) {
        const SkyGradient s = skyAt(day, e);
        EXPECT_EQ(s.zenith, day.zenith);
        EXPECT_EQ(s.horizon, day.horizon);
    }
    for (const SkyKey& k : defaultSkyKeys()) {
        const SkyGradient s = skyAt(day, k.elevation);
        for (int c = 0; c < 3; ++c) {
            EXPECT_NEAR(s.zenith[c], day.zenith[c] * k.scale.zenith[c], 1e-12) << k.elevation;
            EXPECT_NEAR(s.horizon[c], day.horizon[c] * k.scale.horizon[c], 1e-12) << k.elevation;
        }
    }
    EXPECT_EQ(skyAt(day, -40.0).zenith, skyAt(day, -18.0).zenith) << "held below the last key";
    double before = 0.0;
    for (double e = -20.0; e <= 35.0; e += 0.25) {
        const double now = luminance(skyAt(day, e).zenith) + luminance(skyAt(day, e).horizon);
        EXPECT_GE(now, before) << e;
        before = now;
    }
    EXPECT_LT(luminance(skyAt(day, -18.0).zenith), 0.005 * luminance(day.zenith)) << "a night sky";
    // At sunset the horizon is warmer than the zenith, against the day's bluer horizon.
    const SkyGradient sunset = skyAt(day, 0.0);
    EXPECT_GT(sunset.horizon.r / sunset.horizon.b, 2.0 * day.horizon.r / day.horizon.b);
}

void expectSameLight(const Lighting& a, const Lighting& b) {
    EXPECT_EQ(a.sunDirection, b.sunDirection);
    EXPECT_EQ(a.sunColor, b.sunColor);
    EXPECT_EQ(a.skyZenith, b.skyZenith);
    EXPECT_EQ(a.skyHorizon, b.skyHorizon);
    EXPECT_EQ(a.ambientColor, b.ambientColor);
}

TEST(Daylight, AFixedSunIsInEffectAsItIsEvenBelowTheHorizon) {
    Lighting fixed;
    fixed.sunDirection = glm::vec3(0.3f, -0.5f, 0.2f);  // below: a fixed sun is taken as given
    fixed.timeOfDay = 0.0f;                              // the hour is the day's, not a fixed sun's
    expectSameLight(lightingInEffect(fixed), fixed);
}

TEST(Daylight, TheDaysSunStandsOnItsPathDimmedByTheAir) {
    Lighting day;
    day.sunFrom = SunSource::Day;
    day.latitude = 51.5f, day.dayOfYear = 172.0f, day.timeOfDay = 12.0f;
    day.sunColor = glm::vec3(2.0f, 1.8f, 1.5f);
    const Lighting noon = lightingInEffect(day);
    EXPECT_EQ(noon.sunFrom, SunSource::Direction);
    const double e = elevationDegrees(glm::dvec3(noon.sunDirection));
    EXPECT_NEAR(e, 90.0 - std::abs(51.5 - solarDeclination(172.0)), 1e-4);
    const glm::dvec3 air = airTransmittance(e);
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(noon.sunColor[c], day.sunColor[c] * air[c], 1e-5);
    // High sun: the world's own sky (the keys hold above 30 degrees).
    EXPECT_EQ(noon.skyZenith, day.skyZenith);
    EXPECT_EQ(noon.skyHorizon, day.skyHorizon);
    // In effect already: resolving again changes nothing.
    expectSameLight(lightingInEffect(noon), noon);
}

TEST(Daylight, AtMidnightTheSunLightsNothingAndTheSkyIsDark) {
    Lighting day;
    day.sunFrom = SunSource::Day;
    day.latitude = 45.0f, day.dayOfYear = 80.0f, day.timeOfDay = 0.0f;
    day.ambientColor = glm::vec3(0.3f);
    const Lighting night = lightingInEffect(day);
    EXPECT_LT(night.sunDirection.y, -0.7f);  // 45 degrees below, near the equinox
    EXPECT_EQ(night.sunColor, glm::vec3(0.0f));
    for (int c = 0; c < 3; ++c) {
        EXPECT_LT(night.skyZenith[c], 0.005f * day.skyZenith[c]);
        EXPECT_LT(night.ambientColor[c], 0.005f * day.ambientColor[c]);
    }
    // 24 is midnight again.
    day.timeOfDay = 24.0f;
    EXPECT_NEAR(lightingInEffect(day).sunDirection.y, night.sunDirection.y, 1e-5f);
}

}  // namespace
}  // namespace grotto::voxel
