// Exact rays at voxel boundaries: the GPU's traversal (the shadow pass's traceHit,
// through shaders/trace_query.comp) and the CPU's World::raycast agree ray for ray
// (same voxel, same face, the same float distance) on rays that start on faces,
// edges and corners and run along faces and through edges and corners, with zero
// disagreement; and both keep the rules that make the answer right: a ray through
// an edge or corner where solid voxels meet is blocked there, and a ray from a face
// point placed a hair inside the wall beside it (a concave edge) starts in front of
// the face, so it cannot pass through a wall one voxel thin.
#include "engine/scene/occupancy.h"
#include "engine/passes/compute_pass.h"
#include "engine/passes/trace_inputs.h"
#include "tests/gpu_fixture.h"
#include "tests/scenes.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <random>

namespace grotto {
namespace {

using test::GpuTest;

// One ray as trace_query.comp reads it.
struct QueryRay {
    glm::ivec4 voxel;     // xyz: the start voxel; w: the face's axis for a face start, else -1
    glm::vec4 fraction;   // xyz: the start within it; w: the ray's length (voxels)
    glm::vec4 direction;  // xyz: unit
};
static_assert(sizeof(QueryRay) == 48);

struct Hit {
    bool hit = false;
    glm::ivec3 voxel{0};
    int face = -1;
    float t = -1.0f;
    bool operator==(const Hit& o) const {
        return hit == o.hit && (!hit || (voxel == o.voxel && face == o.face && t == o.t));
    }
};

std::ostream& operator<<(std::ostream& os, const Hit& h) {
    if (!h.hit) return os << "no hit";
    return os << "voxel (" << h.voxel.x << ", " << h.voxel.y << ", " << h.voxel.z << ") face " << h.face << " at t "
              << h.t;
}

class TraceQuery {
public:
    explicit TraceQuery(vk::Context& ctx)
        : ctx_(ctx),
          pass_(ctx, "trace_query.comp",
                withTraceBindings({VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER}),
                sizeof(uint32_t)) {}

    std::vector<Hit> trace(const GpuOccupancy& occupancy, const std::vector<QueryRay>& rays) {
        const gpu::TraceConstants t = traceConstants(Camera{}, occupancy, 1.0, glm::dvec3(0.0),
                                                     glm::vec3(0.0f, 1.0f, 0.0f), 1, 1.0);
        vk::Buffer constants = vk::createBuffer(ctx_, sizeof t, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, true);
        std::memcpy(constants.mapped(), &t, sizeof t);
        const VkBufferUsageFlags usage = VK_BUFFER_USAGE_STORAGE_BUFFER_BIT;
        vk::Buffer in = vk::createBuffer(ctx_, rays.size() * sizeof(QueryRay), usage, true);
        vk::Buffer out = vk::createBuffer(ctx_, rays.size() * 2 * sizeof(glm::vec4), usage, true);
        std::memcpy(in.mapped(), rays.data(), rays.size() * sizeof(QueryRay));
        const uint32_t count = uint32_t(rays.size());
        ctx_.submitAndWait([&](VkCommandBuffer cmd) {
            pass_.dispatch(cmd, withTraceBindings({vk::storageBuffer(in.buffer), vk::storageBuffer(out.buffer)},
                                                  constants, occupancy),
                           VkExtent2D{count, 1}, 64, &count);
            computeToHost(cmd);
        });
        std::vector<Hit> hits(rays.size());
        const auto* h = static_cast<const glm::vec4*>(out.mapped());
        for (size_t i = 0; i < rays.size(); ++i) {
            hits[i].t = h[2 * i + 1].x;
            hits[i].hit = hits[i].t >= 0.0f;
            hits[i].voxel = glm::ivec3(h[2 * i]);
            hits[i].face = int(h[2 * i].w);
        }
        vk::destroy(ctx_, in);
        vk::destroy(ctx_, out);
        vk::destroy(ctx_, constants);
        return hits;
    }

private:
    vk::Context& ctx_;
    ComputePass pass_;
};

// The CPU's answer for the same ray.
Hit cpuHit(const voxel::World& world, const QueryRay& r) {
    voxel::RayStart start{glm::ivec3(r.voxel), glm::vec3(r.fraction)};
    if (r.voxel.w >= 0) start = world.faceRayStart(start, r.voxel.w);
    const auto h = world.raycast(start, glm::vec3(r.direction), double(r.fraction.w) * world.voxelSize());
    Hit out;
    if (h) out = {true, h->voxel, h->face, float(h->distance / world.voxelSize())};
    return out;
}

std::vector<Hit> cpuHits(const voxel::World& world, const std::vector<QueryRay>& rays) {
    std::vector<Hit> hits;
    for (const QueryRay& r : rays) hits.push_back(cpuHit(world, r));
    return hits;
}

// Directions that run along faces and through edges and corners from starts on
// voxel boundaries: every sign and axis order of (1,0,0), (1,1,0), (1,1,1),
// (1,2,0), (1,1,2), (1,2,3), and (3,4,0) (whose unit vector is exact), in float.
std::vector<glm::vec3> tieDirections() {
    const glm::vec3 bases[] = {{1, 0, 0}, {1, 1, 0}, {1, 1, 1}, {1, 2, 0}, {1, 1, 2}, {1, 2, 3}, {3, 4, 0}};
    const int orders[6][3] = {{0, 1, 2}, {0, 2, 1}, {1, 0, 2}, {1, 2, 0}, {2, 0, 1}, {2, 1, 0}};
    std::vector<glm::vec3> out;
    for (const glm::vec3& b : bases)
        for (const auto& o : orders)
            for (int s = 0; s < 8; ++s) {
                glm::vec3 d(b[o[0]], b[o[1]], b[o[2]]);
                for (int a = 0; a < 3; ++a)
                    if (s >> a & 1) d[a] = -d[a];
                d = glm::normalize(d);
                bool seen = false;
                for (const glm::vec3& e : out) seen |= e == d;
                if (!seen) out.push_back(d);
            }
    return out;
}

using VoxelRays = GpuTest;

// Random worlds (10 % solid, across a 64^3 tile's corner and negative indices, with
// empty bricks and a far sparse cluster), rays from starts on faces, edges and
// corners and in between, along the directions above and random ones.
TEST_F(VoxelRays, GpuAndCpuAgreeOnRaysAlongFacesAndThroughEdgesAndCorners) {
    std::mt19937 rng(2211);
    std::uniform_real_distribution<float> u(0.0f, 1.0f);
    const glm::ivec3 lo(-70, -20, -40), hi(-40, 12, -10);
    const voxel::World world = test::makeVoxelWorld(lo, hi + glm::ivec3(0, 0, 90), [&](int x, int y, int z) {
        if (z > hi.z) return x == -41 && y == 5 && z >= 45;  // a far column
        if (((x >> 3) + (y >> 3) + (z >> 3)) % 3 == 0) return false;  // empty bricks
        return u(rng) < 0.1f;
    });
    const GpuOccupancy occupancy(ctx(), world);
    TraceQuery query(ctx());

    const float fractions[] = {0.0f, 1.0f, 0.5f, 1e-4f, 1.0f - 1e-4f, 0.25f};
    const std::vector<glm::vec3> ties = tieDirections();
    std::uniform_int_distribution<int> x(lo.x - 3, hi.x + 3), y(lo.y - 3, hi.y + 3), z(lo.z - 3, hi.z + 3);
    std::uniform_int_distribution<int> pick(0, 5);
    std::vector<QueryRay> rays;
    for (int i = 0; i < 60000; ++i) {
        QueryRay r;
        r.voxel = glm::ivec4(x(rng), y(rng), z(rng), -1);
        for (int a = 0; a < 3; ++a) r.fraction[a] = fractions[pick(rng)];
        r.fraction.w = i % 4 == 0 ? 1.0f + 20.0f * u(rng) : 1e30f;  // some short rays, most to the bounds
        glm::vec3 d = ties[size_t(i) % ties.size()];
        if (i % 5 == 4) d = glm::normalize(glm::vec3(u(rng), u(rng), u(rng)) * 2.0f - 1.0f);
        r.direction = glm::vec4(d, 0.0f);
        if (i % 3 == 0) {  // a face start: the open voxel in front of the face, as the shadow pass has it
            r.voxel.w = i / 3 % 3;
            r.fraction[r.voxel.w] = 1e-4f;
        }
        rays.push_back(r);
    }
    const std::vector<Hit> gpu = query.trace(occupancy, rays), cpu = cpuHits(world, rays);
    size_t hits = 0, differ = 0, longHits = 0;
    for (size_t i = 0; i < rays.size(); ++i) {
        hits += cpu[i].hit;
        longHits += cpu[i].hit && cpu[i].t > 8.0f;
        if (gpu[i] == cpu[i]) continue;
        if (++differ <= 10) {
            const QueryRay& r = rays[i];
            ADD_FAILURE() << "ray " << i << " from voxel (" << r.voxel.x << ", " << r.voxel.y << ", " << r.voxel.z
                          << ") + (" << r.fraction.x << ", " << r.fraction.y << ", " << r.fraction.z << "), face axis "
                          << r.voxel.w << ", direction (" << r.direction.x << ", " << r.direction.y << ", "
                          << r.direction.z << "): GPU " << gpu[i] << ", CPU " << cpu[i];
        }
    }
    std::printf("[ measured ] %zu rays: %zu hit (%zu beyond 8 voxels), %zu differ between GPU and CPU\n", rays.size(),
                hits, longHits, differ);
    EXPECT_EQ(differ, 0u);
    EXPECT_GT(hits, rays.size() / 3);  // both answers are common
    EXPECT_LT(hits, rays.size() * 9 / 10);
    EXPECT_GT(longHits, rays.size() / 50);  // and rays cross empty bricks before they hit
}

// How far rays run through solid voxels (VBAO's voxels thickness): across a slab
// five voxels thick exactly 5 / |d.y| from its bottom face, capped at the length
// asked for, 0 from an open voxel; and the GPU and the CPU agree bit for bit on
// random starts in a random world, along faces and through edges and corners.
TEST_F(VoxelRays, SolidRunsCrossSlabsExactlyAndAgreeOnGpuAndCpu) {
    const voxel::World slab = test::makeVoxelWorld({-40, -2, -40}, {40, 8, 40}, [](int, int y, int) { return y >= 0 && y < 5; });
    for (glm::vec3 d : {glm::vec3(0, 1, 0), glm::vec3(0.5f, 1, 0), glm::vec3(1.3f, 1, -0.4f), glm::vec3(-2, 1, 3)}) {
        d = glm::normalize(d);
        const voxel::RayStart bottom{glm::ivec3(0, 0, 0), glm::vec3(0.5f, 0.0f, 0.5f)};
        EXPECT_NEAR(slab.solidRun(bottom, d, 1e3), 5.0 / d.y, 1e-4 * 5.0 / d.y) << d.x << "," << d.y << "," << d.z;
        EXPECT_FLOAT_EQ(float(slab.solidRun(bottom, d, 2.0)), 2.0f) << "capped";
        EXPECT_EQ(slab.solidRun({glm::ivec3(0, 6, 0), glm::vec3(0.5f)}, d, 1e3), 0.0) << "from an open voxel";
    }

    std::mt19937 rng(4242);
    std::uniform_real_distribution<float> u(0.0f, 1.0f);
    const glm::ivec3 lo(-70, -20, -40), hi(-40, 12, -10);
    const voxel::World world = test::makeVoxelWorld(lo, hi, [&](int x, int y, int z) {
        if (((x >> 3) + (y >> 3) + (z >> 3)) % 3 == 0) return false;  // empty bricks
        return u(rng) < 0.6f;  // mostly solid: runs of several voxels
    });
    const GpuOccupancy occupancy(ctx(), world);
    TraceQuery query(ctx());
    const float fractions[] = {0.0f, 1.0f, 0.5f, 1e-4f, 1.0f - 1e-4f, 0.25f};
    const std::vector<glm::vec3> ties = tieDirections();
    std::uniform_int_distribution<int> x(lo.x, hi.x), y(lo.y, hi.y), z(lo.z, hi.z), pick(0, 5);
    std::vector<QueryRay> rays;
    while (rays.size() < 20000) {
        QueryRay r;
        r.voxel = glm::ivec4(x(rng), y(rng), z(rng), -2);
        if (!world.solid(glm::ivec3(r.voxel))) continue;
        for (int a = 0; a < 3; ++a) r.fraction[a] = fractions[pick(rng)];
        r.fraction.w = rays.size() % 4 == 0 ? 2.0f + 10.0f * u(rng) : 1e30f;
        glm::vec3 d = ties[rays.size() % ties.size()];
        if (rays.size() % 5 == 4) d = glm::normalize(glm::vec3(u(rng), u(rng), u(rng)) * 2.0f - 1.0f);
        r.direction = glm::vec4(d, 0.0f);
        rays.push_back(r);
    }
    const std::vector<Hit> gpu = query.trace(occupancy, rays);
    size_t differ = 0, longRuns = 0;
    for (size_t i = 0; i < rays.size(); ++i) {
        const QueryRay& r = rays[i];
        const float cpu = float(world.solidRun({glm::ivec3(r.voxel), glm::vec3(r.fraction)}, glm::vec3(r.direction),
                                               double(r.fraction.w)));
        longRuns += cpu > 2.0f;
        if (gpu[i].t == cpu) continue;
        if (++differ <= 10)
            ADD_FAILURE() << "run " << i << " from voxel (" << r.voxel.x << ", " << r.voxel.y << ", " << r.voxel.z
                          << "): GPU " << gpu[i].t << ", CPU " << cpu;
    }
    std::printf("[ measured ] %zu solid runs (%zu longer than 2 voxels), %zu differ between GPU and CPU\n", rays.size(),
                longRuns, differ);
    EXPECT_EQ(differ, 0u);
    EXPECT_GT(longRuns, rays.size() / 10);
}

// Solid voxels that meet only along an edge (two) or at a corner (six around it):
// a ray from the open voxel before them through that edge or corner is blocked
// there, on the GPU and the CPU alike; and a ray from a floor point at the foot of
// a wall one voxel thin, placed a hair inside the wall, cannot pass through it.
TEST_F(VoxelRays, RaysThroughEdgesAndCornersOfSolidVoxelsAndThinWallsAreBlocked) {
    std::vector<glm::ivec3> solid;
    std::vector<QueryRay> rays;
    std::vector<float> within;  // how far along each ray the blocking voxels lie, at most
    // Bases near the origin, across tile and brick boundaries, negative, far.
    const glm::ivec3 bases[] = {{0, 0, 0}, {7, 7, 7}, {63, 63, 62}, {-1, -1, -1}, {-65, 3, 30}, {200, -100, 5}};
    // How the rays lean along the edge's own axis: they cross the edge inside it.
    const float slopes[] = {0.0f, 0.3f, -0.7f, 0.9f};
    int k = 0;
    for (const glm::ivec3& b0 : bases) {
        for (int a = 0; a < 3; ++a)  // edges along axis a, in its two other axes' plane
            for (int signs = 0; signs < 4; ++signs) {
                const int u = (a + 1) % 3, v = (a + 2) % 3;
                const glm::ivec3 b = b0 + glm::ivec3(0, 0, 4 * k++);  // each its own place
                glm::ivec3 du(0), dv(0);
                du[u] = signs & 1 ? -1 : 1;
                dv[v] = signs & 2 ? -1 : 1;
                solid.push_back(b + du);
                solid.push_back(b + dv);
                for (const float s : slopes) {
                    // From the centre of voxel b through its edge between b + du and b + dv.
                    glm::vec3 d(0.0f);
                    d[u] = float(du[u]);
                    d[v] = float(dv[v]);
                    d[a] = s;
                    QueryRay r;
                    r.voxel = glm::ivec4(b, -1);
                    r.fraction = glm::vec4(0.5f, 0.5f, 0.5f, 1e30f);
                    r.direction = glm::vec4(glm::normalize(d), 0.0f);
                    rays.push_back(r);
                    within.push_back(glm::length(d) * 0.5f);
                    // And from b's edge with b + du, along their shared face toward b + dv.
                    if (std::abs(s) > 0.5f) continue;  // (it would leave the face first)
                    r.fraction = glm::vec4(0.5f);
                    r.fraction[u] = du[u] > 0 ? 1.0f : 0.0f;
                    r.fraction[v] = dv[v] > 0 ? 0.0f : 1.0f;
                    r.fraction.w = 1e30f;
                    glm::vec3 e(0.0f);
                    e[v] = float(dv[v]);
                    e[a] = s;
                    r.direction = glm::vec4(glm::normalize(e), 0.0f);
                    rays.push_back(r);
                    within.push_back(glm::length(e));
                }
            }
        for (int signs = 0; signs < 8; ++signs) {  // corners: the six voxels around one, but not the two on the ray
            const glm::ivec3 b = b0 + glm::ivec3(0, 0, 4 * k++);
            const glm::ivec3 s(signs & 1 ? -1 : 1, signs & 2 ? -1 : 1, signs & 4 ? -1 : 1);
            for (int m = 1; m < 7; ++m) solid.push_back(b + s * glm::ivec3(m & 1, m >> 1 & 1, m >> 2 & 1));
            QueryRay r;
            r.voxel = glm::ivec4(b, -1);
            r.fraction = glm::vec4(0.5f, 0.5f, 0.5f, 1e30f);
            r.direction = glm::vec4(glm::normalize(glm::vec3(s)), 0.0f);
            rays.push_back(r);
            within.push_back(std::sqrt(3.0f) * 0.5f);
        }
    }
    // A floor (y = 0) with walls one voxel thin at z = 40 and x = 60 standing on it.
    const glm::ivec3 room(40, 0, 40);
    for (int x = 20; x <= 60; ++x)
        for (int z = 20; z <= 60; ++z) {
            solid.push_back({x, room.y, z});
            if (z == room.z || x == 60) solid.push_back({x, room.y + 1, z}), solid.push_back({x, room.y + 2, z});
        }
    const std::vector<glm::vec3> over = {{0, 1, -1}, {0.3f, 1, -1}, {-0.5f, 0.2f, -1}, {0, 0, -1}, {0.7f, 2.0f, -1}};
    for (int x = 25; x < 55; x += 3)
        for (const glm::vec3& dir : over)
            for (float hair : {0.0f, 1e-6f, 2e-5f, 1e-3f}) {
                // A point on the floor's face at z = 41 (the wall's face), given as the
                // GPU may place it: up to a hair inside the wall's voxel, or exactly on
                // the boundary in the room's.
                QueryRay r;
                r.voxel = hair > 0.0f ? glm::ivec4(x, room.y + 1, room.z, 1) : glm::ivec4(x, room.y + 1, room.z + 1, 1);
                r.fraction = glm::vec4(0.37f, 1e-4f, hair > 0.0f ? 1.0f - hair : 0.0f, 1e30f);
                r.direction = glm::vec4(glm::normalize(dir), 0.0f);
                rays.push_back(r);
                within.push_back(0.01f);  // at once: the wall stands right there
                // The same against the other wall (x = 60), from x = 59 + 1: its face is at x = 60.
                r.voxel = hair > 0.0f ? glm::ivec4(60, room.y + 1, x + 5, 1) : glm::ivec4(59, room.y + 1, x + 5, 1);
                r.fraction = glm::vec4(hair > 0.0f ? hair : 1.0f, 1e-4f, 0.61f, 1e30f);
                r.direction = glm::vec4(glm::normalize(glm::vec3(-dir.z, dir.y, dir.x)), 0.0f);
                rays.push_back(r);
                within.push_back(0.01f);
            }
    const voxel::World world = test::makeVoxelWorld(solid);
    const GpuOccupancy occupancy(ctx(), world);
    TraceQuery query(ctx());
    const std::vector<Hit> gpu = query.trace(occupancy, rays), cpu = cpuHits(world, rays);
    size_t slipped = 0, differ = 0;
    for (size_t i = 0; i < rays.size(); ++i) {
        differ += !(gpu[i] == cpu[i]);
        for (const auto& [side, h] : {std::pair{"GPU", gpu[i]}, std::pair{"CPU", cpu[i]}})
            if ((!h.hit || h.t > within[i] * (1.0f + 1e-5f)) && ++slipped <= 10) {
                const QueryRay& r = rays[i];
                ADD_FAILURE() << side << ": ray " << i << " from voxel (" << r.voxel.x << ", " << r.voxel.y << ", "
                              << r.voxel.z << ") + (" << r.fraction.x << ", " << r.fraction.y << ", " << r.fraction.z
                              << "), face axis " << r.voxel.w << ", direction (" << r.direction.x << ", "
                              << r.direction.y << ", " << r.direction.z << ") must be blocked within " << within[i]
                              << " voxel: " << h;
            }
    }
    std::printf("[ measured ] %zu rays through edges, corners and thin walls: %zu not blocked where they must be, "
                "%zu differ between GPU and CPU\n",
                rays.size(), slipped, differ);
    EXPECT_EQ(slipped, 0u);
    EXPECT_EQ(differ, 0u);
}

}  // namespace
}  // namespace grotto
