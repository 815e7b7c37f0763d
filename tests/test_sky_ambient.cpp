// Ambient light from the sky (lighting.ambient.from "sky"): the light the sky
// gradient casts on a surface, against its closed forms, and the composite
// lighting every pixel with it around VBAO's bent normal, or the surface's own
// normal with the other methods.
#include "engine/frame/sky_light.h"
#include "tests/ao_fixture.h"
#include "tests/scenes.h"

#include <algorithm>
#include <cmath>

namespace grotto {
namespace {

void expectNear(glm::vec3 got, glm::vec3 want, float tolerance, const char* what) {
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(got[c], want[c], tolerance) << what << ", channel " << c;
}

TEST(SkyLight, MatchesItsClosedForms) {
    // A uniform sky, 0.8 of it below the horizon: a floor gets all of it, a
    // ceiling 0.8 of it, a wall half of each.
    const glm::vec3 c(0.2f, 0.5f, 1.0f);
    expectNear(skyLight(1.0, c, c), c, 2e-3f, "floor");
    expectNear(skyLight(-1.0, c, c), 0.8f * c, 2e-3f, "ceiling");
    expectNear(skyLight(0.0, c, c), 0.9f * c, 2e-3f, "wall");
    // The gradient on a floor: the horizon plus (zenith - horizon) times
    // 2 x the integral of y^1.5 from 0 to 1, 0.8.
    const glm::vec3 zenith(0.28f, 0.45f, 0.78f), horizon(0.75f, 0.82f, 0.92f);
    expectNear(skyLight(1.0, zenith, horizon), horizon + 0.8f * (zenith - horizon), 2e-3f, "gradient, floor");
    // Brighter the more a surface faces up, wherever the zenith outshines the horizon.
    const auto rows = skyLightTable(horizon, zenith * 0.5f);
    for (int k = 0; k < GROTTO_SKY_LIGHT_ROWS; ++k)
        expectNear(rows[k], skyLight(-1.0 + k / 4.0, horizon, zenith * 0.5f), 1e-6f, "the table's rows");
    for (int k = 1; k < GROTTO_SKY_LIGHT_ROWS; ++k) EXPECT_GT(rows[k].x, rows[k - 1].x);
}

using SkyAmbient = test::AoFixture;

// Every surface pixel's colour: sun x shadow + the intensity x the sky's light
// facing its bent normal (VBAO) or its normal (GTAO, as the table the composite
// interpolates), times AO with multi-bounce, times the exposure.
TEST_F(SkyAmbient, EveryPixelIsLitByTheSkyAroundItsBentNormal) {
    const voxel::World corner = test::makeVoxelWorld({-40, -40, -60}, {40, 40, 60}, [](int x, int y, int z) {
        return (y < 0 && x >= -40) || (x < 0 && y >= 0) || (z == 4 && x == 6 && y < 5);
    });
    voxel::Lighting l = corner.desc().lighting;
    l.ambientFrom = voxel::AmbientSource::Sky;
    l.ambientIntensity = 1.3f;
    const auto rows = skyLightTable(l.skyZenith, l.skyHorizon);
    for (const AoMethod method : {AoMethod::Vbao, AoMethod::Gtao}) {
        const bool vbao = method == AoMethod::Vbao;
        const test::Rendered r = render(corner, test::lookAt({14, 14, 24}, {0, 0, 0}, 60.0), 96, 72, options("high", 4.0, method), &l);
        ASSERT_EQ(r.img.bentNormal.empty(), !vbao);
        float worst = 0.0f;
        int shaded = 0, bent = 0;
        for (size_t i = 0; i < r.img.ao.size(); ++i) {
            const uint16_t id = r.img.surfaceIds[i];
            if (id == 0) continue;
            const glm::vec3 n(r.img.normal[3 * i], r.img.normal[3 * i + 1], r.img.normal[3 * i + 2]);
            glm::vec3 toward = n;
            if (vbao) {
                const glm::vec3 b(r.img.bentNormal[3 * i], r.img.bentNormal[3 * i + 1], r.img.bentNormal[3 * i + 2]);
                if (glm::dot(b, b) > 0.25f) toward = b;
                bent += glm::dot(b, n) < 0.99f;
            }
            const float t = (std::clamp(toward.y, -1.0f, 1.0f) * 0.5f + 0.5f) * float(GROTTO_SKY_LIGHT_ROWS - 1);
            const int row = std::min(int(t), GROTTO_SKY_LIGHT_ROWS - 2);
            const glm::vec3 sky = l.ambientIntensity * glm::mix(rows[row], rows[row + 1], t - float(row));
            const float v = std::min(r.img.ao[i], corner.desc().materials[gpu::surfaceMaterial(id) - 1].ao);
            const float cosSun = std::max(glm::dot(n, l.sunDirection), 0.0f);
            for (int c = 0; c < 3; ++c) {
                const float a = r.img.albedo[3 * i + c];
                const float bounce =
                    std::max(v, (((2.0404f * a - 0.3324f) * v + (-4.7951f * a + 0.6417f)) * v + 2.7552f * a + 0.6903f) * v);
                const float expected = a * (l.sunColor[c] * l.sunIntensity * cosSun * r.img.shadow[i] + sky[c] * bounce) * l.exposure;
                worst = std::max(worst, std::abs(r.img.color[4 * i + c] - expected));
            }
            ++shaded;
        }
        EXPECT_GT(shaded, 96 * 72 / 2);
        if (vbao) EXPECT_GT(bent, 200) << "bent normals that differ from the normals, to get wrong";
        EXPECT_LT(worst, 2e-5f) << aoMethodName(method);
    }
}

}  // namespace
}  // namespace grotto
