#pragma once
// Comparisons shared by the live-world tests: a chunk-by-chunk mesh against
// World::mesh(), and an updated brick table against a fresh one.
#include "voxel/brick_table.h"
#include "voxel/world.h"

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include <random>

namespace grotto::voxel::test {

// Chunk for chunk (origin, first quad, per-face counts) and quad for quad.
inline void expectSameMesh(const Mesh& got, const Mesh& want, const std::string& when) {
    ASSERT_EQ(got.chunks.size(), want.chunks.size()) << when;
    for (size_t i = 0; i < got.chunks.size(); ++i) {
        ASSERT_EQ(got.chunks[i].origin, want.chunks[i].origin) << when << ", chunk " << i;
        ASSERT_EQ(got.chunks[i].firstQuad, want.chunks[i].firstQuad) << when << ", chunk " << i;
        ASSERT_EQ(got.chunks[i].faceCount, want.chunks[i].faceCount) << when << ", chunk " << i;
    }
    ASSERT_EQ(got.quads.size(), want.quads.size()) << when;
    for (size_t i = 0; i < got.quads.size(); ++i) ASSERT_EQ(got.quads[i].corners, want.quads[i].corners) << when << ", quad " << i;
    EXPECT_EQ(got.origin, want.origin);
    EXPECT_EQ(got.voxelSize, want.voxelSize);
}

// Every brick in the world's bounds and two bricks around them, bit for bit,
// some far away, and rays through the bounds: as a fresh BrickTable answers.
inline void expectSameTable(const BrickTable& got, const World& world, std::mt19937& rng, const std::string& when) {
    const BrickTable want(world);
    IndexBox b = world.bounds();
    if (b.empty()) b = {glm::ivec3(0), glm::ivec3(0)};
    const glm::ivec3 lo = (b.min >> 3) - 2, hi = (b.max >> 3) + 2;
    uint64_t wrongBricks = 0, wrongBits = 0;
    auto compare = [&](glm::ivec3 brick) {
        const uint32_t g = got.find(brick), w = want.find(brick);
        if ((g != 0) != (w != 0)) {
            ++wrongBricks;
            return;
        }
        if (g == 0) return;
        for (int i = 0; i < 512; ++i) {
            const glm::ivec3 v(i >> 6, (i >> 3) & 7, i & 7);
            wrongBits += got.solid(g, v) != want.solid(w, v);
        }
    };
    const glm::ivec3 n = hi - lo + 1;
    if (double(n.x) * n.y * n.z <= double(1 << 20)) {
        for (int x = lo.x; x <= hi.x; ++x)
            for (int y = lo.y; y <= hi.y; ++y)
                for (int z = lo.z; z <= hi.z; ++z) compare({x, y, z});
    } else {  // far-flung: the solid bricks, their neighbours and samples of the range
        for (const Brick& b : world.bricks())
            for (int i = 0; i < 27; ++i) compare((b.origin >> 3) + glm::ivec3(i % 3, i / 3 % 3, i / 9) - 1);
        for (int i = 0; i < 100000; ++i)
            compare(lo + glm::ivec3(std::uniform_int_distribution<int>(0, n.x - 1)(rng), std::uniform_int_distribution<int>(0, n.y - 1)(rng),
                                    std::uniform_int_distribution<int>(0, n.z - 1)(rng)));
    }
    EXPECT_EQ(wrongBricks, 0u) << when;
    EXPECT_EQ(wrongBits, 0u) << when;
    std::uniform_int_distribution<int> far(-(1 << 26), (1 << 26) - 1);
    for (int i = 0; i < 100; ++i) {
        const glm::ivec3 brick(far(rng), far(rng), far(rng));
        EXPECT_EQ(got.find(brick) != 0, want.find(brick) != 0) << when;
    }
    std::uniform_real_distribution<double> u(0.0, 1.0), dir(-1.0, 1.0);
    int wrongRays = 0;
    for (int i = 0; i < 300; ++i) {
        const glm::dvec3 p = glm::dvec3(b.min) + glm::dvec3(u(rng), u(rng), u(rng)) * glm::dvec3(b.max + 1 - b.min);
        glm::dvec3 d(dir(rng), dir(rng), dir(rng));
        if (glm::length(d) < 1e-3) continue;
        d = glm::normalize(d);
        wrongRays += got.hitWithin(p, d, 24.0) != want.hitWithin(p, d, 24.0);
    }
    EXPECT_EQ(wrongRays, 0) << when;
}

}  // namespace grotto::voxel::test
