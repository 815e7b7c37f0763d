// The G-buffer against a CPU ray cast of the same grid: depth at random pixel
// centres within 1e-4 relative error, sky where the ray escapes, normals equal to
// the face the ray entered; near 1e-4 and a camera 1e6 units from the origin.
#include "engine/renderer.h"
#include "tests/gpu_fixture.h"
#include "voxel/solid.h"

#include <random>

namespace grotto {
namespace {

using test::GpuTest;

// A floor with random pillars and floating blocks, placed at `offset` in world units.
voxel::World terrain(glm::dvec3 offset, double voxelSize) {
    openvdb::initialize();
    auto grid = openvdb::Int32Grid::create(0);
    grid->setTransform(openvdb::math::Transform::createLinearTransform(voxelSize));
    grid->transform().postTranslate(openvdb::Vec3d(offset.x, offset.y, offset.z));
    auto acc = grid->getAccessor();
    std::mt19937 rng(3);
    std::uniform_int_distribution<int> pos(-40, 40), height(1, 12), mat(1, 4);
    for (int x = -48; x < 48; ++x)
        for (int z = -48; z < 48; ++z) acc.setValueOn(openvdb::Coord(x, 0, z), 1);
    for (int i = 0; i < 60; ++i) {
        const int x = pos(rng), z = pos(rng), h = height(rng), m = mat(rng), y0 = i % 3 == 0 ? 6 : 1;
        for (int y = y0; y < y0 + h; ++y)
            for (int dx = 0; dx < 1 + i % 4; ++dx) acc.setValueOn(openvdb::Coord(x + dx, y, z), m);
    }
    voxel::WorldDesc d;
    d.materials = voxel::defaultMaterials();
    return voxel::makeWorld(grid, d);
}

struct Case {
    const char* name;
    glm::dvec3 worldOffset;
    glm::dvec3 eye, target;  // relative to worldOffset
    double nearPlane, farPlane;
    uint32_t width, height;
};
// What test listings print for a case (gtest would dump its bytes).
void PrintTo(const Case& c, std::ostream* os) { *os << c.name; }

class GBuffer : public GpuTest, public ::testing::WithParamInterface<Case> {};

TEST_P(GBuffer, DepthAndNormalsMatchCpuRayCast) {
    const Case k = GetParam();
    const double vs = 0.5;
    const voxel::World world = terrain(k.worldOffset, vs);
    voxel::CameraDesc cd;
    cd.position = k.worldOffset + k.eye;
    cd.target = k.worldOffset + k.target;
    cd.nearPlane = k.nearPlane;
    cd.farPlane = k.farPlane;
    const Camera camera = makeCamera(cd, k.width, k.height);
    auto scene = uploadScene(ctx(), world.mesh(), world.desc());
    FrameImages img;
    {
        Renderer renderer(ctx(), *scene, world.desc().lighting, aoOptionsFor(world.desc().ao, vs, "test"), k.width, k.height);
        renderer.render(camera);
        img = renderer.readback(camera, true);
    }

    const glm::dvec3 forward = -camera.basis[2];
    std::mt19937 rng(11);
    std::uniform_int_distribution<uint32_t> px(0, k.width - 1), py(0, k.height - 1);
    int compared = 0, sky = 0;
    for (int i = 0; i < 1500; ++i) {
        const uint32_t x = px(rng), y = py(rng);
        auto cast = [&](double dx, double dy) {
            return world.raycast(camera.position, camera.rayDirection(x + 0.5 + dx, y + 0.5 + dy), 1e9);
        };
        const auto hit = cast(0, 0);
        // Skip pixels within a twentieth of a pixel of a silhouette or a face edge.
        bool edge = false;
        for (auto [dx, dy] : {std::pair{0.05, 0.0}, {-0.05, 0.0}, {0.0, 0.05}, {0.0, -0.05}}) {
            const auto h = cast(dx, dy);
            if (bool(h) != bool(hit) || (h && (h->face != hit->face || h->voxel != hit->voxel))) edge = true;
        }
        if (edge) continue;
        const size_t p = size_t(y) * k.width + x;
        if (!hit || (k.farPlane > 0 && hit->distance * glm::dot(camera.rayDirection(x + 0.5, y + 0.5), forward) > k.farPlane)) {
            EXPECT_TRUE(std::isinf(img.depth[p])) << "pixel " << x << "," << y << " should be sky";
            ++sky;
            continue;
        }
        const double expected = hit->distance * glm::dot(camera.rayDirection(x + 0.5, y + 0.5), forward);
        EXPECT_NEAR(img.depth[p] / expected, 1.0, 1e-4) << "pixel " << x << "," << y;
        glm::vec3 n(0.0f);
        n[hit->face / 2] = hit->face % 2 == 0 ? 1.0f : -1.0f;
        EXPECT_EQ(glm::vec3(img.normal[3 * p], img.normal[3 * p + 1], img.normal[3 * p + 2]), n)
            << "pixel " << x << "," << y;
        ++compared;
    }
    EXPECT_GT(compared, 200);
    for (float c : img.color) ASSERT_TRUE(std::isfinite(c));
}

INSTANTIATE_TEST_SUITE_P(
    Cameras, GBuffer,
    ::testing::Values(Case{"overview", {0, 0, 0}, {30, 18, 34}, {0, 0, 0}, 0.05, 0.0, 192, 108},
                      Case{"near1e4", {0, 0, 0}, {3.3, 1.2, 2.9}, {-4, 0.5, -6}, 1e-4, 0.0, 160, 90},
                      Case{"far1e6", {1e6, 250, -1e6}, {25, 9, -30}, {0, 0, 0}, 0.05, 0.0, 160, 90},
                      Case{"finite", {0, 0, 0}, {30, 18, 34}, {0, 0, 0}, 0.5, 45.0, 160, 90},
                      Case{"odd333x177", {0, 0, 0}, {-20, 25, 20}, {0, 0, 0}, 0.05, 0.0, 333, 177}),
    [](const auto& info) { return std::string(info.param.name); });

TEST_F(GpuTest, TinyImagesRenderFiniteValues) {
    const voxel::World world = terrain({0, 0, 0}, 1.0);
    auto scene = uploadScene(ctx(), world.mesh(), world.desc());
    for (auto [w, h] : {std::pair{1u, 1u}, {2u, 2u}, {3u, 1u}}) {
        const Camera camera = worldCamera(world, "", w, h);
        Renderer renderer(ctx(), *scene, world.desc().lighting, aoOptionsFor(world.desc().ao, 1.0, "test"), w, h);
        renderer.render(camera);
        const FrameImages img = renderer.readback(camera, true);
        ASSERT_EQ(img.color.size(), size_t(4) * w * h);
        for (float c : img.color) EXPECT_TRUE(std::isfinite(c)) << w << "x" << h;
    }
}

}  // namespace
}  // namespace grotto
