// Closed rooms seen from inside: no pixel may show the sky (a pinhole between
// quads) or be lit by the sun (a shadow ray that slipped out), from many random
// cameras (positions, orientations, fields of view, image sizes, odd ones among
// them) in rooms of many sizes with furniture, walls one or two voxels thick and
// the sun anywhere. A third of the cameras stand on voxel corners and look along
// axes or diagonals, as a user places them, so whole rows of pixels see surface
// points exactly on voxel boundaries; a third look straight into the edge where
// two walls (or a wall and the floor or ceiling) meet, so their centre pixel sees
// a point exactly on it.
#include "engine/renderer.h"
#include "tests/gpu_fixture.h"
#include "tests/scenes.h"

#include <glm/geometric.hpp>

#include <cmath>
#include <cstdio>
#include <random>

namespace grotto {
namespace {

struct Room {
    glm::ivec3 lo, hi;  // the inside, inclusive
    int wall = 1;
    std::vector<std::pair<glm::ivec3, glm::ivec3>> furniture;  // boxes inside, inclusive
    bool solid(int x, int y, int z) const {
        const glm::ivec3 p(x, y, z);
        if (glm::any(glm::lessThan(p, lo - wall)) || glm::any(glm::greaterThan(p, hi + wall))) return false;
        if (glm::any(glm::lessThan(p, lo)) || glm::any(glm::greaterThan(p, hi))) return true;
        for (const auto& [a, b] : furniture)
            if (glm::all(glm::greaterThanEqual(p, a)) && glm::all(glm::lessThanEqual(p, b))) return true;
        return false;
    }
    // Farther than the near plane (0.05) from every solid voxel (p in voxel-corner units).
    bool clear(glm::dvec3 p) const {
        for (int i = 0; i < 8; ++i) {
            const glm::dvec3 q = p + glm::dvec3(i & 1 ? 0.1 : -0.1, i & 2 ? 0.1 : -0.1, i & 4 ? 0.1 : -0.1);
            if (solid(int(std::floor(q.x)), int(std::floor(q.y)), int(std::floor(q.z)))) return false;
        }
        return true;
    }
};

using ClosedRooms = test::GpuTest;

TEST_F(ClosedRooms, ShowNoSkyAndNoSunFromInside) {
    std::mt19937 rng(22);
    auto uniform = [&](double a, double b) { return std::uniform_real_distribution<double>(a, b)(rng); };
    auto integer = [&](int a, int b) { return std::uniform_int_distribution<int>(a, b)(rng); };
    size_t sky = 0, lit = 0, pixels = 0, frames = 0;
    for (int r = 0; r < 8; ++r) {
        Room room;
        const glm::ivec3 size(integer(5, 40), integer(4, 20), integer(5, 40));
        room.lo = glm::ivec3(integer(-40, 20), integer(-40, 20), integer(-40, 20));  // across chunk borders
        room.hi = room.lo + size - 1;
        room.wall = 1 + r / 2 % 2;
        for (int k = integer(3, 12); k > 0; --k) {  // on the floor, or anywhere
            glm::ivec3 a(integer(room.lo.x, room.hi.x), room.lo.y, integer(room.lo.z, room.hi.z));
            if (k % 3 == 1) a.y = integer(room.lo.y, room.hi.y);
            room.furniture.push_back({a, glm::min(a + glm::ivec3(integer(0, 4), integer(0, 3), integer(0, 4)), room.hi)});
        }
        const voxel::World world = test::makeVoxelWorld(room.lo - room.wall, room.hi + room.wall,
                                                        [&](int x, int y, int z) { return room.solid(x, y, z); });
        auto scene = uploadScene(ctx(), world);
        AoOptions noAo;
        noAo.estimator = estimatorPreset("high", 2.0);
        noAo.enabled = false;
        voxel::Lighting lighting = world.desc().lighting;
        lighting.sunShadows = true;
        // The sun anywhere, half the time along a diagonal through voxel edges and corners.
        glm::dvec3 sun(uniform(-1, 1), uniform(-1, 1), uniform(-1, 1));
        if (r % 2 == 0) sun = glm::dvec3(integer(0, 1) * 2 - 1, integer(0, 1) * 2 - 1, integer(0, 2) - 1);
        lighting.sunDirection = glm::vec3(glm::normalize(sun));
        Renderer renderer(ctx(), *scene, lighting, noAo, 64, 48);
        for (int c = 0; c < 60; ++c) {
            glm::dvec3 p, dir;
            const bool placed = c % 3 != 2;
            do {
                if (c % 3 == 1) {  // as far from two walls, looking into the edge where they meet
                    const int a = integer(0, 2), b = (a + integer(1, 2)) % 3, other = 3 - a - b;
                    const int k = integer(1, std::min(size[a], size[b]) / 2);
                    dir = glm::dvec3(0.0);
                    for (int axis : {a, b}) {
                        const bool low = integer(0, 1) == 0;
                        p[axis] = low ? room.lo[axis] + k : room.hi[axis] + 1 - k;
                        dir[axis] = low ? -1.0 : 1.0;
                    }
                    p[other] = integer(room.lo[other] + 1, room.hi[other]);
                } else if (placed) {  // on a voxel corner, along an axis or a diagonal
                    p = glm::dvec3(integer(room.lo.x + 1, room.hi.x), integer(room.lo.y + 1, room.hi.y),
                                   integer(room.lo.z + 1, room.hi.z));
                    dir = glm::dvec3(integer(-1, 1), integer(-1, 1) * (c % 2), integer(-1, 1));
                } else {
                    p = glm::dvec3(uniform(room.lo.x, room.hi.x + 1), uniform(room.lo.y, room.hi.y + 1),
                                   uniform(room.lo.z, room.hi.z + 1));
                    dir = glm::dvec3(uniform(-1, 1), uniform(-1, 1), uniform(-1, 1));
                }
            } while (!room.clear(p) || glm::length(dir) == 0.0 || (dir.x == 0.0 && dir.z == 0.0));
            const uint32_t odd = placed ? 1u : 0u;  // so the centre pixel looks straight along dir
            const uint32_t w = uint32_t(integer(24, 80)) | odd, h = uint32_t(integer(16, 60)) | odd;
            renderer.resize(w, h);
            renderer.resetHistory();  // every camera a cut: culling has no frame before
            const glm::dvec3 eye = world.origin() + p;  // world.origin(): voxel corner (0, 0, 0)
            const Camera camera = makeCamera(test::lookAt(eye, eye + dir, placed ? 60.0 : uniform(20, 120)), w, h);
            renderer.render(camera);
            const FrameImages f = renderer.readback(camera, true);
            ++frames;
            for (size_t i = 0; i < f.depth.size(); ++i) {
                ++pixels;
                const bool isSky = !std::isfinite(f.depth[i]), isLit = !isSky && f.shadow[i] != 0.0f;
                sky += isSky;
                lit += isLit;
                if ((isSky || isLit) && sky + lit <= 10)
                    ADD_FAILURE() << "room " << r << ", camera " << c << " at (" << p.x << ", " << p.y << ", " << p.z
                                  << ") toward (" << dir.x << ", " << dir.y << ", " << dir.z << "), " << w << "x" << h
                                  << ": pixel " << i % w << ", " << i / w << (isSky ? " shows the sky" : " is lit");
            }
        }
    }
    std::printf("[ measured ] %zu frames, %zu pixels: %zu show the sky, %zu lit\n", frames, pixels, sky, lit);
    EXPECT_EQ(sky, 0u);
    EXPECT_EQ(lit, 0u);
}

}  // namespace
}  // namespace grotto
