// The face cache's full light (voxel/light_bake.h) against closed forms and the
// path tracer: a closed box whose walls glow (every bounce, e / (1 - a)), open
// ground under a uniform sky, and one glowing voxel in a closed dark room.
#include "dense_world.h"
#include "shaders/shared/quad.h"
#include "tests/test_util.h"
#include "voxel/brick_table.h"
#include "voxel/face_bake.h"
#include "voxel/form_factor.h"
#include "voxel/light_bake.h"
#include "voxel/path_trace.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <numbers>

namespace grotto::voxel {
namespace {

using glm::dvec3;

Material glowing(float albedo, float emission) {
    Material m;
    m.albedo = glm::vec3(albedo);
    if (emission > 0.0f) m.emissionColor = glm::vec3(1.0f), m.emissionIntensity = emission;
    return m;
}

using test::denseWorld;

// A world's faces baked with full light under `lights`.
struct Baked {
    std::vector<ExposedFace> faces;
    std::vector<FaceTexel> texels;
    LightBakeStats stats;
};
// The faces with what bakeFaces gives their texels (AO, sky, the sun's bits): all
// the light bake starts from.
Baked unlit(const BrickTable& table, const World& world, const LightSources& lights, uint32_t k) {
    Baked b;
    b.faces = exposedFaces(table, world);
    b.texels.resize(b.faces.size() * k * k);
    FaceBakeSettings s;
    s.texelsPerSide = k;
    s.sunDirection = lights.sunDirection;
    bakeFaces(table, world, b.faces, s, b.texels);
    return b;
}
Baked bake(const World& world, const LightSources& lights, uint32_t k = 3, LightBakeSettings ls = {}) {
    const BrickTable table(world);
    Baked b = unlit(table, world, lights, k);
    b.stats = bakeLight(table, world, b.faces, k, lights, ls, b.texels);
    return b;
}

bool inside(const ExposedFace& f, int edge) {
    const glm::ivec3 open = f.cell + glm::ivec3(faceNormal(f.dir));
    return glm::all(glm::greaterThan(open, glm::ivec3(0))) && glm::all(glm::lessThan(open, glm::ivec3(edge - 1)));
}

TEST(LightBake, AClosedBoxWhoseWallsGlowHoldsEOverOneMinusA) {
    // Every inner texel sees glowing walls whichever way it looks: e in closed
    // form, then a x e per bounce, summing to e / (1 - a), with no noise at all.
    const int edge = 6;
    const float a = 0.6f, e = 2.0f;
    const World box = denseWorld(glm::ivec3(edge), {glowing(a, e)}, [edge](int x, int y, int z) {
        return x == 0 || y == 0 || z == 0 || x == edge - 1 || y == edge - 1 || z == edge - 1 ? 1 : 0;
    });
    LightBakeSettings ls;
    ls.tolerance = 1e-6;
    const Baked b = bake(box, LightSources{}, 3, ls);
    EXPECT_GT(b.stats.passes, 10u);  // a^n falls under 1e-6 only after many bounces
    const double expected = e / (1.0 - a);
    int checked = 0;
    for (size_t f = 0; f < b.faces.size(); ++f) {
        if (!inside(b.faces[f], edge)) continue;
        for (size_t t = f * 9; t < f * 9 + 9; ++t, ++checked)
            for (int c = 0; c < 3; ++c) ASSERT_NEAR(b.texels[t].light[c], expected, 2e-4 * expected) << "texel " << t;
    }
    EXPECT_EQ(checked, 6 * 16 * 9);
}

TEST(LightBake, OpenGroundGetsTheSkyAndNoSun) {
    // A slab under a uniform sky: every ray up leaves, so the light is the sky's
    // radiance exactly; the sun's direct beam is the frame's, not the cache's.
    const World slab = denseWorld({16, 1, 16}, {glowing(0.5f, 0.0f)}, [](int, int, int) { return 1; });
    LightSources lights;
    lights.skyZenith = lights.skyHorizon = dvec3(1.0);
    lights.skyIntensity = 0.7;
    lights.sun = dvec3(2.0);
    lights.sunDirection = glm::normalize(dvec3(0.3, 1.0, 0.2));
    const Baked b = bake(slab, lights);
    for (size_t f = 0; f < b.faces.size(); ++f) {
        if (b.faces[f].dir != 2) continue;  // the top
        for (size_t t = f * 9; t < f * 9 + 9; ++t)
            for (int c = 0; c < 3; ++c) ASSERT_NEAR(b.texels[t].light[c], 0.7, 1e-6);
    }
}

TEST(LightBake, OneGlowingVoxelInAClosedDarkRoomMatchesThePathTracer) {
    // The target: every texel within 16 voxels of a lone glowing voxel
    // within 2% of the path-traced light after the default bake. Walls of albedo
    // 0.5 send a third of the light back, so bounces matter.
    const glm::ivec3 size(22, 10, 22), lamp(11, 4, 11);
    const World room = denseWorld(size, {glowing(0.5f, 0.0f), glowing(0.0f, 20.0f)}, [&](int x, int y, int z) {
        if (glm::ivec3(x, y, z) == lamp) return 2;
        return x == 0 || y == 0 || z == 0 || x == size.x - 1 || y == size.y - 1 || z == size.z - 1 ? 1 : 0;
    });
    const Baked b = bake(room, LightSources{});
    // Texels spread over the floor, ceiling and walls, one in 757.
    std::vector<dvec3> points, normals;
    std::vector<size_t> which;
    for (size_t f = 0; f < b.faces.size(); ++f) {
        const ExposedFace& face = b.faces[f];
        if (face.cell == lamp) continue;
        for (uint32_t t = 0; t < 9; ++t) {
            const size_t index = f * 9 + t;
            if (index % 757 != 0) continue;
            const dvec3 p = texelPoint(face, 3, t % 3, t / 3);
            if (glm::length(p - (dvec3(lamp) + 0.5)) > 16.0) continue;
            const glm::ivec3 open = face.cell + glm::ivec3(faceNormal(face.dir));
            if (!glm::all(glm::greaterThan(open, glm::ivec3(0))) || !glm::all(glm::lessThan(open, size - 1))) continue;
            points.push_back(p), normals.push_back(faceNormal(face.dir)), which.push_back(index);
        }
    }
    ASSERT_GE(points.size(), 10u);
    PathTraceSettings s;
    // The reference's own error under 0.5% (1% under the sanitizers, whose quarter
    // of the paths took most of the test's time; the tolerance counts it).
    s.spp = grotto::test::underSanitizers(1 << 18, 1 << 16);
    const PathTraced reference = pathTrace(room, {}, points, normals, {}, LightSources{}, s);
    double worst = 0.0;
    for (size_t k = 0; k < points.size(); ++k) {
        const double want = reference.radiance[k].r, got = 0.5 * b.texels[which[k]].light.r;
        const double error = std::abs(got - want) / want;
        ASSERT_LT(reference.stderror[k].r, grotto::test::underSanitizers(1, 2) * 0.005 * want) << "the reference is too noisy at point " << k;
        worst = std::max(worst, error);
        EXPECT_LT(std::abs(got - want), 0.02 * want + 2.0 * reference.stderror[k].r)
            << "texel " << which[k] << " at (" << points[k].x << ", " << points[k].y << ", " << points[k].z << ")";
    }
    RecordProperty("worst_relative_error", std::to_string(worst));
}

TEST(LightBake, APolygonsFormFactorIsLambertsClosedForm) {
    // A unit square straight over a point at height h: the closed form for a
    // receiver under a corner of an a x b rectangle, four times over.
    const double h = 0.75;
    auto corner = [](double a, double b, double c) {
        const double x = a / c, y = b / c;
        return (x / std::sqrt(1 + x * x) * std::atan(y / std::sqrt(1 + x * x)) +
                y / std::sqrt(1 + y * y) * std::atan(x / std::sqrt(1 + y * y))) / (2.0 * std::numbers::pi);
    };
    const dvec3 square[4] = {{-0.5, h, -0.5}, {0.5, h, -0.5}, {0.5, h, 0.5}, {-0.5, h, 0.5}};
    EXPECT_NEAR(polygonFormFactor(dvec3(0.0), dvec3(0, 1, 0), square), 4.0 * corner(0.5, 0.5, h), 1e-12);
    // Half of it below the receiver's horizon (tilted receiver): only the clipped half counts.
    const dvec3 tilted = glm::normalize(dvec3(1, 0, 0));
    const dvec3 wall[4] = {{1.0, -0.5, -0.5}, {1.0, 0.5, -0.5}, {1.0, 0.5, 0.5}, {1.0, -0.5, 0.5}};
    EXPECT_NEAR(polygonFormFactor(dvec3(0.0), tilted, wall), 4.0 * corner(0.5, 0.5, 1.0), 1e-12);
    // Straddling the horizon of an upright receiver: the half above it, alone.
    const dvec3 upperHalf[4] = {{1.0, 0.0, -0.5}, {1.0, 0.5, -0.5}, {1.0, 0.5, 0.5}, {1.0, 0.0, 0.5}};
    const double half = polygonFormFactor(dvec3(0.0), dvec3(0, 1, 0), upperHalf);
    EXPECT_GT(half, 0.01);
    EXPECT_NEAR(polygonFormFactor(dvec3(0.0), dvec3(0, 1, 0), wall), half, 1e-12);
}

// Relative errors of texels against the path-traced light at their points.
struct Errors {
    double worst = 0.0, median = 0.0;
};

// A closed room of albedo 0.6 (walls one voxel thick) with `open` cells cut out
// of its walls, baked with the default settings and with the same rays a texel
// all cosine-weighted. Texels spread over its inner faces (not the floor when
// `floor` is false), out of the sun and none within a voxel of another wall,
// are held to the path tracer: the guided bake's each within 3% (and 3 of the
// reference's standard errors); its median within 3% and under a third of the
// cosine rays', and its worst under a third of theirs. What is measured is the
// bounce's noise, not how finely a texel follows a shadow's edge or a corner's light.
void expectGuidedRaysTakeOutTheBlotches(const std::function<bool(glm::ivec3)>& open, const LightSources& lights,
                                        bool floor) {
    const glm::ivec3 size(18, 10, 18);
    const World room = denseWorld(size, {glowing(0.6f, 0.0f)}, [&](int x, int y, int z) {
        if (open({x, y, z})) return 0;
        return x == 0 || y == 0 || z == 0 || x == size.x - 1 || y == size.y - 1 || z == size.z - 1 ? 1 : 0;
    });
    // Both bakes start from the same faces' bake; their light's rays differ.
    const BrickTable table(room);
    Baked guided = unlit(table, room, lights, 3), cosine = guided;
    guided.stats = bakeLight(table, room, guided.faces, 3, lights, {}, guided.texels);
    LightBakeSettings cosineOnly;
    cosineOnly.rays += cosineOnly.guidedRays;
    cosineOnly.guidedRays = 0;
    cosine.stats = bakeLight(table, room, cosine.faces, 3, lights, cosineOnly, cosine.texels);

    std::vector<dvec3> points, normals;
    std::vector<size_t> which;
    for (size_t f = 0; f < guided.faces.size(); ++f) {
        const ExposedFace& face = guided.faces[f];
        const glm::ivec3 cell = face.cell + glm::ivec3(faceNormal(face.dir));
        const int axis = int(gpu::faceAxis(face.dir));
        bool clear = cell[axis] > 0 && cell[axis] < size[axis] - 1 && (floor || face.dir != 2);
        for (int a = 0; a < 3; ++a) clear = clear && (a == axis || (cell[a] >= 2 && cell[a] <= size[a] - 3));
        if (!clear) continue;
        for (uint32_t t = 0; t < 9; ++t) {
            const size_t index = f * 9 + t;
            if (index % 311 != 0 || guided.texels[index].sun() * lights.sun.r > 0.0) continue;
            points.push_back(texelPoint(face, 3, t % 3, t / 3)), normals.push_back(faceNormal(face.dir));
            which.push_back(index);
        }
    }
    ASSERT_GE(points.size(), 12u);
    PathTraceSettings s;
    s.spp = 1 << 17;
    const PathTraced reference = pathTrace(room, {}, points, normals, {}, lights, s);
    auto errors = [&](const Baked& b, double within) {
        std::vector<double> relative;
        for (size_t k = 0; k < points.size(); ++k) {
            const double want = reference.radiance[k].r, got = 0.6 * b.texels[which[k]].light.r;
            EXPECT_LT(reference.stderror[k].r, 0.03 * want) << "the reference is too noisy at point " << k;
            relative.push_back(std::abs(got - want) / want);
            EXPECT_LT(std::abs(got - want), within * want + 3.0 * reference.stderror[k].r)
                << "texel " << which[k] << " at (" << points[k].x << ", " << points[k].y << ", " << points[k].z << ")";
        }
        std::sort(relative.begin(), relative.end());
        return Errors{relative.back(), relative[relative.size() / 2]};
    };
    const Errors drawn = errors(guided, 0.03), alone = errors(cosine, 1.0);
    std::printf("relative error over %zu texels, worst and median: with the drawn rays %.1f%%, %.1f%%; cosine rays "
                "alone %.1f%%, %.1f%%\n", points.size(), 100.0 * drawn.worst, 100.0 * drawn.median,
                100.0 * alone.worst, 100.0 * alone.median);
    EXPECT_LT(drawn.median, 0.03);
    EXPECT_GT(alone.median, 3.0 * drawn.median);  // what the drawn rays take out
    EXPECT_GT(alone.worst, 3.0 * drawn.worst);
}

TEST(LightBake, ARoomLitOffASunlitPatchMatchesThePathTracerEverywhere) {
    // The sun straight down through a hole in the roof, no sky: every texel off
    // the sunlit patch on the floor takes its light off that patch first. Cosine
    // rays find it a few times in a hundred, so neighbouring texels read it
    // unevenly (blotches); rays drawn toward the faces that pass a region its
    // light read it nearly exactly.
    LightSources lights;
    lights.sun = dvec3(3.0);
    lights.sunDirection = dvec3(0.0, 1.0, 0.0);
    expectGuidedRaysTakeOutTheBlotches([](glm::ivec3 c) { return c.y == 9 && c.x >= 6 && c.x <= 8 && c.z >= 6 && c.z <= 8; },
                                       lights, false);
}

}  // namespace
}  // namespace grotto::voxel
