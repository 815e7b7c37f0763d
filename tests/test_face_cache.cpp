// The face cache's CPU rays (voxel/face_cache.h, voxel/face_bake.h): which faces
// are exposed, and each texel's AO, sky light and sun visibility against closed
// forms (an open floor, a closed room), the reference AO at the same points, and
// World::raycast toward the sun; a bake split into parts equals one bake
// (edits and the day's sun: test_face_cache_edit.cpp).
#include "grotto/error.h"
#include "tests/face_cache_worlds.h"
#include "voxel/brick_table.h"
#include "voxel/face_bake.h"
#include "voxel/face_brick_table.h"
#include "voxel/face_cache_edit.h"
#include "voxel/face_cache_layout.h"
#include "voxel/face_cache_lookup.h"

#include "voxel/face_cache_twin.h"  // the GPU's read of the cache, compiled as C++ over the laid-out arrays
#include "shaders/shared/quad.h"
#include "voxel/reference_ao.h"

#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include <algorithm>
#include <bit>
#include <cmath>
#include <filesystem>
#include <functional>
#include <limits>
#include <numbers>
#include <cstdio>
#include <random>
#include <tuple>

namespace grotto::voxel {
namespace {

TEST(FaceCache, ExposedFacesAreTheSolidVoxelsOpenSides) {
    EXPECT_EQ(exposedFaces(grotto::test::solidWorld({3, 3, 3}, [](glm::ivec3 v) { return v == glm::ivec3(1); })).size(), 6u);
    EXPECT_EQ(exposedFaces(grotto::test::solidWorld({4, 3, 3}, [](glm::ivec3 v) { return v.y == 1 && v.z == 1 && v.x >= 1 && v.x <= 2; })).size(), 10u);
    const World cube = grotto::test::solidWorld({5, 5, 5}, [](glm::ivec3 v) { return glm::all(glm::greaterThan(v, glm::ivec3(0))) && glm::all(glm::lessThan(v, glm::ivec3(4))); });
    const std::vector<ExposedFace> faces = exposedFaces(cube);
    ASSERT_EQ(faces.size(), 54u);  // 6 sides of 3 x 3
    EXPECT_TRUE(std::is_sorted(faces.begin(), faces.end()));
    for (const ExposedFace& f : faces) {
        EXPECT_TRUE(cube.solid(f.cell));
        EXPECT_FALSE(cube.solid(f.cell + glm::ivec3(faceNormal(f.dir))));
    }
}

TEST(FaceCache, TexelsTileTheFaceOnItsPlane) {
    const ExposedFace top{{2, 3, 4}, 2};  // +Y: the plane y = 4
    for (uint32_t k : {1u, 2u, 4u}) {
        glm::dvec3 sum(0.0);
        for (uint32_t j = 0; j < k; ++j)
            for (uint32_t i = 0; i < k; ++i) {
                const glm::dvec3 p = texelPoint(top, k, i, j);
                EXPECT_EQ(p.y, 4.0);
                EXPECT_GT(p.x, 2.0); EXPECT_LT(p.x, 3.0); EXPECT_GT(p.z, 4.0); EXPECT_LT(p.z, 5.0);
                sum += p;
            }
        EXPECT_NEAR(sum.x / (k * k), 2.5, 1e-12);  // centred on the face
        EXPECT_NEAR(sum.z / (k * k), 4.5, 1e-12);
    }
    EXPECT_EQ(texelPoint({{2, 3, 4}, 1}, 1, 0, 0).x, 2.0);  // -X: the plane x = 2
    EXPECT_EQ(texelPoint({{2, 3, 4}, 0}, 1, 0, 0).x, 3.0);  // +X: the plane x = 3
}

// An open floor sees the whole sky: the cosine-weighted mean of sqrt(height) over
// the upper hemisphere is 2 * integral of u^1.5 = 0.8, so zenith 0.8, horizon 0.2;
// its underside sees only the darker horizon below (0.8); a side face half of each.
TEST(FaceCache, AnOpenFloorSeesTheSkyAsTheClosedFormsSay) {
    const World floor = grotto::test::solidWorld({33, 2, 33}, [](glm::ivec3 v) { return v.y == 0; });
    const std::vector<ExposedFace> faces = {{{16, 0, 16}, 2}, {{16, 0, 16}, 3}, {{32, 0, 16}, 0}};
    const std::vector<ExposedFace> all = exposedFaces(floor);
    for (const ExposedFace& f : faces) ASSERT_TRUE(std::binary_search(all.begin(), all.end(), f));
    FaceBakeSettings s{.radius = 4.0, .texelsPerSide = 2, .rays = 1024, .sunDirection = {0.45, 0.8, 0.3}};
    const std::vector<FaceTexel> t = grotto::test::bakeAll(floor, faces, s);
    const FaceTexel& top = t[0];
    EXPECT_EQ(top.samples, 1024u);
    EXPECT_EQ(top.open, 1024u);
    EXPECT_NEAR(top.skyZenith / top.samples, 0.8, 0.003);
    EXPECT_NEAR(top.skyHorizon / top.samples, 0.2, 0.003);
    EXPECT_EQ(top.sun(), 1.0);
    const FaceTexel& bottom = t[4];
    EXPECT_EQ(bottom.open, bottom.samples);
    EXPECT_NEAR(bottom.skyHorizon / bottom.samples, 0.8, 1e-6);
    EXPECT_EQ(bottom.skyZenith, 0.0f);
    EXPECT_EQ(bottom.sun(), 0.0);  // turned away from the sun
    // A side face: half its rays go down (horizon 0.8), half up, where the zenith's
    // weight sqrt(height) averages (0.4 / pi) * integral of sqrt(cos) over a half turn
    // = 0.4 sqrt(pi) Gamma(3/4) / (pi Gamma(5/4)).
    const FaceTexel& side = t[8];
    EXPECT_EQ(side.open, side.samples);
    const double zenith = 0.4 * std::sqrt(std::numbers::pi) * std::tgamma(0.75) / (std::numbers::pi * std::tgamma(1.25));
    EXPECT_NEAR(side.skyZenith / side.samples, zenith, 0.005);
    EXPECT_NEAR(side.skyHorizon / side.samples, 0.4 + 0.5 - zenith, 0.005);
}

// A closed room's inside sees no sky and no sun, whatever the sun does; its AO is
// the reference's at the same points, within the two estimates' error.
TEST(FaceCache, AClosedRoomIsDarkInsideAndItsAoIsTheReferences) {
    const World clipped = grotto::test::solidWorld({12, 12, 12}, [](glm::ivec3 v) {  // the room's walls alone
        const bool inside = glm::all(glm::greaterThanEqual(v, glm::ivec3(1))) && glm::all(glm::lessThanEqual(v, glm::ivec3(10)));
        return inside && (glm::any(glm::equal(v, glm::ivec3(1))) || glm::any(glm::equal(v, glm::ivec3(10))));
    });
    const std::vector<ExposedFace> faces = exposedFaces(clipped);
    FaceBakeSettings s{.radius = 4.0, .texelsPerSide = 2, .rays = 256, .sunRays = 8, .sunDirection = {0.0, 1.0, 0.0},
                       .sunAngleDegrees = 5.0};
    const std::vector<FaceTexel> t = grotto::test::bakeAll(clipped, faces, s);
    std::vector<glm::dvec3> points, normals;
    std::vector<size_t> inside;
    for (size_t f = 0; f < faces.size(); ++f) {
        const glm::dvec3 n = faceNormal(faces[f].dir);
        const glm::ivec3 open = faces[f].cell + glm::ivec3(n);
        const bool in = glm::all(glm::greaterThan(open, glm::ivec3(1))) && glm::all(glm::lessThan(open, glm::ivec3(10)));
        for (size_t x = 0; x < 4; ++x) {
            const FaceTexel& v = t[4 * f + x];
            if (in) {
                EXPECT_EQ(v.skyHorizon, 0.0f);
                EXPECT_EQ(v.skyZenith, 0.0f);
                EXPECT_EQ(v.sunOpen, 0u);
                inside.push_back(4 * f + x);
                points.push_back(texelPoint(faces[f], 2, uint32_t(x % 2), uint32_t(x / 2)));
                normals.push_back(n);
            }
        }
    }
    ASSERT_EQ(inside.size(), 6u * 64u * 4u);  // 8 x 8 faces a wall inside
    const ReferenceAo ref = referenceAo(clipped, points, normals, {.radius = 4.0, .spp = 1024, .seed = 7});
    double worst = 0.0, meanDiff = 0.0;
    for (size_t k = 0; k < inside.size(); ++k) {
        const double a = t[inside[k]].ao(), b = ref.visibility[k];
        const double sigma = std::sqrt(b * (1.0 - b) * (1.0 / 256 + 1.0 / 1024)) + 1.0 / 256;
        worst = std::max(worst, std::abs(a - b) / sigma);
        meanDiff += (a - b) / inside.size();
    }
    EXPECT_LT(worst, 5.0) << "every texel within 5 sigma of the reference";
    EXPECT_LT(std::abs(meanDiff), 0.003) << "no bias";
}

// A point sun's visibility is the share of the texel's square it reaches: its 16
// rays start all over the square, so a texel an edge of sunlight crosses reads part
// lit, and one wholly lit or wholly shadowed reads exactly that. Against
// World::raycast from a 32 x 32 grid of points on each face (one texel a face).
TEST(FaceCache, PointSunVisibilityIsTheLitShareOfTheTexelsSquare) {
    std::mt19937 rng(11);
    const World w = grotto::test::randomWorld(20, 0.18, rng);
    const std::vector<ExposedFace> faces = exposedFaces(w);
    const glm::dvec3 sun = glm::normalize(glm::dvec3(0.45, 0.8, 0.3));
    FaceBakeSettings s{.texelsPerSide = 1, .rays = 4, .sunDirection = sun};
    ASSERT_EQ(s.sunRays, 16u);
    const std::vector<FaceTexel> t = grotto::test::bakeAll(w, faces, s);
    size_t lit = 0, dark = 0, part = 0;
    double worst = 0.0;
    for (size_t f = 0; f < faces.size(); ++f) {
        const glm::dvec3 n = faceNormal(faces[f].dir), centre = texelPoint(faces[f], 1, 0, 0);
        glm::dvec3 u(0.0), v(0.0);
        u[int(gpu::faceUAxis(faces[f].dir))] = 1.0, v[int(gpu::faceVAxis(faces[f].dir))] = 1.0;
        constexpr int kGrid = grotto::test::underSanitizers(32, 16);  // points over the face, a side
        int open = 0;
        for (int a = 0; a < kGrid; ++a)
            for (int b = 0; b < kGrid; ++b) {
                const glm::dvec3 p = centre + u * ((a + 0.5) / kGrid - 0.5) + v * ((b + 0.5) / kGrid - 0.5) + n * s.epsilon;
                open += glm::dot(n, sun) > 0.0 && !w.raycast(p, sun, 1e9);
            }
        const double share = double(open) / (kGrid * kGrid), read = double(t[f].sunOpen) / t[f].sunSamples;
        ASSERT_EQ(t[f].sunSamples, 16u);
        if (open == 0) EXPECT_EQ(t[f].sunOpen, 0u) << "face " << f << " is wholly shadowed";
        if (open == kGrid * kGrid) EXPECT_EQ(t[f].sunOpen, 16u) << "face " << f << " is wholly lit";
        if (share > 0.1 && share < 0.9) EXPECT_TRUE(read > 0.0 && read < 1.0) << "face " << f << ": " << share << " lit";
        worst = std::max(worst, std::abs(read - share));
        lit += open == kGrid * kGrid, dark += open == 0, part += open > 0 && open < kGrid * kGrid;
    }
    std::printf("%zu faces: %zu lit, %zu shadowed, %zu part lit; worst share off by %.3f\n", faces.size(), lit, dark,
                part, worst);
    EXPECT_LT(worst, 0.2) << "16 rays over a square an edge crosses";
    EXPECT_GT(part, faces.size() / 50);  // every kind occurs
    EXPECT_GT(lit, faces.size() / 20);
    EXPECT_GT(dark, faces.size() / 10);
}

// A texel's sun rays start all over its square, so an edit its centre's ray
// passes by, but a ray from the square's far side crosses, makes its sun stale.
TEST(FaceCache, AnEditTheTexelsSquareSeesTowardTheSunMakesItsSunStale) {
    const FaceBakeSettings s{.texelsPerSide = 1, .sunDirection = glm::normalize(glm::dvec3(0.25, 1.0, 0.0))};
    const glm::dvec3 centre(0.5, 1.0, 0.5);  // the top (+y, direction 2) face of voxel (0, 0, 0), one texel
    ASSERT_EQ(faceNormal(2), glm::dvec3(0.0, 1.0, 0.0));
    const IndexBox box{{2, 5, 0}, {2, 5, 0}};  // from the centre the sun's ray passes it by a quarter voxel
    const glm::dvec3 d = s.sunDirection, lo(2.0, 5.0, 0.0), hi(3.0, 6.0, 1.0);
    auto meets = [&](glm::dvec3 p) {  // the ray p + t d through the box
        const glm::dvec3 a = (lo - p) / d, b = (hi - p) / d;
        const glm::dvec3 near = glm::min(a, b), far = glm::max(a, b);
        return std::max({near.x, near.y, near.z, 0.0}) <= std::min({far.x, far.y, far.z});
    };
    ASSERT_FALSE(meets(centre + glm::dvec3(0.0, 1e-4, 0.0)));
    ASSERT_TRUE(meets(centre + glm::dvec3(0.45, 1e-4, 0.0)));  // near the square's +x side
    EXPECT_TRUE(staleAfterEdit(centre, 2, box, s, 1.0).sun);
    EXPECT_FALSE(staleAfterEdit(centre, 2, IndexBox{{3, 5, 0}, {3, 5, 0}}, s, 1.0).sun);  // beyond every ray
}

// Each texel's rays depend on the texel alone: parts baked apart, in any order, and
// rays added in two calls give the same counts as one bake.
TEST(FaceCache, ABakeSplitIntoPartsEqualsOneBake) {
    std::mt19937 rng(5);
    const World w = grotto::test::randomWorld(16, 0.25, rng);
    const std::vector<ExposedFace> faces = exposedFaces(w);
    FaceBakeSettings s{.texelsPerSide = 2, .rays = 64, .sunRays = 4, .sunAngleDegrees = 2.0};
    const std::vector<FaceTexel> whole = grotto::test::bakeAll(w, faces, s);
    const size_t half = faces.size() / 3;
    std::vector<FaceTexel> parts = grotto::test::bakeAll(w, std::span(faces).subspan(half), s);
    const std::vector<FaceTexel> first = grotto::test::bakeAll(w, std::span(faces).first(half), s);
    parts.insert(parts.begin(), first.begin(), first.end());
    EXPECT_TRUE(parts == whole);

    FaceBakeSettings halfRays = s;
    halfRays.rays = 32, halfRays.sunRays = 2;
    std::vector<FaceTexel> twice(whole.size());
    const BrickTable table(w);
    bakeFaces(table, w, faces, halfRays, twice);
    bakeFaces(table, w, faces, halfRays, twice);
    for (size_t k = 0; k < whole.size(); ++k) {
        ASSERT_EQ(twice[k].open, whole[k].open);
        ASSERT_EQ(twice[k].sunOpen, whole[k].sunOpen);
        ASSERT_NEAR(twice[k].skyZenith, whole[k].skyZenith, 1e-4);
    }
}

// Reading at a point blends the four nearest texel centres bilinearly across
// coplanar exposed faces: a field linear over a floor comes back exactly, away
// from the floor's rim; at a convex edge the missing neighbours drop out.
TEST(FaceCache, LookupBlendsTexelsAcrossCoplanarFaces) {
    const World floor = grotto::test::solidWorld({8, 2, 8}, [](glm::ivec3 v) { return v.y == 0; });
    const std::vector<ExposedFace> faces = exposedFaces(floor);
    for (uint32_t k : {1u, 2u, 3u}) {
        std::vector<FaceTexel> texels(faces.size() * k * k);
        auto field = [](glm::dvec3 p) { return 0.1 + 0.05 * p.x + 0.03 * p.z; };  // below 1 everywhere here
        for (size_t f = 0; f < faces.size(); ++f)
            for (uint32_t j = 0; j < k; ++j)
                for (uint32_t i = 0; i < k; ++i) {
                    FaceTexel& t = texels[(f * k + j) * k + i];
                    t.samples = 1u << 20;
                    t.open = uint32_t(std::lround(field(texelPoint(faces[f], k, i, j)) * t.samples));
                    t.sunSamples = 1, t.sunOpen = 1;
                }
        const FaceCacheLookup lookup(faces, texels, k);
        std::mt19937 rng(k);
        std::uniform_real_distribution<double> inner(1.0, 7.0);
        for (int n = 0; n < 200; ++n) {
            const glm::dvec3 p(inner(rng), 1.0, inner(rng));
            EXPECT_NEAR(lookup.at(p, 2).ao, field(p), 2e-6) << "k " << k;
        }
        // At the rim the nearest centres are the face's own: the field at the edge texels.
        const CachedLight corner = lookup.at({0.0, 1.0, 0.0}, 2);
        EXPECT_NEAR(corner.ao, field(texelPoint({{0, 0, 0}, 2}, k, 0, 0)), 2e-6);
        EXPECT_EQ(corner.samples, 1u << 20);
        EXPECT_EQ(lookup.at({3.5, 5.0, 3.5}, 2).samples, 0u);  // a plane with no exposed face: nothing
    }
}

// The arrays the GPU reads, read by the shader's own code: every exposed face is
// found at its place and no other face is; at random points on face planes the
// read equals the CPU lookup up to the texels' 8-bit quantisation.
TEST(FaceCache, TheGpuLayoutReadsAsTheCpuLookup) {
    std::mt19937 rng(9);
    const World w = grotto::test::randomWorld(20, 0.3, rng);
    const std::vector<ExposedFace> faces = exposedFaces(w);
    for (uint32_t k : {1u, 2u}) {
        const std::vector<FaceTexel> texels = grotto::test::bakeAll(w, faces, {.texelsPerSide = k, .rays = 16, .sunRays = 1});
        const FaceCacheArrays arrays = layFaceCache(faces, texels, k);
        EXPECT_EQ(faceCacheGpuBytes(faces, k), arrays.bytes());
        gpu::faceCacheTwin = &arrays;
        const FaceCacheLookup lookup(faces, texels, k);
        std::vector<int> seen(faces.size(), 0);
        for (int z = -1; z <= 20; ++z)
            for (int y = -1; y <= 20; ++y)
                for (int x = -1; x <= 20; ++x)
                    for (uint32_t d = 0; d < 6; ++d) {
                        const int g = gpu::faceCacheFace({x, y, z}, d);
                        const int64_t c = lookup.find({{x, y, z}, uint8_t(d)});
                        ASSERT_EQ(g >= 0, c >= 0) << x << " " << y << " " << z << " dir " << d;
                        if (g < 0) continue;
                        ASSERT_LT(size_t(g), faces.size());
                        ++seen[size_t(g)];
                        // The GPU's texels of that face are the CPU's face's, packed.
                        for (uint32_t t = 0; t < k * k; ++t)
                            ASSERT_EQ(gpu::faceCacheTexel(uint32_t(g) * k * k + t), packFaceTexel(texels[size_t(c) * k * k + t]));
                    }
        EXPECT_TRUE(std::all_of(seen.begin(), seen.end(), [](int n) { return n == 1; })) << "each face at one index";
        std::uniform_real_distribution<double> along(0.0, 20.0);
        size_t read = 0;
        for (int n = 0; n < 4000; ++n) {
            const ExposedFace& f = faces[rng() % faces.size()];
            glm::dvec3 p = texelPoint(f, 1, 0, 0);
            const int ua = int(gpu::faceUAxis(f.dir)), va = int(gpu::faceVAxis(f.dir));
            p[ua] = f.cell[ua] + along(rng) / 20.0, p[va] = f.cell[va] + along(rng) / 20.0;
            const glm::ivec3 origin(2, -3, 5);  // camera-relative: whole voxels taken out
            bool found = false;
            const glm::vec4 g = gpu::faceCacheAt(glm::vec3(p - glm::dvec3(origin)), origin, f.dir, found);
            const CachedLight c = lookup.at(p, f.dir);
            ASSERT_TRUE(found);
            EXPECT_NEAR(g.x, c.ao, 0.6 * kFaceTexelStep[0] + 1e-5);
            EXPECT_NEAR(g.y, c.sun, 0.6 * kFaceTexelStep[1] + 1e-5);
            EXPECT_NEAR(g.z, c.skyHorizon, 0.6 * kFaceTexelStep[2] + 1e-5);
            EXPECT_NEAR(g.w, c.skyZenith, 0.6 * kFaceTexelStep[3] + 1e-5);
            ++read;
        }
        EXPECT_EQ(read, 4000u);
        gpu::faceCacheTwin = nullptr;
    }
}

// The layout sorts bricks by a 64-bit key of their place from the least brick,
// 21 bits an axis; a world far from the origin keeps to it, and one wider than
// 2^24 voxels compares the bricks themselves: either way each face is found at
// one place, with its own texels.
TEST(FaceCache, TheLayoutFindsEveryFaceFarFromTheOriginAndInAWorldWiderThanItsKey) {
    std::mt19937 rng(21);
    const World w = grotto::test::randomWorld(12, 0.3, rng);
    const std::vector<ExposedFace> faces = exposedFaces(w);
    const std::vector<FaceTexel> texels = grotto::test::bakeAll(w, faces, {.texelsPerSide = 1, .rays = 16, .sunRays = 1});
    for (const bool wide : {false, true}) {
        // Far: every face moved 2^26 voxels down x; wide: those in the upper half of y moved back up 2^27.
        std::vector<std::pair<ExposedFace, FaceTexel>> moved;
        for (size_t f = 0; f < faces.size(); ++f) {
            ExposedFace m = faces[f];
            m.cell.x -= 1 << 26;
            if (wide && m.cell.y >= 6) m.cell.x += 1 << 27;
            moved.push_back({m, texels[f]});
        }
        std::sort(moved.begin(), moved.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
        std::vector<ExposedFace> listed;
        std::vector<FaceTexel> theirs;
        for (const auto& [face, texel] : moved) listed.push_back(face), theirs.push_back(texel);
        const FaceCacheArrays arrays = layFaceCache(listed, theirs, 1);
        gpu::faceCacheTwin = &arrays;
        std::vector<int> seen(listed.size(), 0);
        for (size_t f = 0; f < listed.size(); ++f) {
            const int g = gpu::faceCacheFace(listed[f].cell, listed[f].dir);
            ASSERT_GE(g, 0) << "wide " << wide << " face " << f;
            ++seen[size_t(g)];
            EXPECT_EQ(arrays.faceOrder[size_t(g)], f);
            EXPECT_EQ(gpu::faceCacheTexel(uint32_t(g)), packFaceTexel(theirs[f]));
        }
        EXPECT_TRUE(std::all_of(seen.begin(), seen.end(), [](int n) { return n == 1; })) << "each face at one index";
        gpu::faceCacheTwin = nullptr;
    }
}

// Full light over the day reads a point's texels and the four faces whose centres
// lie nearest from one look-up: both equal what each look-up alone finds, at
// random points across faces (near their sides, where neighbours and other
// bricks come in) and at every texel count the cache takes a side.
TEST(FaceCache, TheTexelsAndFacesReadTogetherAreEachReadAlone) {
    std::mt19937 rng(12);
    const World w = grotto::test::randomWorld(20, 0.3, rng);
    const std::vector<ExposedFace> faces = exposedFaces(w);
    for (uint32_t k : {1u, 2u, 3u, 4u}) {
        const std::vector<FaceTexel> texels(faces.size() * k * k);
        const FaceCacheArrays arrays = layFaceCache(faces, texels, k);
        gpu::faceCacheTwin = &arrays;
        std::uniform_real_distribution<double> along(0.0, 1.0);
        size_t across = 0;  // points whose texels lie on more than one face
        for (int n = 0; n < 4000; ++n) {
            const ExposedFace& f = faces[rng() % faces.size()];
            glm::dvec3 p = texelPoint(f, 1, 0, 0);
            const int ua = int(gpu::faceUAxis(f.dir)), va = int(gpu::faceVAxis(f.dir));
            p[ua] = f.cell[ua] + along(rng), p[va] = f.cell[va] + along(rng);
            const glm::ivec3 origin(-7, 3, 11);
            const glm::vec3 at(p - glm::dvec3(origin));
            gpu::FaceCacheTaps together;
            const gpu::FaceCacheTaps t = gpu::faceCacheTapsWithFaces(at, origin, f.dir, int(k), together);
            const gpu::FaceCacheTaps alone = gpu::faceCacheTapsAtK(at, origin, f.dir, int(k)), faceAlone = gpu::faceCacheTapsAtK(at, origin, f.dir, 1);
            for (int c = 0; c < 4; ++c) {
                ASSERT_EQ(t.face[c], alone.face[c]) << "k " << k << " tap " << c;
                ASSERT_EQ(t.cell[c], alone.cell[c]);
                ASSERT_EQ(t.texel[c], alone.texel[c]);
                ASSERT_EQ(t.weight[c], alone.weight[c]);
                ASSERT_EQ(together.face[c], faceAlone.face[c]);
                ASSERT_EQ(together.texel[c], faceAlone.texel[c]);
                ASSERT_EQ(together.weight[c], faceAlone.weight[c]);
            }
            across += t.face[0] != t.face[3] || t.face[1] != t.face[2];
        }
        if (k > 1) EXPECT_GT(across, 100u) << "k " << k << ": few points near the faces' sides";
        gpu::faceCacheTwin = nullptr;
    }
}

// The bricks' perfect hash, read by the shader's own code: each brick of sets
// dense and sparse, near the origin and at the coordinates' extremes, is found
// at its own index, and no brick outside the set (its neighbours, random ones)
// is found at all; the table holds no more than 9/8 slots a brick.
TEST(FaceCache, TheBrickTableFindsEachBrickAndNoOther) {
    std::mt19937 rng(31);
    std::vector<std::vector<glm::ivec3>> sets(4);
    sets[1] = {{0, 0, 0}};
    for (int x = -20; x < 20; ++x)  // dense: 40 x 12 x 40 bricks, every second column
        for (int y = -6; y < 6; ++y)
            for (int z = -20; z < 20; z += 1 + ((x + y) & 1)) sets[2].push_back({x, y, z});
    std::uniform_int_distribution<int> anywhere(std::numeric_limits<int>::min() / 8, std::numeric_limits<int>::max() / 8);
    for (int i = 0; i < 20000; ++i) sets[3].push_back({anywhere(rng), anywhere(rng), anywhere(rng)});
    sets[3].push_back({std::numeric_limits<int>::min() / 8, std::numeric_limits<int>::max() / 8, 0});
    for (std::vector<glm::ivec3>& set : sets) {
        std::sort(set.begin(), set.end(), [](const glm::ivec3& a, const glm::ivec3& b) {
            return std::tie(a.x, a.y, a.z) < std::tie(b.x, b.y, b.z);
        });
        set.erase(std::unique(set.begin(), set.end()), set.end());
        const FaceBrickTable table = layFaceBrickTable(set);
        EXPECT_LE(table.slots.size(), set.size() * 9 / 8 + 1);
        EXPECT_EQ(faceBrickTableBytes(set.size()), table.slots.size() * 16 + table.seeds.size() * 4);
        FaceCacheArrays arrays;
        arrays.bricks = table.slots;
        arrays.records = table.seeds;
        arrays.table = table.shape;
        gpu::faceCacheTwin = &arrays;
        for (size_t i = 0; i < set.size(); ++i) {
            ASSERT_EQ(gpu::faceCacheRecord(set[i]), i + 1) << set[i].x << " " << set[i].y << " " << set[i].z;
            for (int d = 0; d < 6; ++d) {
                glm::ivec3 n = set[i];
                n[d / 2] += d % 2 ? 1 : -1;
                if (!std::binary_search(set.begin(), set.end(), n, [](const glm::ivec3& a, const glm::ivec3& b) {
                        return std::tie(a.x, a.y, a.z) < std::tie(b.x, b.y, b.z);
                    }))
                    ASSERT_EQ(gpu::faceCacheRecord(n), 0u);
            }
        }
        std::uniform_int_distribution<int> near(-30, 30);
        for (int i = 0; i < 20000; ++i) {
            const glm::ivec3 b = i % 2 ? glm::ivec3(near(rng), near(rng), near(rng)) : glm::ivec3(anywhere(rng), anywhere(rng), anywhere(rng));
            const bool in = std::binary_search(set.begin(), set.end(), b, [](const glm::ivec3& a, const glm::ivec3& c) {
                return std::tie(a.x, a.y, a.z) < std::tie(c.x, c.y, c.z);
            });
            ASSERT_EQ(gpu::faceCacheRecord(b) != 0u, in);
        }
    }
}

TEST(FaceCache, BadSettingsAreRefused) {
    const World w = grotto::test::solidWorld({3, 3, 3}, [](glm::ivec3 v) { return v == glm::ivec3(1); });
    const std::vector<ExposedFace> faces = exposedFaces(w);
    std::vector<FaceTexel> t(faces.size());
    EXPECT_THROW(bakeFaces(BrickTable(w), w, faces, {.radius = 0.0, .texelsPerSide = 1}, t), Error);
    EXPECT_THROW(bakeFaces(BrickTable(w), w, faces, {.texelsPerSide = 0}, t), Error);
    EXPECT_THROW(bakeFaces(BrickTable(w), w, faces, {.texelsPerSide = 2}, t), Error);
}

// The row-at-a-time count equals the listed faces, and the bricks holding them,
// on random worlds with solid bricks at negative indices and across brick borders.
TEST(FaceCache, CountingEqualsListing) {
    std::mt19937 rng(33);
    for (double density : {0.05, 0.3, 0.7, 1.0}) {
        World w = grotto::test::randomWorld(21, density, rng);
        w.apply(Edit::fillBox({{-9, -3, -17}, {-2, 4, -5}}, 1));
        w.apply(Edit::carveBox({{-5, 0, -9}, {-4, 1, -8}}));
        const std::vector<ExposedFace> faces = exposedFaces(w);
        std::vector<glm::ivec3> bricks;
        for (const ExposedFace& f : faces) bricks.push_back(f.cell >> 3);
        std::sort(bricks.begin(), bricks.end(), [](glm::ivec3 a, glm::ivec3 b) {
            return std::tie(a.x, a.y, a.z) < std::tie(b.x, b.y, b.z);
        });
        bricks.erase(std::unique(bricks.begin(), bricks.end()), bricks.end());
        const ExposedFaceCount count = countExposedFaces(w);
        EXPECT_EQ(count.faces, faces.size()) << "density " << density;
        EXPECT_EQ(count.bricks, bricks.size()) << "density " << density;
        EXPECT_EQ(faceCacheGpuBytes(count, 3), faceCacheGpuBytes(faces, 3));
    }
}

}  // namespace
}  // namespace grotto::voxel
