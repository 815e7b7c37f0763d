// The temporal pass: exact reprojection for a still camera and a one-pixel pan
// (whose newly revealed edge restarts its history),
// history reset on cuts and new sequences, no drift over thousands of still
// frames (nor at the frame counter's wrap), and no ghost in disoccluded areas.
#include "engine/renderer.h"
#include "tests/gpu_fixture.h"
#include "tests/scenes.h"
#include "tests/test_util.h"

#include <cmath>
#include <cstdio>

namespace grotto {
namespace {

using test::GpuTest;

// Half-resolution views of a read-back frame (its AOVs are stored at full size).
struct Half {
    uint32_t w, h;
    std::vector<float> raw, spatial, temporal, history, depth;
    float at(const std::vector<float>& v, int x, int y) const { return v[size_t(y) * w + x]; }
};

Half half(const FrameImages& f) {
    Half r{(f.width + 1) / 2, (f.height + 1) / 2, {}, {}, {}, {}, {}};
    for (uint32_t y = 0; y < r.h; ++y)
        for (uint32_t x = 0; x < r.w; ++x) {
            const size_t i = size_t(2 * y) * f.width + 2 * x;
            r.raw.push_back(f.aoRaw[i]);
            r.spatial.push_back(f.aoSpatial[i]);
            r.temporal.push_back(f.aoTemporal[i]);
            r.history.push_back(f.aoHistory[i]);
            r.depth.push_back(f.depth[i]);
        }
    return r;
}

AoOptions options(uint32_t history = 16) {
    AoOptions o;
    o.estimator = estimatorPreset("high", 3.0);
    o.chain.temporalHistory = history;
    return o;
}

// A wall in the plane z = 0 facing +Z, with one-voxel bumps that give its AO
// structure, seen straight on from +Z.
voxel::World bumpyWall() {
    return test::makeVoxelWorld({-40, -30, -1}, {40, 30, 0}, [](int x, int y, int z) {
        return z == -1 || (z == 0 && ((x % 7 == 0 && y % 5 == 0) || (x % 11 == 3 && y % 9 < 4)));
    });
}

// The pass's blend for one pixel, from the previous output at the reprojected
// pixel and this frame's AO: clamp to the raw AO's 3x3 range widened by the
// margin, then move towards the spatial AO with weight 1 / length.
float expectedBlend(const Half& now, int x, int y, float previous, float length) {
    float lo = 2.0f, hi = -1.0f;
    for (int j = -1; j <= 1; ++j)
        for (int i = -1; i <= 1; ++i) {
            const float v = now.at(now.raw, std::clamp(x + i, 0, int(now.w) - 1), std::clamp(y + j, 0, int(now.h) - 1));
            lo = std::min(lo, v), hi = std::max(hi, v);
        }
    const float spatial = now.at(now.spatial, x, y);
    lo = std::min(lo, spatial) - GROTTO_TEMPORAL_CLAMP_MARGIN, hi = std::max(hi, spatial) + GROTTO_TEMPORAL_CLAMP_MARGIN;
    return std::clamp(previous, lo, hi) + (spatial - std::clamp(previous, lo, hi)) / length;
}

// World position seen at AO pixel (x, y).
glm::dvec3 worldAt(const Camera& camera, const Half& f, int x, int y) {
    return camera.pointAt(2 * x + 0.5, 2 * y + 0.5, f.at(f.depth, x, y));
}

class Temporal : public GpuTest {
protected:
    struct Run {
        std::unique_ptr<GpuScene> scene;
        std::unique_ptr<Renderer> renderer;
    };
    // Frames 0 and 1 from cameras a and b: the first output, and the second's.
    static std::pair<Half, Half> twoFrames(Run& run, const Camera& a, const Camera& b) {
        run.renderer->render(a, 0);
        Half first = half(run.renderer->readback(a, true));
        run.renderer->render(b, 1);
        return {std::move(first), half(run.renderer->readback(b, true))};
    }
    Run start(const voxel::World& world, const AoOptions& ao, uint32_t w, uint32_t h) {
        Run r;
        r.scene = uploadScene(ctx(), world.mesh(), world.desc());
        r.renderer = std::make_unique<Renderer>(ctx(), *r.scene, world.desc().lighting, ao, w, h);
        return r;
    }
};

TEST_F(Temporal, StillCameraReprojectsEveryPixelOntoItself) {
    const voxel::World world = voxel::World::load(test::worldsDir() / "rooms.json");
    // One denoise pass (the default: the temporal pass blurs the raw AO itself) and
    // two (it blurs the first pass's output and reads the raw AO for its clamp).
    for (const uint32_t denoise : {1u, 2u}) {
        AoOptions ao = options();
        ao.chain.denoisePasses = denoise;
        Run run = start(world, ao, 160, 90);
        const Camera camera = worldCamera(world, "table", 160, 90);
        run.renderer->render(camera, 7);
        const Half first = half(run.renderer->readback(camera, true));
        run.renderer->render(camera, 8);
        const Half second = half(run.renderer->readback(camera, true));
        int checked = 0;
        for (int y = 0; y < int(second.h); ++y)
            for (int x = 0; x < int(second.w); ++x) {
                if (!std::isfinite(second.at(second.depth, x, y))) continue;
                EXPECT_EQ(first.at(first.history, x, y), 1.0f);  // a fresh sequence
                ASSERT_EQ(second.at(second.history, x, y), 2.0f) << x << "," << y;
                EXPECT_NEAR(second.at(second.temporal, x, y),
                            expectedBlend(second, x, y, first.at(first.temporal, x, y), 2.0f), 1e-6)
                    << x << "," << y << " with " << denoise << " denoise passes";
                ++checked;
            }
        EXPECT_GT(checked, 3000);
    }
}

TEST_F(Temporal, OnePixelPanReprojectsTheHistoryExactly) {
    const voxel::World world = bumpyWall();
    const uint32_t w = 128, h = 96;
    Run run = start(world, options(), w, h);
    const double wallZ = world.origin().z;  // the top face of voxel layer z = -1
    const glm::dvec3 eye(0.31, 0.27, wallZ + 12.0);
    const Camera a = makeCamera(test::lookAt(eye, eye - glm::dvec3(0, 0, 1)), w, h);
    // One AO pixel at the wall's distance: the wall moves exactly one pixel left.
    const double pixel = 2.0 * 2.0 * std::tan(a.fovY / 2) * a.aspect() / w * 12.0;
    const Camera b = makeCamera(test::lookAt(eye + glm::dvec3(pixel, 0, 0), eye + glm::dvec3(pixel, 0, -1)), w, h);
    const auto [first, second] = twoFrames(run, a, b);
    // Only the wall plane moves by exactly one pixel; bumps are nearer.
    auto onWall = [&](const Half& f, int px, int py) { return std::abs(f.at(f.depth, px, py) - 12.0f) < 1e-3f; };
    int checked = 0;
    double worst = 0.0;
    for (int y = 2; y < int(second.h) - 2; ++y)
        for (int x = 2; x < int(second.w) - 3; ++x) {
            if (!onWall(second, x, y) || !onWall(first, x + 1, y)) continue;
            EXPECT_EQ(second.at(second.history, x, y), 2.0f) << x << "," << y;
            const double got = second.at(second.temporal, x, y);
            const double want = expectedBlend(second, x, y, first.at(first.temporal, x + 1, y), 2.0f);
            worst = std::max(worst, std::abs(got - want));
            EXPECT_NEAR(got, want, 1e-6) << x << "," << y;  // measured 3.6e-7
            ++checked;
        }
    EXPECT_GT(checked, 1500);
    std::printf("%d pixels, worst %.2e\n", checked, worst);
    // The last column shows what the first camera never saw: its reprojection
    // falls off-screen, so its history restarts; the column beside it keeps its own.
    const int last = int(second.w) - 1;
    int restarted = 0, kept = 0;
    for (int y = 0; y < int(second.h); ++y) {
        if (std::isfinite(second.at(second.depth, last, y))) {
            EXPECT_EQ(second.at(second.history, last, y), 1.0f) << "row " << y;
            EXPECT_EQ(second.at(second.temporal, last, y), second.at(second.spatial, last, y)) << "row " << y;
            ++restarted;
        }
        if (onWall(second, last - 1, y) && onWall(first, last, y)) {
            EXPECT_EQ(second.at(second.history, last - 1, y), 2.0f) << "row " << y;
            ++kept;
        }
    }
    EXPECT_EQ(restarted, int(second.h));
    EXPECT_GT(kept, int(second.h) / 2);
}

TEST_F(Temporal, TurningCameraReprojectsThroughDepthAndBothCameras) {
    // A turn and a step at once: every pixel moves by its own sub-pixel amount.
    // The expected history is the previous output interpolated bilinearly at the
    // point's position in the previous view, computed here in double.
    const voxel::World world = bumpyWall();
    const uint32_t w = 128, h = 96;
    Run run = start(world, options(), w, h);
    const double wallZ = world.origin().z;
    const glm::dvec3 eye(0.31, 0.27, wallZ + 12.0);
    const Camera a = makeCamera(test::lookAt(eye, eye + glm::dvec3(0.05, 0.02, -1)), w, h);
    const Camera b = makeCamera(test::lookAt(eye + glm::dvec3(0.1, -0.05, 0.2), eye + glm::dvec3(0.09, 0.04, -1)), w, h);
    const auto [first, second] = twoFrames(run, a, b);
    const glm::dmat4 clipA = a.projection() * a.viewFromWorld();
    int checked = 0;
    double worst = 0.0;
    for (int y = 2; y < int(second.h) - 2; ++y)
        for (int x = 2; x < int(second.w) - 2; ++x) {
            const glm::dvec3 p = worldAt(b, second, x, y);
            if (!(std::abs(p.z - wallZ) < 1e-3)) continue;  // the wall plane only
            const glm::dvec4 clip = clipA * glm::dvec4(p, 1.0);
            // AO pixel coordinates in the first frame (AO pixel i sits at full-res 2i + 0.5).
            const glm::dvec2 uv = ((glm::dvec2(clip) / clip.w * 0.5 + 0.5) * glm::dvec2(w, h) - 0.5) / 2.0;
            const glm::ivec2 base(glm::floor(uv));
            // Its 2x2 neighbourhood must lie on the first frame: the step and turn carry
            // edge pixels off it (reading them was out of bounds).
            if (base.x < 0 || base.y < 0 || base.x + 1 >= int(first.w) || base.y + 1 >= int(first.h)) continue;
            const glm::dvec2 f = uv - glm::dvec2(base);
            double expected = 0.0;
            bool plane = true;
            for (int j = 0; j < 2; ++j)
                for (int i = 0; i < 2; ++i) {
                    const int tx = base.x + i, ty = base.y + j;
                    plane = plane && std::abs(worldAt(a, first, tx, ty).z - wallZ) < 1e-3;
                    expected += (i ? f.x : 1 - f.x) * (j ? f.y : 1 - f.y) * first.at(first.temporal, tx, ty);
                }
            if (!plane) continue;
            const double got = second.at(second.temporal, x, y);
            const double want = expectedBlend(second, x, y, float(expected), 2.0f);
            worst = std::max(worst, std::abs(got - want));
            EXPECT_NEAR(got, want, 2e-3) << x << "," << y;
            ++checked;
        }
    EXPECT_GT(checked, 1000);
    std::printf("%d pixels, worst %.2e\n", checked, worst);
}

TEST_F(Temporal, CutsAndNewSequencesStartAfresh) {
    const voxel::World world = voxel::World::load(test::worldsDir() / "rooms.json");
    Run run = start(world, options(), 96, 54);
    const Camera camera = worldCamera(world, "table", 96, 54);
    for (uint32_t i = 0; i < 3; ++i) run.renderer->render(camera, i);
    auto histories = [&] {
        const Half f = half(run.renderer->readback(camera, true));
        float lo = 1e9f, hi = -1e9f;
        for (size_t i = 0; i < f.history.size(); ++i)
            if (std::isfinite(f.depth[i])) lo = std::min(lo, f.history[i]), hi = std::max(hi, f.history[i]);
        return std::pair{lo, hi};
    };
    EXPECT_EQ(histories(), (std::pair{3.0f, 3.0f}));
    run.renderer->resetHistory();  // a camera cut
    run.renderer->render(camera, 3);
    EXPECT_EQ(histories(), (std::pair{1.0f, 1.0f}));
    run.renderer->render(camera, 4);
    EXPECT_EQ(histories(), (std::pair{2.0f, 2.0f}));
    run.renderer->render(camera, 9);  // not the next frame: a new sequence
    EXPECT_EQ(histories(), (std::pair{1.0f, 1.0f}));
    const Half f = half(run.renderer->readback(camera, true));
    EXPECT_EQ(f.temporal, f.spatial);  // no history: the spatial AO passes through
}

// Mean AO over surface pixels.
double meanAo(const FrameImages& f) {
    double sum = 0.0;
    size_t n = 0;
    for (size_t i = 0; i < f.ao.size(); ++i)
        if (std::isfinite(f.depth[i])) sum += f.ao[i], ++n;
    return sum / double(n);
}

TEST_F(Temporal, StillCameraDoesNotDriftOverTenThousandFramesNorAtTheCounterWrap) {
    const voxel::World world = voxel::World::load(test::worldsDir() / "rooms.json");
    const Camera camera = worldCamera(world, "table", 32, 18);
    Run run = start(world, options(), 32, 18);
    // Under the sanitizers 2000 frames, not 10000: every frame runs the same passes.
    const uint32_t last = uint32_t(test::underSanitizers(10000, 2000));
    double at1000 = 0.0;
    for (uint32_t i = 0; i <= last; ++i) {
        run.renderer->render(camera, i);
        if (i == 1000) at1000 = meanAo(run.renderer->readback(camera, true));
    }
    const FrameImages atLast = run.renderer->readback(camera, true);
    // Frames 1000 and 10000 (2000) sit at other points of the 64-frame noise cycle;
    // the history averages over it, so their means must still agree.
    EXPECT_NEAR(meanAo(atLast), at1000, 1e-3);
    // The same sequence started one noise cycle (64 frames) before the 32-bit
    // counter wraps (phase 0, as from 0) gives the same pixels, history intact
    // across it: 64 frames fill the 16-frame history before the wrap, and fewer
    // than 16 after it leave a history cut at the wrap short of 16.
    Run wrapped = start(world, options(), 32, 18);
    Run plain = start(world, options(), 32, 18);
    const uint32_t startAt = 0xFFFFFFFFu - 63u;
    for (uint32_t i = 0; i < 64 + 8; ++i) {
        wrapped.renderer->render(camera, startAt + i);
        plain.renderer->render(camera, i);
    }
    const FrameImages a = wrapped.renderer->readback(camera, true), b = plain.renderer->readback(camera, true);
    EXPECT_EQ(a.ao, b.ao);
    EXPECT_EQ(a.aoHistory, b.aoHistory);
    for (size_t i = 0; i < a.aoHistory.size(); ++i)
        if (std::isfinite(a.depth[i])) ASSERT_EQ(a.aoHistory[i], 16.0f) << "history cut at the wrap";
}

TEST_F(Temporal, DisoccludedPixelsShowNoGhostOfTheOccluder) {
    // A pillar in front of a floor/wall corner; the camera slides sideways and
    // uncovers the wall behind it. Pixels uncovered then must reach the AO that
    // a camera resting there converges to, with history no older than the uncovering.
    const voxel::World world = test::makeVoxelWorld({-30, -1, -30}, {30, 20, 10}, [](int x, int y, int z) {
        return y == -1 || z == -30 || (x >= -1 && x <= 1 && z >= -12 && z <= -10 && y < 12);
    });
    const uint32_t w = 160, h = 90;
    auto cameraAt = [&](double x) { return makeCamera(test::lookAt({x, 6, 8}, {x, 4, -30}), w, h); };
    const AoOptions ao = options();
    Run moving = start(world, ao, w, h);
    uint32_t frame = 0;
    for (; frame < 20; ++frame) moving.renderer->render(cameraAt(0.0), frame);
    const Half before = half(moving.renderer->readback(cameraAt(0.0), true));
    constexpr int kSlide = 4, kSettle = 8;
    for (int k = 1; k <= kSlide; ++k) moving.renderer->render(cameraAt(1.5 * k), frame++);
    for (int k = 0; k < kSettle; ++k) moving.renderer->render(cameraAt(6.0), frame++);
    const Camera end = cameraAt(6.0);
    const Half after = half(moving.renderer->readback(end, true));

    Run resting = start(world, ao, w, h);
    for (uint32_t i = 0; i < 64; ++i) resting.renderer->render(end, frame - 64 + i);
    const Half steady = half(resting.renderer->readback(end, true));

    // Uncovered: back-wall points that the pillar hid from the first camera.
    const Camera first = cameraAt(0.0);
    const glm::dmat4 firstClip = first.projection() * first.viewFromWorld();
    double sumDiff = 0.0;
    int uncovered = 0, kept = 0;
    for (int y = 0; y < int(after.h); ++y)
        for (int x = 0; x < int(after.w); ++x) {
            const double z = after.at(after.depth, x, y);
            if (!(z > 30.0)) continue;
            const glm::dvec3 world = end.pointAt(2 * x + 0.5, 2 * y + 0.5, z);
            const glm::dvec4 clip = firstClip * glm::dvec4(world, 1.0);
            const glm::dvec2 px = (glm::dvec2(clip) / clip.w * 0.5 + 0.5) * glm::dvec2(w, h);
            if (!std::isfinite(px.x) || !std::isfinite(px.y)) continue;  // the sky: no point to project
            const int bx = int(px.x) / 2, by = int(px.y) / 2;
            if (bx < 0 || by < 0 || bx >= int(before.w) || by >= int(before.h)) continue;
            if (!(before.at(before.depth, bx, by) < 25.0f)) continue;  // the pillar was in front
            if (after.at(after.history, x, y) > float(kSlide + kSettle)) ++kept;
            sumDiff += std::abs(after.at(after.temporal, x, y) - steady.at(steady.temporal, x, y));
            ++uncovered;
        }
    ASSERT_GT(uncovered, 50);
    // A freshly uncovered pixel whose bilinear footprint reaches the wall still
    // visible beside the pillar takes that (same-plane) history; the rest must
    // restart. Measured: 32 % keep it; 94 % without the plane test.
    EXPECT_LT(double(kept) / uncovered, 0.5) << kept << " of " << uncovered << " kept history from before";
    EXPECT_LT(sumDiff / uncovered, 0.05) << uncovered << " uncovered pixels";
    std::printf("%d uncovered pixels, %d kept history, mean |AO - steady AO| %.4f\n", uncovered, kept, sumDiff / uncovered);
}

}  // namespace
}  // namespace grotto
