// The face cache read on the GPU (shaders/face_cache_query.comp, through the
// shader's own shared/face_cache.h) against the CPU's FaceCacheLookup, point by
// point, on a random world with validation on: the same faces found, the same
// values within the texels' 8-bit quantisation.
#include "engine/passes/compute_pass.h"
#include "engine/scene/face_cache_gpu.h"
#include "tests/gpu_fixture.h"
#include "voxel/brick_table.h"
#include "voxel/face_bake.h"
#include "voxel/face_cache_layout.h"
#include "voxel/face_cache_lookup.h"

#include <cstring>
#include <random>

namespace grotto {
namespace {

using test::GpuTest;

struct CacheQuery {
    glm::vec4 point;
    glm::ivec4 origin;
};
static_assert(sizeof(CacheQuery) == 32);

class FaceCacheGpu : public GpuTest {};

TEST_F(FaceCacheGpu, ReadsAsTheCpuLookup) {
    std::mt19937 rng(21);
    std::bernoulli_distribution fill(0.3);
    const glm::ivec3 size(24, 16, 20);
    std::vector<uint8_t> cells(size_t(size.x) * size.y * size.z);
    for (uint8_t& c : cells) c = fill(rng) ? 1 : 0;
    const voxel::World world = voxel::World::fromDense(size, cells.data(), 0.5, glm::dvec3(-3000.0, 7.0, 1234.0));
    const voxel::BrickTable table(world);
    const std::vector<voxel::ExposedFace> faces = voxel::exposedFaces(table, world);
    for (uint32_t k : {1u, 3u}) {
        std::vector<voxel::FaceTexel> texels(faces.size() * k * k);
        voxel::bakeFaces(table, world, faces, {.radius = 2.0, .texelsPerSide = k, .rays = 16, .sunRays = 1}, texels);
        const GpuFaceCache cache(ctx(), voxel::layFaceCache(faces, texels, k));
        const voxel::FaceCacheLookup lookup(faces, texels, k);

        std::vector<CacheQuery> queries;
        std::vector<voxel::CachedLight> expected;
        std::uniform_real_distribution<double> within(0.0, 1.0);
        std::uniform_int_distribution<int> shift(-5000, 5000);
        for (int n = 0; n < 3000; ++n) {
            // A point on a random face's plane, on it or on a neighbour's; a tenth on
            // a plane beside a face (found nowhere, or on another face).
            const voxel::ExposedFace& f = faces[rng() % faces.size()];
            glm::dvec3 p = voxel::texelPoint(f, 1, 0, 0);
            const int ua = int(gpu::faceUAxis(f.dir)), va = int(gpu::faceVAxis(f.dir)), axis = int(gpu::faceAxis(f.dir));
            p[ua] = f.cell[ua] - 0.5 + 2.0 * within(rng), p[va] = f.cell[va] - 0.5 + 2.0 * within(rng);
            if (n % 10 == 0) p[axis] += (rng() % 2 ? 1.0 : -1.0);
            const glm::ivec3 origin(shift(rng), shift(rng), shift(rng));  // camera-relative, as a frame has it
            queries.push_back({glm::vec4(glm::vec3(p - glm::dvec3(origin)), 0.0f), glm::ivec4(origin, f.dir)});
            expected.push_back(lookup.at(p, f.dir));
        }
        const VkBufferUsageFlags usage = VK_BUFFER_USAGE_STORAGE_BUFFER_BIT;
        vk::Buffer in = vk::createBuffer(ctx(), queries.size() * sizeof(CacheQuery), usage, true);
        vk::Buffer out = vk::createBuffer(ctx(), queries.size() * 2 * sizeof(glm::vec4), usage, true);
        std::memcpy(in.mapped(), queries.data(), queries.size() * sizeof(CacheQuery));
        const ComputePass pass(ctx(), "face_cache_query.comp",
                               GpuFaceCache::withBindings({VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER}),
                               3 * sizeof(uint32_t));
        const uint32_t push[3] = {uint32_t(queries.size()), cache.table(), k};
        ctx().submitAndWait([&](VkCommandBuffer cmd) {
            pass.dispatch(cmd, cache.withBindings({vk::storageBuffer(in.buffer), vk::storageBuffer(out.buffer)}),
                          VkExtent2D{push[0], 1}, 64, push);
            computeToHost(cmd);
        });
        const auto* r = static_cast<const glm::vec4*>(out.mapped());
        size_t found = 0;
        for (size_t i = 0; i < queries.size(); ++i) {
            const voxel::CachedLight& e = expected[i];
            const bool cpuFound = e.samples > 0;
            ASSERT_EQ(r[2 * i + 1].x > 0.5f, cpuFound) << "query " << i;
            if (!cpuFound) continue;
            ++found;
            using voxel::kFaceTexelStep;
            ASSERT_NEAR(r[2 * i].x, e.ao, 0.6 * kFaceTexelStep[0] + 2e-5) << i;
            ASSERT_NEAR(r[2 * i].y, e.sun, 0.6 * kFaceTexelStep[1] + 2e-5) << i;
            // The weights are stored finer than AO (halfs); the blend's float
            // weights where a point sits near a texel's edge leave as much as AO's step.
            ASSERT_NEAR(r[2 * i].z, e.skyHorizon, 0.6 * kFaceTexelStep[0] + 2e-5) << i;
            ASSERT_NEAR(r[2 * i].w, e.skyZenith, 0.6 * kFaceTexelStep[0] + 2e-5) << i;
        }
        EXPECT_GT(found, queries.size() / 2);  // both answers occur
        EXPECT_LT(found, queries.size());
        vk::destroy(ctx(), in);
        vk::destroy(ctx(), out);
    }
}

}  // namespace
}  // namespace grotto
