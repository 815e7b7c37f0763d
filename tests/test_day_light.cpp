// Full light over the day (voxel/light_bake.h with the day's sun): the light
// kept by source, summed at an hour's colours, against a bake with the sun held
// at that hour; and the file's round trip of each face's day words.
#include "dense_world.h"
#include "grotto/error.h"
#include "tests/test_util.h"
#include "voxel/brick_table.h"
#include "voxel/face_bake.h"
#include "voxel/face_cache_edit.h"
#include "voxel/face_cache_file.h"
#include "voxel/light_bake.h"
#include "voxel/light_edit.h"
#include "voxel/luminance.h"
#include "voxel/path_trace.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <vector>

namespace grotto::voxel {
namespace {

using glm::dvec3;

// A room 18 x 10 x 18 with a window in its roof and one in its south wall (+z),
// a reddish floor and a lamp in a corner: at each hour the sun lights another
// patch, and the walls take their light off it.
World dayRoom() {
    Material wall, floor, lamp;
    wall.albedo = glm::vec3(0.6f);
    floor.albedo = glm::vec3(0.8f, 0.45f, 0.25f);
    lamp.albedo = glm::vec3(0.5f), lamp.emissionColor = glm::vec3(1.0f, 0.8f, 0.5f), lamp.emissionIntensity = 4.0f;
    const glm::ivec3 size(18, 10, 18);
    WorldDesc desc;  // lit by the day's sun (kPath) and baked in full, as the edits read it
    desc.lighting.sunFrom = SunSource::Day, desc.lighting.ambientFrom = AmbientSource::Full;
    desc.lighting.latitude = 45.0f, desc.lighting.dayOfYear = 80.0f, desc.lighting.north = 0.0f;
    return grotto::voxel::test::denseWorld(size, {wall, floor, lamp}, [&](int x, int y, int z) {
        if (y == 9 && x >= 7 && x <= 10 && z >= 5 && z <= 8) return 0;      // the roof's window
        if (z == 17 && x >= 5 && x <= 12 && y >= 2 && y <= 5) return 0;     // the south wall's
        if (x == 1 && y == 1 && z == 1) return 3;                            // the lamp
        if (y == 0) return 2;
        return x == 0 || y == 9 || z == 0 || x == 17 || z == 17 ? 1 : 0;
    }, desc);
}

const SunPath kPath{45.0, 80.0, 0.0};  // the March equinox: the sun from the east through the south to the west

struct Baked {
    std::vector<ExposedFace> faces;
    std::vector<FaceTexel> texels;
    std::vector<glm::vec3> dayLight;
};

LightSources skyOnly() {
    LightSources l;
    l.skyZenith = dvec3(0.25, 0.45, 0.9), l.skyHorizon = dvec3(0.8, 0.85, 0.95), l.skyIntensity = 1.0;
    return l;
}

// Baked for the whole day: the texels' bits, and the light by source.
Baked bakeDay(const World& world) {
    const BrickTable table(world);
    Baked b;
    b.faces = exposedFaces(table, world);
    b.texels.resize(b.faces.size() * 9);
    b.dayLight.resize(b.faces.size() * kDayLightWords);
    FaceBakeSettings s;
    s.day = kPath;
    bakeFaces(table, world, b.faces, s, b.texels);
    LightSources lights = skyOnly();
    lights.day = kPath;
    bakeLight(table, world, b.faces, 3, lights, {}, b.texels, {}, b.dayLight);
    return b;
}

// Baked with the sun held toward `sun` at radiance `radiance`.
Baked bakeHeld(const World& world, dvec3 sun, dvec3 radiance) {
    const BrickTable table(world);
    Baked b;
    b.faces = exposedFaces(table, world);
    b.texels.resize(b.faces.size() * 9);
    FaceBakeSettings s;
    s.sunDirection = sun;
    bakeFaces(table, world, b.faces, s, b.texels);
    LightSources lights = skyOnly();
    lights.sunDirection = sun, lights.sun = radiance;
    bakeLight(table, world, b.faces, 3, lights, {}, b.texels);
    return b;
}

// Each face's mean light (irradiance over pi, but the sun's direct beam) from
// the day's bake at continuous position `at` under a sun of `radiance`: its
// glowing faces' light, the sky's through its weights and its words, and the
// sun's interpolated between the bounce positions.
std::vector<glm::dvec3> dayFaceLight(const Baked& day, double at, dvec3 radiance) {
    const LightSources sky = skyOnly();
    const DayBounceSpan span = dayBounceSpan(at);
    std::vector<glm::dvec3> out(day.faces.size(), glm::dvec3(0.0));
    for (size_t f = 0; f < day.faces.size(); ++f) {
        const glm::vec3* w = &day.dayLight[f * kDayLightWords];
        const glm::dvec3 sun = glm::mix(glm::dvec3(w[2 + span.before]), glm::dvec3(w[2 + span.after]), span.toward);
        for (size_t t = f * 9; t < f * 9 + 9; ++t) {
            const FaceTexel& x = day.texels[t];
            const double n = double(x.samples);
            out[f] += (glm::dvec3(x.light) + sky.skyZenith * (x.skyZenith / n) + sky.skyZenith * glm::dvec3(w[0]) +
                       sky.skyHorizon * (x.skyHorizon / n) + sky.skyHorizon * glm::dvec3(w[1]) + radiance * sun) /
                      9.0;
        }
    }
    return out;
}

std::vector<glm::dvec3> heldFaceLight(const Baked& held) {
    std::vector<glm::dvec3> out(held.faces.size(), glm::dvec3(0.0));
    for (size_t t = 0; t < held.texels.size(); ++t) out[t / 9] += glm::dvec3(held.texels[t].light) / 9.0;
    return out;
}

// Each face's relative error in luminance, over the faces inside the room that
// hold at least a tenth of the room's mean light.
std::vector<double> relativeErrors(const Baked& baked, const std::vector<glm::dvec3>& a, const std::vector<glm::dvec3>& b) {
    double mean = 0.0;
    size_t inside = 0;
    auto isInside = [&](size_t f) {
        const glm::ivec3 open = baked.faces[f].cell + glm::ivec3(faceNormal(baked.faces[f].dir));
        return open.x > 0 && open.x < 17 && open.y > 0 && open.y < 9 && open.z > 0 && open.z < 17;
    };
    for (size_t f = 0; f < a.size(); ++f)
        if (isInside(f)) mean += luminance(b[f]), ++inside;
    mean /= double(std::max<size_t>(inside, 1));
    std::vector<double> errors;
    for (size_t f = 0; f < a.size(); ++f)
        if (isInside(f) && luminance(b[f]) > 0.1 * mean)
            errors.push_back(std::abs(luminance(a[f]) - luminance(b[f])) / luminance(b[f]));
    std::sort(errors.begin(), errors.end());
    return errors;
}

double quantile(const std::vector<double>& sorted, double q) { return sorted[size_t(q * double(sorted.size() - 1))]; }

// The room's bake for the day, made once for the tests that start from it.
const Baked& roomsDay() {
    static const Baked day = bakeDay(dayRoom());
    return day;
}

TEST(DayLight, AnyHoursLightIsTheLightOfTheSunHeldThere) {
    // At a bounce position the day's light is the held sun's but for the two
    // bakes' own noise (they draw toward other faces, and a held sun's texels
    // see it over their whole square); between two it is interpolated. Without
    // the sun's bounce the faces would be off by 36-47% (median).
    const World room = dayRoom();
    const Baked& day = roomsDay();
    const std::vector<dvec3> directions = daySunDirections(kPath);
    const dvec3 radiance(2.0, 1.8, 1.5);
    struct Hour {
        uint32_t position;
        double median, high;  // the most the faces' median and 95th percentile errors may be
    };
    std::vector<Hour> hours = {{dayBouncePosition(8), 0.02, 0.06}, {11, 0.03, 0.08}, {20, 0.03, 0.08}};
    hours.resize(size_t(grotto::test::underSanitizers(3, 1)));  // each held bake takes seconds there
    for (const Hour& h : hours) {
        const Baked held = bakeHeld(room, directions[h.position], radiance);
        const std::vector<double> errors =
            relativeErrors(day, dayFaceLight(day, double(h.position), radiance), heldFaceLight(held));
        ASSERT_GE(errors.size(), 200u);
        std::printf("position %u (%.2f h): %zu faces, median %.2f%%, 95th %.2f%%, worst %.2f%%\n", h.position,
                    sunPositionHour(kPath, int(h.position), int(kDaySunPositions)), errors.size(),
                    100 * quantile(errors, 0.5), 100 * quantile(errors, 0.95), 100 * errors.back());
        EXPECT_LT(quantile(errors, 0.5), h.median);
        EXPECT_LT(quantile(errors, 0.95), h.high);
    }
}

TEST(DayLight, AnEditLightsTheWordsAgainAsAFreshBakeWould) {
    // The roof's window closed: the patch it threw on the floor goes, and the
    // walls it lit darken at every hour the sun stood over it. Then the edited
    // cache's faces, as LiveFaceCache edits them, against a fresh bake's.
    World room = dayRoom();
    Baked day = roomsDay();
    BrickTable table(room);
    FaceBakeSettings s;
    s.day = kPath, s.fullLight = true;
    const EditResult result = room.apply(Edit::fillBox({{7, 9, 5}, {10, 9, 8}}, 1));
    table.update(room, result.voxels);
    const std::vector<ExposedFace> before = day.faces;
    const std::vector<glm::vec3> sentBefore = sentLight(room, day.faces, day.texels, 3, day.dayLight);
    std::vector<FaceReach> reach;
    updateAfterEdit(table, room, result.voxels, s, day.faces, day.texels, nullptr, true, &reach);
    day.dayLight = carriedDayLight(before, day.faces, day.dayLight);
    const RelightStats relit = relightAfterEdit(table, room, day.faces, 3, day.texels, reach, result.voxels, before,
                                                sentBefore, glowingFaces(room, before), day.dayLight);
    const Baked fresh = bakeDay(room);
    ASSERT_EQ(fresh.faces, day.faces);
    const dvec3 radiance(2.0, 1.8, 1.5);
    for (const uint32_t position : {dayBouncePosition(4), 15u}) {
        const std::vector<double> errors =
            relativeErrors(day, dayFaceLight(day, double(position), radiance), dayFaceLight(fresh, double(position), radiance));
        std::printf("[ measured ] %llu faces lit again; position %u: median %.2f%%, 95th %.2f%%, worst %.2f%%\n",
                    (unsigned long long)relit.faces, position, 100 * quantile(errors, 0.5), 100 * quantile(errors, 0.95),
                    100 * errors.back());
        EXPECT_LT(quantile(errors, 0.5), 0.02);
        EXPECT_LT(quantile(errors, 0.95), 0.06);
    }
}

TEST(DayLight, TheFileKeepsEachFacesDayWordsAndRefusesBadOnes) {
    const grotto::test::ScratchDir dir;
    FaceCacheFile c;
    c.header.key = {.voxelHash = 1, .radiusVoxels = 4.0, .texelsPerSide = 3, .day = kPath, .lightHash = 7};
    c.header.rays = 64, c.header.totalFaces = c.header.faceCount = 2;
    c.texels.resize(18);
    for (size_t t = 0; t < c.texels.size(); ++t) {
        FaceTexel& x = c.texels[t];
        x.samples = 64, x.open = 32, x.skyZenith = 20.0f, x.skyHorizon = 10.0f, x.light = glm::vec3(0.5f);
        x.daySun = uint32_t(t * 0x9e3779b9u), x.dayPositions = kDaySunPositions;
    }
    for (size_t w = 0; w < 2 * kDayLightWords; ++w) c.dayLight.push_back(glm::vec3(float(w), 0.25f * float(w), 1.0f));
    saveFaceCache(c, dir / "day.gfc");
    const FaceCacheFile back = loadFaceCache(dir / "day.gfc");
    EXPECT_EQ(back.texels, c.texels);
    EXPECT_EQ(back.dayLight, c.dayLight);
    EXPECT_EQ(std::filesystem::file_size(dir / "day.gfc"), 132u + 18u * 40u + 2u * kDayLightWords * 12u);

    // A file cut short of its day words, and a day word that is negative.
    std::filesystem::copy_file(dir / "day.gfc", dir / "short.gfc");
    std::filesystem::resize_file(dir / "short.gfc", std::filesystem::file_size(dir / "day.gfc") - 12);
    EXPECT_THROW(
        try { readFaceCacheHeader(dir / "short.gfc"); } catch (const Error& e) {
            EXPECT_NE(std::string(e.what()).find("texels: the file holds"), std::string::npos) << e.what();
            throw;
        },
        Error);
    c.dayLight[kDayLightWords + 3].g = -1.0f;
    saveFaceCache(c, dir / "negative.gfc");
    EXPECT_THROW(
        try { loadFaceCache(dir / "negative.gfc"); } catch (const Error& e) {
            EXPECT_NE(std::string(e.what()).find("day's light of face 1: negative"), std::string::npos) << e.what();
            throw;
        },
        Error);
}

}  // namespace
}  // namespace grotto::voxel
