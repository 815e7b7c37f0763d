// Live worlds on the engine side: the quad slot allocator; a scene updated chunk
// by chunk draws the same G-buffer, bit for bit, as a fresh upload of the edited
// world (a chunk rewritten in place, one that outgrows its slot, a removed and a
// new chunk, the vertex and index buffers grown), staging only the changed
// chunks; edits restart the temporal history within the AO's reach for exactly
// one frame, also 1e6 units from the origin; and resize, lighting and AO changes
// on a live renderer give what a fresh renderer gives.
#include "grotto/error.h"
#include "engine/frame/history_boxes.h"
#include "engine/scene/quad_slots.h"
#include "engine/renderer.h"
#include "tests/gpu_fixture.h"
#include "tests/scenes.h"

#include <algorithm>
#include <cmath>
#include <cstring>

namespace grotto {
namespace {

using test::GpuTest;

TEST(QuadSlots, FirstFitReleaseMergesAndGrowthAddsFreeSpace) {
    QuadSlots s(100);
    EXPECT_EQ(s.allocate(30), 0u);
    EXPECT_EQ(s.allocate(30), 30u);
    EXPECT_EQ(s.allocate(30), 60u);
    EXPECT_EQ(s.freeQuads(), 10u);
    EXPECT_FALSE(s.allocate(11).has_value());
    s.release(0, 30);
    s.release(60, 30);  // merges with the free tail [90, 100)
    EXPECT_EQ(s.freeRanges(), 2u);
    EXPECT_EQ(s.freeQuads(), 70u);
    EXPECT_FALSE(s.allocate(41).has_value());  // 30 + 40 free, but not in one piece
    EXPECT_EQ(s.allocate(35), 60u);            // first fit skips the 30 at 0
    EXPECT_EQ(s.allocate(20), 0u);
    s.release(30, 30);  // joins [20, 30) and [30, 60): one range of 40
    EXPECT_EQ(s.freeRanges(), 2u);
    EXPECT_EQ(s.allocate(40), 20u);
    EXPECT_EQ(s.allocate(5), 95u);
    EXPECT_EQ(s.freeQuads(), 0u);
    EXPECT_FALSE(s.allocate(1).has_value());
    s.release(95, 5);
    s.grow(150);  // the new space joins the free tail
    EXPECT_EQ(s.freeRanges(), 1u);
    EXPECT_EQ(s.allocate(55), 95u);
    EXPECT_EQ(s.capacity(), 150u);
}

TEST(QuadSlots, SlotsLeaveRoomAndBuffersMore) {
    for (uint32_t n : {0u, 1u, 15u, 16u, 100u, 1000u, 30000u}) {
        const uint32_t s = slotQuads(n);
        EXPECT_EQ(s % 16, 0u) << n;
        EXPECT_GE(s, n + std::max(n / 8, 16u)) << n;
        EXPECT_LT(s, n + std::max(n / 8, 16u) + 16) << n;
    }
    EXPECT_EQ(bufferQuads(0), 256u);
    EXPECT_EQ(bufferQuads(16000), 17000u);
    EXPECT_EQ(grownQuads(1000, 10), 1500u);
    EXPECT_EQ(grownQuads(1000, 4000), 5000u);
}

TEST(HistoryBoxes, MergeBeyondTheLimitKeepingEveryBoxAndWriteCameraRelative) {
    HistoryBoxes boxes;
    const glm::dvec3 far(1e6, -2e6, 3e6);
    std::vector<voxel::WorldBox> added;
    for (int i = 0; i < 12; ++i) {  // a row of unit boxes, and one far off the row
        const glm::dvec3 at = far + (i == 11 ? glm::dvec3(0, 500, 0) : glm::dvec3(3.0 * i, 0, 0));
        added.push_back({at, at + 1.0});
        boxes.add(added.back());
    }
    boxes.add({});  // empty: ignored
    ASSERT_EQ(boxes.boxes().size(), size_t(GROTTO_TEMPORAL_MAX_BOXES));
    for (const voxel::WorldBox& a : added) {
        bool inside = false;
        for (const voxel::WorldBox& b : boxes.boxes())
            inside |= glm::all(glm::lessThanEqual(b.min, a.min)) && glm::all(glm::lessThanEqual(a.max, b.max));
        EXPECT_TRUE(inside);
    }
    // Neighbours on the row merged, not the far box with the row.
    for (const voxel::WorldBox& b : boxes.boxes()) EXPECT_LT(b.max.y - b.min.y, 2.0);
    gpu::TemporalConstants t{};
    const glm::dvec3 camera = far + glm::dvec3(0.25, 0.5, -10.0);
    boxes.write(camera, 2.0, t);
    EXPECT_EQ(t.boxCount, uint32_t(GROTTO_TEMPORAL_MAX_BOXES));
    for (size_t i = 0; i < boxes.boxes().size(); ++i) {
        const glm::dvec3 lo = boxes.boxes()[i].min - 2.0 - camera, hi = boxes.boxes()[i].max + 2.0 - camera;
        for (int k = 0; k < 3; ++k) {  // exact to float precision, rounded outwards
            EXPECT_LE(t.boxMin[i][k], lo[k]);
            EXPECT_NEAR(t.boxMin[i][k], lo[k], 1e-6 * (1.0 + std::abs(lo[k])));
            EXPECT_GE(t.boxMax[i][k], hi[k]);
            EXPECT_NEAR(t.boxMax[i][k], hi[k], 1e-6 * (1.0 + std::abs(hi[k])));
        }
    }
    boxes.clear();
    EXPECT_TRUE(boxes.boxes().empty());
}

// A floor of 3 x 2 chunks with pillars, and a floating block in a chunk of its own.
bool baseWorld(int x, int y, int z) {
    if (y == 0) return true;
    if (y <= 3 && x % 9 == 2 && z % 7 == 3) return true;
    return x >= 70 && x <= 73 && y >= 40 && y <= 43 && z >= 5 && z <= 8;
}

// The same world after a few edits.
bool editedWorld(int x, int y, int z) {
    if (x >= 70 && x <= 73 && y >= 40) return false;  // the floating block goes: its chunk is removed
    if (x >= 4 && x <= 5 && y == 1 && z >= 4 && z <= 6) return true;  // chunk (0 0 0): a few more quads
    if (x == 11 && z == 3 && y >= 1) return false;                     // ... and a pillar less
    // Chunk (32 0 0): a checkerboard, too many quads for its slot, longer draws than the index buffer
    if (x >= 32 && x < 64 && z < 32 && y == 1 && (x + z) % 2 == 0) return true;
    if (x >= 8 && x <= 11 && y >= 36 && y <= 38 && z >= 40 && z <= 43) return true;  // a new chunk (0 32 32)
    return baseWorld(x, y, z);
}

voxel::World worldOf(bool (*solid)(int, int, int)) {
    return test::makeVoxelWorld({0, 0, 0}, {95, 45, 63}, [solid](int x, int y, int z) { return solid(x, y, z); });
}

bool sameQuads(const voxel::Mesh& a, const voxel::MeshChunk& ca, const voxel::Mesh& b, const voxel::MeshChunk& cb) {
    if (ca.faceCount != cb.faceCount) return false;
    return std::memcmp(a.quads.data() + ca.firstQuad, b.quads.data() + cb.firstQuad,
                       ca.quadCount() * sizeof(voxel::MeshQuad)) == 0;
}

// What changed from mesh `from` to mesh `to`: the chunks to replace and to remove.
struct MeshDiff {
    std::vector<voxel::MeshChunkQuads> replaced;
    std::vector<glm::ivec3> removed;
    uint64_t replacedQuads = 0;
};
MeshDiff diff(const voxel::Mesh& from, const voxel::Mesh& to) {
    auto find = [](const voxel::Mesh& m, glm::ivec3 origin) -> const voxel::MeshChunk* {
        for (const voxel::MeshChunk& c : m.chunks)
            if (c.origin == origin) return &c;
        return nullptr;
    };
    MeshDiff d;
    for (const voxel::MeshChunk& c : to.chunks) {
        const voxel::MeshChunk* before = find(from, c.origin);
        if (before && sameQuads(from, *before, to, c)) continue;
        voxel::MeshChunkQuads q{c.origin, c.faceCount, {}};
        q.quads.assign(to.quads.begin() + c.firstQuad, to.quads.begin() + c.firstQuad + c.quadCount());
        d.replacedQuads += c.quadCount();
        d.replaced.push_back(std::move(q));
    }
    for (const voxel::MeshChunk& c : from.chunks)
        if (!find(to, c.origin)) d.removed.push_back(c.origin);
    return d;
}

class ChunkUpdates : public GpuTest {
protected:
    static constexpr uint32_t kW = 256, kH = 160;
    Camera camera_ = makeCamera(test::lookAt({48, 50, 95}, {48, 10, 30}), kW, kH);
    AoOptions noAo() const {
        AoOptions ao;
        ao.estimator = estimatorPreset("high", 2.0);
        ao.enabled = false;
        return ao;
    }
    // Raw depth and surface ids of one frame of `scene`.
    FrameImages gbuffer(GpuScene& scene, const voxel::World& world) {
        Renderer renderer(ctx(), scene, world.desc().lighting, noAo(), kW, kH);
        renderer.render(camera_);
        return renderer.readback(camera_, true);
    }
    static size_t differing(const FrameImages& a, const FrameImages& b) {
        size_t n = 0;
        for (size_t i = 0; i < a.surfaceIds.size(); ++i)
            n += a.surfaceIds[i] != b.surfaceIds[i] || std::memcmp(&a.depthBuffer[i], &b.depthBuffer[i], 4) != 0;
        return n;
    }
    static void expectSameChunks(const GpuScene& a, const GpuScene& b) {
        ASSERT_EQ(a.chunks.size(), b.chunks.size());
        EXPECT_EQ(a.quadCount, b.quadCount);
        for (size_t i = 0; i < a.chunks.size(); ++i) {
            const GpuChunk &x = a.chunks[i], &y = b.chunks[i];
            EXPECT_EQ(x.index, y.index) << i;
            EXPECT_EQ(x.origin, y.origin) << i;
            EXPECT_EQ(x.lo, y.lo) << i;
            EXPECT_EQ(x.hi, y.hi) << i;
            EXPECT_EQ(x.exact().faceCount, y.exact().faceCount) << i;
        }
    }
};

TEST_F(ChunkUpdates, UpdatedChunksDrawTheSameGBufferAsAFreshUpload) {
    const voxel::World before = worldOf(baseWorld), after = worldOf(editedWorld);
    const voxel::Mesh meshBefore = before.mesh(), meshAfter = after.mesh();
    const MeshDiff d = diff(meshBefore, meshAfter);
    // The edits touch chunks of every kind.
    const glm::ivec3 inPlace(0, 0, 0), outgrown(32, 0, 0), gone(64, 32, 0), added(0, 32, 32);
    ASSERT_EQ(d.removed, std::vector<glm::ivec3>{gone});
    // Three edited, and two beside the checkerboard whose quads meet its new corners
    // along their shared borders (voxel/watertight.h).
    ASSERT_EQ(d.replaced.size(), 5u);

    auto live = uploadScene(ctx(), meshBefore, before.desc());
    const FrameImages original = gbuffer(*live, before);
    const GpuChunk inPlaceBefore = *live->findChunk(inPlace), outgrownBefore = *live->findChunk(outgrown);
    const uint32_t indexQuadsBefore = live->indexQuads;
    const VkDeviceSize vertexBytesBefore = live->vertices.size;

    live->updateChunks(d.replaced, d.removed);
    EXPECT_TRUE(live->uploadsPending());
    // Rewritten in place; moved to a new slot; the vertex buffer and the index buffer grown.
    const GpuChunk* rewritten = live->findChunk(inPlace);
    ASSERT_NE(rewritten, nullptr);
    EXPECT_NE(rewritten->exact().faceCount, inPlaceBefore.exact().faceCount);
    EXPECT_EQ(rewritten->slotFirst, inPlaceBefore.slotFirst);
    EXPECT_NE(live->findChunk(outgrown)->slotFirst, outgrownBefore.slotFirst);
    EXPECT_GT(live->findChunk(outgrown)->exact().faceCount[2], indexQuadsBefore);
    EXPECT_EQ(live->findChunk(gone), nullptr);
    EXPECT_NE(live->findChunk(added), nullptr);
    EXPECT_EQ(live->vertexBufferGrowths, 1u);
    EXPECT_GT(live->vertices.size, vertexBytesBefore);
    EXPECT_GT(live->indexQuads, indexQuadsBefore);
    // Staged: the changed chunks' vertices (16 bytes a quad) and the new index buffer, nothing else.
    const uint64_t vertexBytes = 16 * d.replacedQuads;
    EXPECT_EQ(live->stagedBytesLast, vertexBytes + 24ull * live->indexQuads);
    EXPECT_EQ(live->stagedBytesTotal, live->stagedBytesLast);
    EXPECT_LT(vertexBytes, 16 * meshAfter.quads.size());  // not the whole world
    EXPECT_GE(live->gpuBytes(), size_t(live->vertices.size + live->indices.size));

    auto fresh = uploadScene(ctx(), meshAfter, after.desc());
    EXPECT_EQ(fresh->gpuBytes(), sceneBufferBytes(meshAfter));  // what `grotto info` reports, slack included
    expectSameChunks(*live, *fresh);
    const FrameImages updated = gbuffer(*live, after);
    EXPECT_FALSE(live->uploadsPending());
    const FrameImages expected = gbuffer(*fresh, after);
    EXPECT_GT(differing(original, expected), 1000u) << "the edits must show in the view";
    EXPECT_EQ(differing(updated, expected), 0u);

    // And back (an undo): slots freed above are reused, and the old view returns.
    const MeshDiff back = diff(meshAfter, meshBefore);
    live->updateChunks(back.replaced, back.removed);
    EXPECT_EQ(live->stagedBytesLast, 16 * back.replacedQuads);  // the index buffer is long enough
    EXPECT_EQ(live->vertexBufferGrowths, 1u);
    auto freshBefore = uploadScene(ctx(), meshBefore, before.desc());
    expectSameChunks(*live, *freshBefore);
    EXPECT_EQ(differing(gbuffer(*live, before), original), 0u);
}

TEST_F(ChunkUpdates, UpdatesStagedTwiceBeforeAFrameLandAsTheLast) {
    const voxel::World before = worldOf(baseWorld), after = worldOf(editedWorld);
    const voxel::Mesh meshBefore = before.mesh(), meshAfter = after.mesh();
    auto live = uploadScene(ctx(), meshBefore, before.desc());
    const FrameImages original = gbuffer(*live, before);
    // Edit and undo with no frame between: the buffer grows, and the chunks move
    // back into slots whose first writes are still pending.
    const MeshDiff there = diff(meshBefore, meshAfter), back = diff(meshAfter, meshBefore);
    live->updateChunks(there.replaced, there.removed);
    live->updateChunks(back.replaced, back.removed);
    EXPECT_EQ(live->stagedBytesTotal, live->stagedBytesLast + 16 * there.replacedQuads + 24ull * live->indexQuads);
    EXPECT_EQ(differing(gbuffer(*live, before), original), 0u);
    // Then there again in two steps, each with a frame: the edit shows.
    auto fresh = uploadScene(ctx(), meshAfter, after.desc());
    live->updateChunks(there.replaced, {});
    gbuffer(*live, after);
    live->updateChunks({}, there.removed);
    EXPECT_EQ(live->stagedBytesLast, 0u);
    EXPECT_EQ(differing(gbuffer(*live, after), gbuffer(*fresh, after)), 0u);
}

TEST_F(ChunkUpdates, BufferGrownTwiceBeforeAFrame) {
    const voxel::World before = worldOf(baseWorld), after = worldOf(editedWorld);
    const voxel::Mesh meshBefore = before.mesh(), meshAfter = after.mesh();
    auto live = uploadScene(ctx(), meshBefore, before.desc());
    gbuffer(*live, before);
    // Two copies of the checkerboard chunk high above, one update each, no frame
    // between: each outgrows the buffer, the second the buffer the first made.
    const MeshDiff d = diff(meshBefore, meshAfter);
    const auto it = std::find_if(d.replaced.begin(), d.replaced.end(),
                                 [](const voxel::MeshChunkQuads& q) { return q.origin == glm::ivec3(32, 0, 0); });
    ASSERT_NE(it, d.replaced.end());
    const voxel::MeshChunkQuads& board = *it;
    voxel::Mesh expected = meshBefore;
    for (const glm::ivec3 origin : {glm::ivec3(0, 64, 0), glm::ivec3(32, 64, 32)}) {
        voxel::MeshChunkQuads q = board;
        q.origin = origin;
        live->updateChunks({&q, 1}, {});
        voxel::MeshChunk c;
        c.origin = origin;
        c.firstQuad = uint32_t(expected.quads.size());
        c.faceCount = q.faceCount;
        expected.chunks.push_back(c);
        expected.quads.insert(expected.quads.end(), q.quads.begin(), q.quads.end());
    }
    EXPECT_EQ(live->vertexBufferGrowths, 2u);
    auto fresh = uploadScene(ctx(), expected, before.desc());
    expectSameChunks(*live, *fresh);
    camera_ = makeCamera(test::lookAt({48, 110, 110}, {32, 64, 16}), kW, kH);
    const FrameImages a = gbuffer(*live, before), b = gbuffer(*fresh, before);
    EXPECT_GT(std::count_if(b.surfaceIds.begin(), b.surfaceIds.end(), [](uint16_t id) { return id != 0; }), 2000);
    EXPECT_EQ(differing(a, b), 0u);
}

TEST_F(ChunkUpdates, BadChunkIsRefused) {
    const voxel::World world = worldOf(baseWorld);
    auto live = uploadScene(ctx(), world.mesh(), world.desc());
    voxel::MeshChunkQuads q{{0, 0, 0}, {1, 0, 0, 0, 0, 0}, {}};  // claims a quad it does not have
    EXPECT_THROW(live->updateChunks({&q, 1}, {}), Error);
}

// History restarts within the AO's reach of an invalidated box, for one frame.
class EditHistory : public GpuTest, public ::testing::WithParamInterface<double> {};

TEST_P(EditHistory, RestartsWithinTheAoRadiusForOneFrame) {
    const glm::dvec3 offset(GetParam());
    const voxel::World world = test::makeVoxelWorld({-40, -1, -40}, {40, 2, 40}, [](int x, int y, int z) {
        return y == -1 || (y <= 1 && x % 10 == 0 && z % 10 == 0);
    }, 1.0, offset);
    auto scene = uploadScene(ctx(), world.mesh(), world.desc());
    AoOptions ao;
    ao.estimator = estimatorPreset("medium", 2.0);
    ao.chain.temporalHistory = 16;
    const uint32_t w = 160, h = 120;
    Renderer renderer(ctx(), *scene, world.desc().lighting, ao, w, h);
    const Camera camera = makeCamera(test::lookAt(offset + glm::dvec3(0, 30, 30), offset), w, h);
    uint32_t frame = 0;
    for (; frame < 20; ++frame) renderer.render(camera, frame);

    // A box of voxels on the floor, off the centre of the view.
    const voxel::WorldBox box{offset + glm::dvec3(3, 0, -4), offset + glm::dvec3(8, 2, 2)};
    renderer.invalidateHistory(box);
    const double radius = ao.estimator.radius, reach = aoReach(ao);
    EXPECT_GT(reach, radius);
    auto distance = [&](const glm::dvec3& p) {  // Euclidean and per axis, to the box
        const glm::dvec3 d = glm::max(glm::max(box.min - p, p - box.max), glm::dvec3(0.0));
        return std::pair{glm::length(d), std::max({d.x, d.y, d.z})};
    };
    for (const float expectedNear : {1.0f, 2.0f}) {
        renderer.render(camera, frame++);
        const FrameImages f = renderer.readback(camera, true);
        int nearCount = 0, farCount = 0;
        for (uint32_t y = 0; y < h; y += 2)
            for (uint32_t x = 0; x < w; x += 2) {
                const size_t i = size_t(y) * w + x;
                if (!std::isfinite(f.depth[i])) continue;
                const auto [euclid, axis] = distance(camera.pointAt(x + 0.5, y + 0.5, f.depth[i]));
                if (euclid <= radius) {
                    ++nearCount;
                    ASSERT_EQ(f.aoHistory[i], expectedNear) << x << "," << y;
                } else if (axis > reach + 1.0) {
                    ++farCount;
                    ASSERT_EQ(f.aoHistory[i], 16.0f) << x << "," << y;
                }
            }
        EXPECT_GT(nearCount, 50);
        EXPECT_GT(farCount, 1000);
    }
}

INSTANTIATE_TEST_SUITE_P(NearAndFar, EditHistory, ::testing::Values(0.0, 1e6),
                         [](const auto& info) { return info.param == 0.0 ? "AtOrigin" : "Far"; });

// Settings changed on a live renderer give what a fresh renderer with them gives.
TEST_F(ChunkUpdates, ResizeLightingAndAoMatchAFreshRenderer) {
    const voxel::World world = worldOf(editedWorld);
    auto scene = uploadScene(ctx(), world.mesh(), world.desc());
    const voxel::Lighting light = world.desc().lighting;
    voxel::Lighting dusk = light;
    dusk.sunDirection = glm::normalize(glm::vec3(-0.6f, 0.3f, 0.2f));
    dusk.sunColor = {1.0f, 0.6f, 0.4f};
    dusk.ambientIntensity *= 0.5f;
    AoOptions high;
    high.estimator = estimatorPreset("high", 3.0);
    high.chain.temporalHistory = 16;
    auto view = [](uint32_t w, uint32_t h) { return makeCamera(test::lookAt({40, 30, 80}, {40, 2, 20}), w, h); };
    // The live renderer's frame against a fresh renderer's, both rendering `frames`.
    auto expectFresh = [&](Renderer& live, const voxel::Lighting& l, const AoOptions& ao, uint32_t w, uint32_t h,
                           std::vector<uint32_t> frames, const char* what) {
        Renderer fresh(ctx(), *scene, l, ao, w, h);
        for (uint32_t i : frames) fresh.render(view(w, h), i);
        live.render(view(w, h), frames.back());
        const FrameImages a = live.readback(view(w, h), true), b = fresh.readback(view(w, h), true);
        ASSERT_EQ(a.width, w);
        ASSERT_EQ(a.height, h);
        EXPECT_EQ(a.color, b.color) << what;
        EXPECT_EQ(a.ao, b.ao) << what;
        EXPECT_EQ(a.aoHistory, b.aoHistory) << what;
    };
    Renderer live(ctx(), *scene, light, high, 96, 64);
    for (uint32_t i = 0; i < 3; ++i) live.render(view(96, 64), i);
    live.resize(131, 77);  // odd sizes, history restarts
    expectFresh(live, light, high, 131, 77, {3}, "resize");
    live.setLighting(dusk);  // uniforms only: the history goes on
    expectFresh(live, dusk, high, 131, 77, {3, 4}, "lighting");
    AoOptions medium = high;
    medium.estimator = estimatorPreset("medium", 5.0);
    medium.chain.denoisePasses = 2;
    medium.chain.temporalHistory = 8;
    live.setAo(medium);
    expectFresh(live, dusk, medium, 131, 77, {5}, "AO settings");
    AoOptions off = medium;
    off.enabled = false;
    live.setAo(off);
    expectFresh(live, dusk, off, 131, 77, {6}, "AO off");
    AoOptions full = high;
    full.chain.fullResolution = true;
    full.chain.temporalHistory = 0;
    full.method = AoMethod::Hbao;
    live.setAo(full);
    live.resize(64, 40);
    expectFresh(live, dusk, full, 64, 40, {7}, "full-resolution HBAO without history");
    EXPECT_EQ(live.ao().method, AoMethod::Hbao);
}

}  // namespace
}  // namespace grotto
