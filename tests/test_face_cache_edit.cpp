// The face cache after edits, and for the day's moving sun (voxel/face_cache_edit.h,
// voxel/face_bake.h, voxel/face_cache_file.h): random carves and fills retrace
// exactly what they reach, for one sun and along the day's path; the day's bits
// are exact rays from each texel's centre; a day bake's file keeps its path and
// bits, and is refused for another day or a fixed sun.
#include "grotto/error.h"
#include "tests/face_cache_worlds.h"
#include "tests/test_util.h"
#include "voxel/brick_table.h"
#include "voxel/face_cache_edit.h"
#include "voxel/face_cache_file.h"

#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include <algorithm>
#include <bit>
#include <cstdio>
#include <filesystem>
#include <random>

namespace grotto::voxel {
namespace {

// Random carves and fills of a random world baked with `s`: after each, every
// texel is either carried over bit for bit, and then a fresh bake of the edited
// world gives it the AO and sun a fresh bake before the edit did (and the same
// sky, unless the rule left its sky for later, off by little), or traced again
// and equal to the fresh bake.
void checkEditsRetraceWhatTheyReach(const FaceBakeSettings& s, int edits = 6) {
    std::mt19937 rng(25);
    World w = grotto::test::randomWorld(28, 0.08, rng);
    BrickTable table(w);
    std::vector<ExposedFace> faces = exposedFaces(table, w);
    std::vector<FaceTexel> texels = grotto::test::bakeAll(w, faces, s), truth = texels;  // truth: a fresh bake of the world now
    std::uniform_int_distribution<int> at(0, 27), extent(0, 4);
    size_t carried = 0, retraced = 0, far = 0;
    double farError = 0.0;
    for (int e = 0; e < edits; ++e) {
        const glm::ivec3 lo(at(rng), at(rng), at(rng));
        const IndexBox box{lo, glm::min(lo + glm::ivec3(extent(rng), extent(rng), extent(rng)), glm::ivec3(27))};
        const EditResult result = w.apply(e % 2 ? Edit::fillBox(box, 1) : Edit::carveBox(box));
        ASSERT_FALSE(result.voxels.empty());
        table.update(w, result.voxels);
        const std::vector<ExposedFace> before = faces;
        const std::vector<FaceTexel> old = texels;
        CacheEditStats stats;
        updateAfterEdit(table, w, result.voxels, s, faces, texels, &stats);
        ASSERT_EQ(faces, exposedFaces(table, w));
        const std::vector<FaceTexel> fresh = grotto::test::bakeAll(w, faces, s);
        const uint32_t perFace = 4;
        size_t tracedFaces = 0;
        for (size_t f = 0; f < faces.size(); ++f) {
            const auto it = std::lower_bound(before.begin(), before.end(), faces[f]);
            const bool existed = it != before.end() && *it == faces[f];
            bool stale = !existed;
            for (uint32_t t = 0; t < perFace && existed; ++t)
                stale |= staleAfterEdit(texelPoint(faces[f], 2, t % 2, t / 2), faces[f].dir, result.voxels, s, 1.0).now();
            tracedFaces += stale;
            for (uint32_t t = 0; t < perFace; ++t) {
                const size_t i = f * perFace + t;
                if (stale) {
                    ASSERT_EQ(texels[i], fresh[i]) << "edit " << e << ", face " << f << " traced again";
                    ++retraced;
                    continue;
                }
                const size_t j = size_t(it - before.begin()) * perFace + t;
                ASSERT_EQ(texels[i], old[j]) << "edit " << e << ", face " << f << " carried over";
                const FaceTexel& was = truth[j];
                ASSERT_EQ(fresh[i].open, was.open) << "edit " << e << ", face " << f << ": AO the rule missed";
                ASSERT_EQ(fresh[i].sunOpen, was.sunOpen) << "edit " << e << ", face " << f << ": sun the rule missed";
                ASSERT_EQ(fresh[i].daySun, was.daySun) << "edit " << e << ", face " << f << ": the day's sun the rule missed";
                ++carried;
                const bool skyFar =
                    staleAfterEdit(texelPoint(faces[f], 2, t % 2, t / 2), faces[f].dir, result.voxels, s, 1.0).skyFar;
                if (!skyFar) {
                    ASSERT_EQ(fresh[i], was) << "edit " << e << ", face " << f << ": sky the rule missed";
                    continue;
                }
                ++far;
                farError += std::abs(double(fresh[i].skyHorizon + fresh[i].skyZenith) -
                                     double(was.skyHorizon + was.skyZenith)) / was.samples;
            }
        }
        truth = fresh;
        EXPECT_EQ(stats.traced, tracedFaces);
        EXPECT_EQ(stats.carried, faces.size() - tracedFaces);
    }
    std::printf("[ measured ] %d edits: %zu texels carried, %zu traced again, %zu with their sky left for later\n", edits,
                carried, retraced, far);
    EXPECT_GT(carried, 10 * retraced / 4);  // most of the world untouched
    EXPECT_GT(retraced, 500u);
    ASSERT_GT(far, 100u);
    // Left for later, the far texels' sky is off by less than the rule's bound on average.
    EXPECT_LT(farError / double(far), kSkyStaleShare);
}

// Under the sanitizers 3 random edits, not 6 (each is checked against a fresh
// bake of the whole world, which was the time), as for the day's sun below.
TEST(FaceCache, AnEditRetracesWhatItCanReachAndTouchesNothingElse) {
    checkEditsRetraceWhatTheyReach({.radius = 2.0, .texelsPerSide = 2, .rays = 12, .sunRays = 3,
                                    .sunDirection = glm::normalize(glm::dvec3(0.3, 0.9, -0.2)), .sunAngleDegrees = 4.0},
                                   grotto::test::underSanitizers(6, 3));
}

// An edit's faces listed again near it alone (what a live cache does each edit)
// are the world's listed afresh, across fills, carves, spheres and paints
// inside, across and outside the world, and a box larger than the world.
TEST(FaceCache, TheFacesAfterAnEditAreTheWorldsListedAfresh) {
    std::mt19937 rng(71);
    for (double density : {0.1, 0.5, 0.9}) {
        World w = grotto::test::randomWorld(20, density, rng);
        std::vector<ExposedFace> faces = exposedFaces(w);
        std::uniform_int_distribution<int> at(-4, 22), size(0, 6), op(0, 4);
        for (int e = 0; e < 30; ++e) {
            const glm::ivec3 lo(at(rng), at(rng), at(rng));
            const IndexBox box{lo, lo + glm::ivec3(size(rng), size(rng), size(rng))};
            const glm::dvec3 centre = w.origin() + (glm::dvec3(lo) + 0.5) * w.voxelSize();
            const int o = e == 29 ? 5 : op(rng);
            const Edit edit = o == 0   ? Edit::fillBox(box, 1)
                              : o == 1 ? Edit::carveBox(box)
                              : o == 2 ? Edit::carveSphere(centre, 3.5 * w.voxelSize())
                              : o == 3 ? Edit::fillSphere(centre, 2.5 * w.voxelSize(), 1)
                              : o == 4 ? Edit{.op = Edit::Op::Paint, .box = box, .material = 1}
                                       : Edit::carveBox({{-30, -30, -30}, {50, 50, 50}});  // the whole world
            const EditResult r = w.apply(edit);
            faces = exposedFacesAfterEdit(BrickTable(w), w, faces, r.voxels);
            ASSERT_EQ(faces, exposedFaces(w)) << "density " << density << ", edit " << e << " (op " << o << ")";
        }
        EXPECT_TRUE(faces.empty());
    }
}

// A face judged whole from its centre is judged as its texels are, one by one:
// random faces of a world 64 voxels wide, random boxes inside it and beyond, for
// a point sun and discs of several sizes, AO radii from a tenth of a voxel to 12
// voxels and 1 to 4 texels a side. Most faces are settled from the centre.
TEST(FaceCache, AFaceJudgedWholeIsJudgedAsItsTexels) {
    std::mt19937 rng(31);
    const World w = grotto::test::randomWorld(64, 0.05, rng);
    const std::vector<ExposedFace> faces = exposedFaces(w);
    std::uniform_int_distribution<int> at(-8, 71), extent(0, 6);
    std::uniform_real_distribution<double> unit(-1.0, 1.0);
    size_t judged = 0, settled = 0;
    for (int e = 0; e < 24; ++e) {
        const glm::ivec3 lo(at(rng), at(rng), at(rng));
        const IndexBox box{lo, lo + glm::ivec3(extent(rng), extent(rng), extent(rng))};
        const FaceBakeSettings s{.radius = e % 3 == 0 ? 0.1 : e % 3 == 1 ? 2.0 : 12.0,
                                 .texelsPerSide = uint32_t(1 + e % 4),
                                 .sunDirection = glm::normalize(glm::dvec3(unit(rng), 0.2 + std::abs(unit(rng)), unit(rng))),
                                 .sunAngleDegrees = e % 4 == 0 ? 0.0 : e % 4 == 1 ? 0.5 : e % 4 == 2 ? 4.0 : 30.0};
        const StaleRule rule(box, s, w.voxelSize());
        for (size_t f = e; f < faces.size(); f += 7) {
            const StaleParts whole = rule.worstOnFace(faces[f], s.texelsPerSide);
            StaleParts each;
            for (uint32_t j = 0; j < s.texelsPerSide; ++j)
                for (uint32_t i = 0; i < s.texelsPerSide; ++i) {
                    const StaleParts p = rule.at(texelPoint(faces[f], s.texelsPerSide, i, j), faces[f].dir);
                    each.ao |= p.ao, each.sun |= p.sun, each.skyNear |= p.skyNear, each.skyFar |= p.skyFar;
                }
            ASSERT_EQ(whole.ao, each.ao) << "edit " << e << " face " << f;
            ASSERT_EQ(whole.sun, each.sun) << "edit " << e << " face " << f;
            ASSERT_EQ(whole.skyNear, each.skyNear) << "edit " << e << " face " << f;
            ASSERT_EQ(whole.skyFar, each.skyFar) << "edit " << e << " face " << f;
            ++judged;
            settled += !each.ao && !each.sun && !each.skyNear;
        }
    }
    std::printf("%zu faces judged, %zu with nothing to trace again\n", judged, settled);
    EXPECT_GT(settled, judged / 2);
    EXPECT_LT(settled, judged);
}

// The day's sun: the box swept along the whole day's path.
TEST(FaceCache, AnEditRetracesTheDaysSunAlongTheBoxSweptOverTheDay) {
    checkEditsRetraceWhatTheyReach({.radius = 2.0, .texelsPerSide = 2, .rays = 12, .day = SunPath{48.0, 172.0, 20.0}},
                                   grotto::test::underSanitizers(6, 3));
}

// A bake for the day's sun written and read back: its path in the header, its
// bits in the texels; another path's world, or a fixed sun's, refuses it.
TEST(FaceCache, ADayBakesFileKeepsItsPathAndBits) {
    std::mt19937 rng(45);
    World w = grotto::test::randomWorld(12, 0.15, rng);
    Lighting l = w.desc().lighting;
    l.sunFrom = SunSource::Day, l.latitude = -33.5f, l.dayOfYear = 300.0f, l.north = 12.0f, l.timeOfDay = 9.0f;
    w.setLighting(l);
    const FaceCacheKey key = faceCacheKey(w, 2.0, 2);
    ASSERT_TRUE(key.day.has_value());
    EXPECT_EQ(*key.day, sunPathOf(l));
    EXPECT_EQ(key.sunDirection, glm::dvec3(0.0)) << "no one hour's sun";
    const std::vector<ExposedFace> faces = exposedFaces(w);
    FaceCacheFile file{.header = {.key = key, .rays = 4, .sunRays = 0, .totalFaces = faces.size(), .faceCount = faces.size()}};
    file.texels = grotto::test::bakeAll(w, faces, {.radius = 2.0, .texelsPerSide = 2, .rays = 4, .day = key.day});
    const std::filesystem::path path = std::filesystem::temp_directory_path() / "grotto-day-bake-round-trip.gfc";
    saveFaceCache(file, path);
    const FaceCacheFile back = loadFaceCache(path);
    EXPECT_EQ(back.header.key, key);
    EXPECT_EQ(back.texels, file.texels);
    size_t lit = 0;
    for (const FaceTexel& t : back.texels) lit += size_t(std::popcount(t.daySun));
    EXPECT_GT(lit, back.texels.size()) << "bits kept";
    // Any hour of the same day takes it; another day, or a fixed sun, does not.
    auto refusal = [&]() -> std::string {
        try {
            requireMatchingBake(back.header, faceCacheKey(w, 2.0, 2), faces.size(), path);
        } catch (const Error& e) {
            return e.what();
        }
        return "taken";
    };
    l.timeOfDay = 17.5f;
    w.setLighting(l);
    EXPECT_NO_THROW(requireMatchingBake(back.header, faceCacheKey(w, 2.0, 2), faces.size(), path));
    l.dayOfYear = 301.0f;
    w.setLighting(l);
    EXPECT_NE(refusal().find("day's sun: baked for latitude -33.5, day 300, north 12, the world asks latitude -33.5, day 301"),
              std::string::npos) << refusal();
    l.sunFrom = SunSource::Direction;
    w.setLighting(l);
    EXPECT_NE(refusal().find("day's sun: baked for latitude -33.5, day 300, north 12, the world asks none"), std::string::npos)
        << refusal();
    std::filesystem::remove(path);
}

// Each texel's bit for a position of the day's sun is World::raycast's answer
// from its centre toward that position (0 where the sun is behind the face).
TEST(FaceCache, TheDaysSunBitsAreExactRaysFromTheTexelsCentre) {
    std::mt19937 rng(44);
    const World w = grotto::test::randomWorld(20, 0.1, rng);
    const SunPath path{48.0, 172.0, 20.0};
    const FaceBakeSettings s{.radius = 2.0, .texelsPerSide = 2, .rays = 2, .day = path};
    const std::vector<ExposedFace> faces = exposedFaces(w);
    const std::vector<FaceTexel> texels = grotto::test::bakeAll(w, faces, s);
    const std::vector<glm::dvec3> sun = daySunDirections(path);
    ASSERT_EQ(sun.size(), size_t(kDaySunPositions));
    EXPECT_NEAR(elevationDegrees(sun.front()), 0.0, 1e-9) << "the first at sunrise";
    EXPECT_NEAR(elevationDegrees(sun.back()), 0.0, 1e-9) << "the last at sunset";
    size_t compared = 0, differing = 0, lit = 0;
    for (size_t f = 0; f < faces.size(); ++f) {
        const glm::dvec3 n = faceNormal(faces[f].dir);
        for (uint32_t t = 0; t < 4; ++t) {
            const FaceTexel& texel = texels[f * 4 + t];
            ASSERT_EQ(texel.dayPositions, kDaySunPositions);
            EXPECT_EQ(texel.sunSamples, 0u) << "no fixed sun's rays";
            const glm::dvec3 from = texelPoint(faces[f], 2, t % 2, t / 2) + n * 1e-4;
            for (uint32_t m = 0; m < kDaySunPositions; ++m) {
                const bool exact = glm::dot(sun[m], n) > 0.0 && !w.raycast(from, sun[m], 1e6);
                const bool bit = (texel.daySun >> m) & 1u;
                ++compared, lit += exact, differing += bit != exact;
            }
        }
    }
    std::printf("[ measured ] %zu of %zu bits differ from World::raycast, %zu lit\n", differing, compared, lit);
    EXPECT_GT(lit, compared / 10);
    EXPECT_LT(lit, compared * 9 / 10);
    EXPECT_LE(differing, compared / 10000) << "rays that graze a voxel edge";
}

}  // namespace
}  // namespace grotto::voxel
