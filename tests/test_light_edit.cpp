// Full light after an edit (voxel/light_edit.h, relightFaces): the faces the edit's
// rays reach and those whose light it moved are lit again, and the cache then
// matches a fresh bake of the edited world. A lamp taken out of a sealed room
// leaves no light at all.
#include "dense_world.h"
#include "voxel/brick_table.h"
#include "voxel/face_bake.h"
#include "voxel/face_cache_edit.h"
#include "voxel/light_bake.h"
#include "voxel/light_edit.h"
#include "voxel/luminance.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

namespace grotto::voxel {
namespace {

constexpr uint32_t kSide = 2, kPerFace = kSide * kSide;
const FaceBakeSettings kSettings{.radius = 3.0, .texelsPerSide = kSide, .rays = 32, .fullLight = true};

Material stone(float albedo, float emission = 0.0f) {
    Material m;
    m.albedo = glm::vec3(albedo);
    if (emission > 0.0f) m.emissionColor = glm::vec3(1.0f, 0.8f, 0.6f), m.emissionIntensity = emission;
    return m;
}

// A sealed room 24 x 10 x 16 of albedo 0.5 (material 1), lamps of material 2.
const glm::ivec3 kRoom(24, 10, 16);
constexpr size_t kInsideFaces = 2 * (22 * 8 + 22 * 14 + 8 * 14);  // its walls', floor's and ceiling's
World sealedRoom(std::vector<glm::ivec3> lamps) {
    return test::denseWorld(kRoom, {stone(0.5f), stone(0.8f, 12.0f)}, [&](int x, int y, int z) {
        if (std::find(lamps.begin(), lamps.end(), glm::ivec3(x, y, z)) != lamps.end()) return 2;
        return x == 0 || y == 0 || z == 0 || x == kRoom.x - 1 || y == kRoom.y - 1 || z == kRoom.z - 1 ? 1 : 0;
    });
}

std::vector<FaceTexel> freshBake(const BrickTable& table, const World& world, const std::vector<ExposedFace>& faces) {
    std::vector<FaceTexel> texels(faces.size() * kPerFace);
    bakeFaces(table, world, faces, kSettings, texels);
    bakeLight(table, world, faces, kSide, lightSources(world.desc().lighting), {}, texels);
    return texels;
}

// A world with its cache, edited as LiveFaceCache does it.
struct LitWorld {
    World world;
    BrickTable table;
    std::vector<ExposedFace> faces;
    std::vector<FaceTexel> texels;
    std::vector<GlowingFace> glowing;

    explicit LitWorld(World w) : world(std::move(w)), table(world), faces(exposedFaces(table, world)) {
        texels = freshBake(table, world, faces);
        glowing = glowingFaces(world, faces);
    }
    // Returns the faces lit again.
    size_t edit(const Edit& e) {
        const EditResult result = world.apply(e);
        table.update(world, result.voxels);
        std::vector<FaceReach> reach;
        const std::vector<ExposedFace> before = faces;
        const std::vector<glm::vec3> sentBefore = sentLight(world, faces, texels, kSide);
        updateAfterEdit(table, world, result.voxels, kSettings, faces, texels, nullptr, true, &reach);
        const RelightStats stats =
            relightAfterEdit(table, world, faces, kSide, texels, reach, result.voxels, before, sentBefore, glowing);
        glowing = glowingFaces(world, faces);
        std::printf("[ measured ] %llu faces lit again of %zu, %u rounds of bounced change\n",
                    (unsigned long long)stats.faces, faces.size(), stats.rounds);
        return stats.faces;
    }
};

double lightOf(const FaceTexel& t) { return luminance(glm::dvec3(t.light)); }

TEST(LightEdit, ALampTakenOutOfASealedRoomLeavesNoLight) {
    const glm::ivec3 lamp(6, 4, 8);
    LitWorld lit(sealedRoom({lamp}));
    ASSERT_GT(lit.glowing.size(), 0u);
    double before = 0.0;
    for (const FaceTexel& t : lit.texels) before = std::max(before, lightOf(t));
    ASSERT_GT(before, 0.1);
    lit.edit(Edit::carveBox({lamp, lamp}));
    EXPECT_TRUE(lit.glowing.empty());
    // Outside, the sky lights the walls; inside nothing is left.
    size_t inside = 0;
    for (size_t t = 0; t < lit.texels.size(); ++t) {
        const ExposedFace& f = lit.faces[t / kPerFace];
        const glm::ivec3 open = f.cell + glm::ivec3(faceNormal(f.dir));
        if (glm::any(glm::lessThan(open, glm::ivec3(1))) || glm::any(glm::greaterThan(open, kRoom - 2))) continue;
        ++inside;
        ASSERT_EQ(lit.texels[t].light, glm::vec3(0.0f))
            << "texel " << t << " of the face of (" << f.cell.x << ", " << f.cell.y << ", " << f.cell.z << ")";
    }
    EXPECT_EQ(inside, kInsideFaces * kPerFace);
}

// Every texel against a fresh bake of the world as it is now: within 5% of the
// larger of its own light and the mean. The rule leaves up to 1/64 standing, and
// the two bakes' noise differs where the light is dim: a texel's rays more where
// it is noisy depend on the whole bake's (LightBakeSettings::extraShare).
void expectLikeAFreshBake(const LitWorld& lit, const char* what) {
    const std::vector<FaceTexel> fresh = freshBake(lit.table, lit.world, lit.faces);
    double mean = 0.0, worst = 0.0;
    for (const FaceTexel& t : fresh) mean += lightOf(t) / double(fresh.size());
    for (size_t t = 0; t < fresh.size(); ++t) {
        const double error = std::abs(lightOf(lit.texels[t]) - lightOf(fresh[t])) / std::max(lightOf(fresh[t]), mean);
        worst = std::max(worst, error);
        const ExposedFace& f = lit.faces[t / kPerFace];
        ASSERT_LT(error, 0.05) << what << ": texel " << t << " holds " << lightOf(lit.texels[t]) << ", a fresh bake "
                               << lightOf(fresh[t]) << "; its face (" << f.cell.x << ", " << f.cell.y << ", " << f.cell.z
                               << ") looking " << int(f.dir) << ", of mean light " << mean;
    }
    std::printf("[ measured ] %s: worst texel off by %.4f of max(its light, the mean)\n", what, worst);
}

TEST(LightEdit, LampsPlacedAndWallsBuiltInALitRoomMatchAFreshBake) {
    LitWorld lit(sealedRoom({{4, 3, 4}}));
    // A lamp placed in the dark far end: the room lit again, as a fresh bake.
    size_t relit = lit.edit(Edit::fillBox({{19, 5, 11}, {19, 5, 11}}, 2));
    EXPECT_GE(relit, kInsideFaces);  // all of the room's inside
    expectLikeAFreshBake(lit, "a lamp placed");
    // A wall across the room between the two lamps, with a door: what lay in
    // each lamp's sight beyond it goes dark, though far from the wall's rays.
    relit = lit.edit(Edit::fillBox({{12, 1, 1}, {12, 8, 14}}, 1));
    expectLikeAFreshBake(lit, "a wall built");
    lit.edit(Edit::carveBox({{12, 1, 6}, {12, 4, 8}}));
    expectLikeAFreshBake(lit, "a door cut");
    // The first lamp painted over with stone: its light goes, the other's stays.
    lit.edit(Edit::fillBox({{4, 3, 4}, {4, 3, 4}}, 1));
    expectLikeAFreshBake(lit, "a lamp replaced");
}

TEST(LightEdit, AnEditFarFromEveryLampLightsLittleAgain) {
    // A lamp in a corner of the room and a pillar built in the far corner, out
    // of the lamp's reach but for light too dim to matter: only the faces the
    // pillar's rays reach are lit again, not the room.
    LitWorld lit(sealedRoom({{2, 2, 2}}));
    const size_t relit = lit.edit(Edit::fillBox({{21, 1, 13}, {21, 3, 13}}, 1));
    EXPECT_LT(relit, lit.faces.size() / 4);
    expectLikeAFreshBake(lit, "a pillar far off");
}

}  // namespace
}  // namespace grotto::voxel
