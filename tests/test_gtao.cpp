// GTAO: the GPU pass against its CPU twin, flat floors that must stay open,
// corners that must darken symmetrically, tiny sizes, no AO leaking across
// silhouettes in the upsample, and thin-occluder compensation.
#include "engine/lab/gtao_twin.h"
#include "engine/renderer.h"
#include "tests/ao_fixture.h"
#include "tests/scenes.h"
#include "tests/test_util.h"

#include <algorithm>
#include <cmath>
#include <map>

namespace grotto {
namespace {

using test::Rendered;

class Gtao : public test::AoFixture {};

TEST_F(Gtao, GpuMatchesCpuTwinForEveryPreset) {
    const voxel::World world = voxel::World::load(test::worldsDir() / "rooms.json");
    for (const char* quality : {"low", "medium", "high", "ultra", "full-res high"}) {
        AoOptions ao = options(quality[0] == 'f' ? "high" : quality);
        ao.chain.fullResolution = quality[0] == 'f';
        const Rendered r = render(world, world.camera("table", 16.0 / 9.0), 160, 90, ao);
        const GtaoTwin twin(r.constants, r.img.depthBuffer, r.img.surfaceIds);
        const glm::uvec2 half = r.constants.halfSize;
        int compared = 0;
        float worst = 0.0f;
        for (uint32_t y = 0; y < half.y; y += 3)
            for (uint32_t x = 0; x < half.x; x += 3) {
                const glm::vec2 cpu = twin.pixel(glm::ivec2(x, y));
                const float* gpu = &r.img.aoRawHalf[2 * (size_t(y) * half.x + x)];
                worst = std::max(worst, std::abs(gpu[0] - cpu.x));
                EXPECT_NEAR(gpu[0], cpu.x, 1e-3) << quality << " pixel " << x << "," << y;
                EXPECT_EQ(gpu[1], cpu.y) << quality << " edges at " << x << "," << y;
                ++compared;
            }
        EXPECT_GT(compared, 300);
        RecordProperty(std::string("worst_") + quality, std::to_string(worst));
    }
}

TEST_F(Gtao, FlatFloorStaysOpenFromStraightDownToGrazing) {
    const voxel::World floor = test::makeVoxelWorld({-256, -1, -256}, {255, -1, 255}, [](int, int, int) { return true; });
    const auto scene = upload(floor, options("high"));
    // Large images too: coarse depth MIPs only come into play there.
    for (auto [w, h] : {std::pair{192u, 108u}, {1280u, 720u}})
    for (double degrees : {0.0, 45.0, 80.0, 85.0, 89.0, 89.5}) {
        const double a = glm::radians(degrees);
        const glm::dvec3 eye(0.0, 1.5, 0.0);
        const glm::dvec3 dir(std::sin(a), -std::cos(a), 0.0);
        const Rendered r = render(*scene, floor, test::lookAt(eye, eye + dir, 70.0), w, h, options("high"));
        int floorPixels = 0;
        for (size_t i = 0; i < r.img.ao.size(); ++i) {
            ASSERT_TRUE(std::isfinite(r.img.ao[i]) && std::isfinite(r.img.aoRaw[i])) << degrees;
            if (!std::isfinite(r.img.depth[i])) continue;
            ++floorPixels;
            // The reference is exactly 1 here (test_reference.cpp): every pixel within
            // 0.01 of it, which also bounds any banding to 0.01.
            EXPECT_GE(r.img.ao[i], 0.99f) << degrees << " degrees, " << w << "x" << h << ", pixel " << i % w << "," << i / w;
            EXPECT_GE(r.img.aoRaw[i], 0.99f) << degrees << " degrees, raw";
            if (r.img.ao[i] < 0.99f || r.img.aoRaw[i] < 0.99f) break;  // one report per view is enough
        }
        EXPECT_GT(floorPixels, 1000) << degrees;
    }
}

TEST_F(Gtao, CornerDarkensMonotonicallyAndSymmetrically) {
    // Floor y < 0 and a wall x < 0 meet along the z axis; the camera sits on the
    // bisecting plane x = y, so floor and wall see the corner alike.
    const voxel::World corner = test::makeVoxelWorld({-40, -40, -60}, {40, 40, 60}, [](int x, int y, int) {
        return (y < 0 && x >= -40) || (x < 0 && y >= 0);
    });
    AoOptions ao = options("ultra", 4.0);
    ao.chain.denoisePasses = 2;
    const Rendered r = render(corner, test::lookAt({14, 14, 24}, {0, 0, 0}, 60.0), 320, 240, ao);
    // Average AO by distance from the corner line, floor and wall apart.
    std::map<int, std::pair<double, int>> floorBins, wallBins;
    for (uint32_t y = 0; y < r.img.height; ++y)
        for (uint32_t x = 0; x < r.img.width; ++x) {
            const size_t i = size_t(y) * r.img.width + x;
            if (!std::isfinite(r.img.depth[i])) continue;
            const glm::dvec3 w = worldAt(r, x, y);
            if (std::abs(w.z) > 8) continue;  // away from the ends
            const bool onFloor = r.img.normal[3 * i + 1] > 0.5f, onWall = r.img.normal[3 * i] > 0.5f;
            const double d = onFloor ? w.x + 0.5 : w.y + 0.5;  // distance from the corner line
            if (d < 0 || d > 6) continue;
            auto& bin = (onFloor ? floorBins : wallBins)[int(d * 2)];
            if (onFloor || onWall) bin.first += r.img.ao[i], ++bin.second;
        }
    double previous = 0.0;
    for (int b = 0; b < 12; ++b) {
        ASSERT_GT(floorBins[b].second, 20) << "bin " << b;
        ASSERT_GT(wallBins[b].second, 20) << "bin " << b;
        const double f = floorBins[b].first / floorBins[b].second, w = wallBins[b].first / wallBins[b].second;
        EXPECT_NEAR(f, w, 0.03) << "floor and wall differ at " << b / 2.0 << " from the corner";
        EXPECT_GE(f + 0.01, previous) << "AO must not darken away from the corner (bin " << b << ")";
        previous = f;
    }
    EXPECT_LT(floorBins[0].first / floorBins[0].second, 0.8);   // dark in the corner
    EXPECT_GT(floorBins[11].first / floorBins[11].second, 0.9); // open beyond the radius
}

TEST_F(Gtao, TinySizesAndOneSliceOneStepStayFinite) {
    const voxel::World world = voxel::World::load(test::worldsDir() / "rooms.json");
    AoOptions minimal = options("low");
    minimal.estimator.slices = 1;
    minimal.estimator.steps = 1;
    for (auto [w, h] : {std::pair{1u, 1u}, {2u, 2u}, {3u, 5u}, {333u, 177u}})
        for (const AoOptions& ao : {minimal, options("high")}) {
            const Rendered r = render(world, world.camera("table", 16.0 / 9.0), w, h, ao);
            for (size_t i = 0; i < r.img.ao.size(); ++i) {
                ASSERT_TRUE(r.img.ao[i] >= 0.0f && r.img.ao[i] <= 1.0f) << w << "x" << h << " pixel " << i << ": " << r.img.ao[i];
                ASSERT_TRUE(r.img.aoRaw[i] >= 0.0f && r.img.aoRaw[i] <= 1.0f)
                    << w << "x" << h << " pixel " << i << ": " << r.img.aoRaw[i];
                for (int c = 0; c < 4; ++c) ASSERT_TRUE(std::isfinite(r.img.color[4 * i + c])) << w << "x" << h;
            }
        }
}

TEST_F(Gtao, UpsampleLeaksNoAoAcrossASilhouette) {
    // A thin bar floats in front of a dark floor/wall corner: the bar is open, the
    // corner behind it dark, and the bar's pixels must not pick up the corner's AO.
    const voxel::World scene = test::makeVoxelWorld({-40, -40, -40}, {40, 40, 40}, [](int x, int y, int z) {
        const bool bar = x == 8 && y == 8 && z >= -30 && z <= 30;
        return bar || (y < 0 && x >= -40) || (x < 0 && y >= 0);
    });
    // Radius 6 (8.7 with the multiplier): the bar, 11 units from the corner, stays open.
    const Rendered r = render(scene, test::lookAt({20.5, 20.5, 0.5}, {0.5, 0.5, 0.5}, 50.0), 256, 192, options("high", 6.0));
    int barPixels = 0, darkNeighbours = 0;
    float barMin = 1.0f, behindMin = 1.0f;
    for (uint32_t y = 1; y + 1 < r.img.height; ++y)
        for (uint32_t x = 1; x + 1 < r.img.width; ++x) {
            const size_t i = size_t(y) * r.img.width + x;
            const bool bar = r.img.depth[i] < 20.0f;  // the bar is ~18 units away, the corner ~28
            if (!bar) continue;
            ++barPixels;
            barMin = std::min(barMin, r.img.ao[i]);
            for (int dy : {-1, 1}) {
                const size_t j = i + dy * int(r.img.width);
                if (r.img.depth[j] <= 20.0f) continue;
                behindMin = std::min(behindMin, r.img.ao[j]);
                if (r.img.ao[j] < 0.85f) ++darkNeighbours;
            }
        }
    EXPECT_GT(barPixels, 100);
    EXPECT_GT(darkNeighbours, 10) << "the test needs dark AO right behind the silhouette; darkest " << behindMin;
    EXPECT_GE(barMin, 0.95f) << "AO leaked onto the bar";
}

TEST_F(Gtao, ThinOccluderCompensationOpensBehindPolesButKeepsWallContact) {
    // Floor, a one-voxel pole at the origin and a thick wall at x >= 10. The
    // compensation stretches view-depth distances rather than measuring thickness,
    // so how much the wall changes depends on the view; for this one (facing the
    // wall) it must stay within 0.02 while the pole's surroundings open up more.
    const voxel::World scene = test::makeVoxelWorld({-30, -2, -30}, {30, 12, 30}, [](int x, int y, int z) {
        return y < 0 || (x == 0 && z == 0 && y < 10) || (x >= 10 && x < 16 && y < 10);
    });
    auto meanNear = [&](const Rendered& r, auto inside) {
        double sum = 0;
        int n = 0;
        for (uint32_t y = 0; y < r.img.height; ++y)
            for (uint32_t x = 0; x < r.img.width; ++x) {
                const size_t i = size_t(y) * r.img.width + x;
                if (!std::isfinite(r.img.depth[i]) || r.img.normal[3 * i + 1] < 0.5f) continue;  // floor only
                if (inside(worldAt(r, x, y))) sum += r.img.ao[i], ++n;
            }
        EXPECT_GT(n, 50);
        return sum / std::max(n, 1);
    };
    const voxel::CameraDesc cam = test::lookAt({-12, 9, 14}, {2, 0, -2}, 60.0);
    AoOptions plain = options("ultra", 3.0);
    plain.estimator.thinOccluder = 0.0f;  // off against on (the default is 0.2)
    AoOptions thin = plain;
    thin.estimator.thinOccluder = 0.4f;
    const Rendered a = render(scene, cam, 256, 192, plain), b = render(scene, cam, 256, 192, thin);
    auto behindPole = [](glm::dvec3 p) { return glm::length(glm::dvec2(p.x, p.z)) < 3.0 && glm::length(glm::dvec2(p.x, p.z)) > 0.8 && p.x > 0.2; };
    auto wallContact = [](glm::dvec3 p) { return p.x > 7.5 && p.x < 9.5 && std::abs(p.z) < 6; };
    const double poleA = meanNear(a, behindPole), poleB = meanNear(b, behindPole);
    const double wallA = meanNear(a, wallContact), wallB = meanNear(b, wallContact);
    EXPECT_GT(poleB, poleA + 0.01) << "compensation should open the floor behind the pole";
    EXPECT_GT(poleB - poleA, wallB - wallA) << "the pole should gain more than the wall";
    EXPECT_NEAR(wallB, wallA, 0.02) << "the wall's contact shadow should stay";
    std::printf("thin occluder: pole %.3f -> %.3f, wall %.3f -> %.3f\n", poleA, poleB, wallA, wallB);
    RecordProperty("pole", std::to_string(poleA) + " -> " + std::to_string(poleB));
    RecordProperty("wall", std::to_string(wallA) + " -> " + std::to_string(wallB));
}

TEST_F(Gtao, ThinOccluderCompensationOpensTheFloorBehindThePolesOfThin) {
    // The shipped thin world: one-voxel poles at z = -20, x = -24 + 3k, on a floor
    // whose top is y = -0.5. Seen from the +z side, the floor just behind a pole is
    // what a single depth layer over-darkens.
    const voxel::World world = voxel::World::load(test::worldsDir() / "thin.json");
    const voxel::CameraDesc cam = test::lookAt({0, 7, -7}, {0, 0, -21}, 60.0);
    AoOptions plain = options("ultra");
    plain.estimator.thinOccluder = 0.0f;
    AoOptions thin = plain;
    thin.estimator.thinOccluder = 0.4f;
    const Rendered a = render(world, cam, 256, 192, plain), b = render(world, cam, 256, 192, thin);
    auto behindPole = [](glm::dvec3 p) {
        const double poleX = -24.0 + 3.0 * std::round((p.x + 24.0) / 3.0);
        const double d = glm::length(glm::dvec2(p.x - poleX, p.z + 20.0));
        return std::abs(p.y + 0.5) < 0.01 && p.z < -20.6 && d > 0.8 && d < 3.0 && std::abs(p.x) < 20.0;
    };
    double sumA = 0.0, sumB = 0.0;
    int n = 0;
    for (uint32_t y = 0; y < a.img.height; ++y)
        for (uint32_t x = 0; x < a.img.width; ++x) {
            const size_t i = size_t(y) * a.img.width + x;
            if (!std::isfinite(a.img.depth[i]) || a.img.normal[3 * i + 1] < 0.5f || !behindPole(worldAt(a, x, y))) continue;
            sumA += a.img.ao[i], sumB += b.img.ao[i], ++n;
        }
    ASSERT_GT(n, 200);
    std::printf("thin world, floor behind the poles (%d pixels): %.3f -> %.3f\n", n, sumA / n, sumB / n);
    EXPECT_GT(sumB / n, sumA / n + 0.01) << "compensation should open the floor behind thin's poles";
    RecordProperty("behind_poles", std::to_string(sumA / n) + " -> " + std::to_string(sumB / n));
}

}  // namespace
}  // namespace grotto

namespace grotto {
namespace {

TEST_F(Gtao, CompositeShadesWithTheAoItReports) {
    // The composite upsamples the AO for itself; the AO AOV comes from the
    // standalone upsample. Every surface pixel's colour must follow from that AOV:
    // albedo x (sun x max(n.l, 0) x shadow + ambient x multi-bounce(min(AO, material AO))),
    // the multi-bounce fit being Jimenez et al.'s cubic, times the exposure: scene-linear, no tone map.
    const voxel::World world = voxel::World::load(test::worldsDir() / "rooms.json");
    for (const bool temporal : {false, true}) {
        AoOptions ao = options("high");
        ao.chain.temporalHistory = temporal ? 16 : 0;
        const Rendered r = render(world, world.camera("table", 16.0 / 9.0), 161, 91, ao);
        const voxel::Lighting& l = world.desc().lighting;
        const glm::vec3 sun = l.sunColor * l.sunIntensity, ambient = l.ambientColor * l.ambientIntensity;
        int shaded = 0, occluded = 0;
        float worst = 0.0f;
        for (size_t i = 0; i < r.img.ao.size(); ++i) {
            const uint16_t id = r.img.surfaceIds[i];
            if (id == 0) continue;
            const float v = std::min(r.img.ao[i], world.desc().materials[gpu::surfaceMaterial(id) - 1].ao);
            const glm::vec3 n(r.img.normal[3 * i], r.img.normal[3 * i + 1], r.img.normal[3 * i + 2]);
            const float cosSun = std::max(glm::dot(n, l.sunDirection), 0.0f);
            for (int c = 0; c < 3; ++c) {
                const float a = r.img.albedo[3 * i + c];
                const float bounce =
                    std::max(v, (((2.0404f * a - 0.3324f) * v + (-4.7951f * a + 0.6417f)) * v + 2.7552f * a + 0.6903f) * v);
                const float expected = a * (sun[c] * cosSun * r.img.shadow[i] + ambient[c] * bounce) * l.exposure;
                worst = std::max(worst, std::abs(r.img.color[4 * i + c] - expected));
            }
            ++shaded;
            occluded += r.img.ao[i] < 0.9f;
        }
        EXPECT_GT(shaded, 161 * 91 / 2);
        EXPECT_GT(occluded, 100);  // there is AO to get wrong
        EXPECT_LT(worst, 1e-5f) << (temporal ? "with" : "without") << " the temporal pass";
    }
}

TEST_F(Gtao, MaxDistanceFadesAoOutOverItsLastTenth) {
    // Nearer than 0.9 D the AO is untouched, beyond D it is open, and in between it
    // is the linear blend towards open; the CPU twin agrees, with the search skipped.
    const voxel::World world = voxel::World::load(test::worldsDir() / "rooms.json");
    AoOptions unlimited = options("high");
    const Rendered a = render(world, world.camera("table", 16.0 / 9.0), 160, 90, unlimited);
    const glm::uvec2 half = a.constants.halfSize;
    auto depthAt = [&](uint32_t x, uint32_t y) { return a.img.depth[size_t(2 * y) * a.img.width + 2 * x]; };
    std::vector<float> depths;
    for (uint32_t y = 0; y < half.y; ++y)
        for (uint32_t x = 0; x < half.x; ++x)
            if (std::isfinite(depthAt(x, y))) depths.push_back(depthAt(x, y));
    std::nth_element(depths.begin(), depths.begin() + depths.size() / 2, depths.end());
    AoOptions limited = unlimited;
    limited.estimator.maxDistance = depths[depths.size() / 2];  // half the surface pixels lie beyond
    const float d = limited.estimator.maxDistance;
    const Rendered b = render(world, world.camera("table", 16.0 / 9.0), 160, 90, limited);
    const GtaoTwin twin(b.constants, b.img.depthBuffer, b.img.surfaceIds);
    int nearer = 0, fading = 0, beyond = 0, occludedNearer = 0;
    for (uint32_t y = 0; y < half.y; ++y)
        for (uint32_t x = 0; x < half.x; ++x) {
            const float z = depthAt(x, y);
            if (!std::isfinite(z)) continue;
            const size_t i = 2 * (size_t(y) * half.x + x);
            const float va = a.img.aoRawHalf[i], vb = b.img.aoRawHalf[i];
            EXPECT_EQ(a.img.aoRawHalf[i + 1], b.img.aoRawHalf[i + 1]) << "edges do not fade, pixel " << x << "," << y;
            if (z <= 0.9f * d) {
                EXPECT_EQ(vb, va) << "pixel " << x << "," << y << " at " << z << " of " << d;
                ++nearer, occludedNearer += va < 0.9f;
            } else if (z >= d) {
                EXPECT_EQ(vb, 1.0f) << "pixel " << x << "," << y << " at " << z << " of " << d;
                ++beyond;
            } else {
                const float fade = (z - 0.9f * d) / (0.1f * d);
                EXPECT_NEAR(vb, va + (1.0f - va) * fade, 1e-5f) << "pixel " << x << "," << y;
                ++fading;
            }
            if ((x + y) % 5 == 0) EXPECT_NEAR(twin.pixel(glm::ivec2(x, y)).x, vb, 1e-3f) << "twin at " << x << "," << y;
        }
    EXPECT_GT(nearer, 300);
    EXPECT_GT(occludedNearer, 20);  // there is AO the limit must not touch
    EXPECT_GT(beyond, 300);
    EXPECT_GT(fading, 20);
}

TEST_F(Gtao, CompositeTakesMaterialAoAndLeavesTheSunAlone) {
    // An open floor whose material is fully occluded: only the sun's Lambert term
    // remains, exactly albedo x sun x cos(sun elevation).
    std::vector<voxel::Material> palette = voxel::defaultMaterials();
    palette[0].ao = 0.0f;
    const voxel::World floor = test::makeVoxelWorld({-64, -1, -64}, {63, -1, 63}, [](int, int, int) { return true; },
                                                    1.0, glm::dvec3(0.0), palette);
    const voxel::Material m = floor.desc().materials[0];
    const voxel::Lighting l = floor.desc().lighting;
    const Rendered r = render(floor, test::lookAt({0, 10, 0.01}, {0, 0, 0}, 40.0), 32, 32, options("high"));
    const size_t centre = (16 * 32 + 16) * 4;
    for (int c = 0; c < 3; ++c)
        EXPECT_NEAR(r.img.color[centre + c],
                    m.albedo[c] * l.sunColor[c] * l.sunIntensity * l.sunDirection.y * l.exposure, 1e-4);
    EXPECT_GE(r.img.ao[16 * 32 + 16], 0.97f);  // the computed AO itself is open
}

}  // namespace
}  // namespace grotto

namespace grotto {
namespace {

// The numerical extremes we support: no NaN or Inf may reach an output.
TEST_F(Gtao, NumericalExtremesStayFinite) {
    auto hills = [](int x, int y, int z) { return y < 0 || (y < 6 && (x * 7 + z * 13) % 11 == 0); };
    const voxel::World near = test::makeVoxelWorld({-48, -2, -48}, {47, 6, 47}, hills);
    const voxel::World far = test::makeVoxelWorld({-48, -2, -48}, {47, 6, 47}, hills, 1.0, glm::dvec3(1e6, 0, -1e6));
    struct Extreme {
        const char* name;
        const voxel::World* world;
        voxel::CameraDesc camera;
        uint32_t width, height;
    };
    auto cam = [](glm::dvec3 p, glm::dvec3 t, double fov, double n = 0.05, double f = 0.0) {
        voxel::CameraDesc c = test::lookAt(p, t, fov);
        c.nearPlane = n;
        c.farPlane = f;
        return c;
    };
    const std::vector<Extreme> cases = {
        {"inside solid", &near, cam({0.2, -1.0, 0.3}, {5, -1, 5}, 60), 64, 48},
        {"sky only", &near, cam({0, 20, 0}, {0.1, 40, 0.2}, 60), 64, 48},
        {"fov 1", &near, cam({-30, 8, -30}, {10, 0, 10}, 1), 64, 48},
        {"fov 170", &near, cam({0, 3, 0}, {10, 0, 10}, 170), 64, 48},
        {"near 1e-4", &near, cam({0.3, 0.5, 0.3}, {10, -0.5, 10}, 60, 1e-4), 64, 48},
        {"finite far 1e7, near 10", &near, cam({-40, 30, -40}, {0, 0, 0}, 60, 10, 1e7), 64, 48},
        {"1e6 from the origin", &far, cam({1e6 - 30, 10, -1e6 - 30}, {1e6, 0, -1e6}, 60), 64, 48},
        {"4K", &near, cam({-40, 20, -40}, {0, 0, 0}, 60), 3840, 2160},
    };
    for (const Extreme& e : cases) {
        AoOptions ao = options("high", e.width > 1000 ? 40.0 : 4.0);  // 4K also gets a screen-filling radius
        const Rendered r = render(*e.world, e.camera, e.width, e.height, ao);
        size_t bad = 0;
        for (size_t i = 0; i < r.img.ao.size(); ++i) {
            if (!(r.img.ao[i] >= 0.0f && r.img.ao[i] <= 1.0f) || !(r.img.aoRaw[i] >= 0.0f && r.img.aoRaw[i] <= 1.0f)) {
                if (bad < 4) ADD_FAILURE() << e.name << ": pixel " << i << " AO " << r.img.ao[i] << ", raw " << r.img.aoRaw[i];
                ++bad;
            }
            for (int c = 0; c < 4; ++c)
                if (!std::isfinite(r.img.color[4 * i + c])) ++bad;
        }
        EXPECT_EQ(bad, 0u) << e.name;
    }
}

}  // namespace
}  // namespace grotto
