#pragma once
// A whole world's full light baked on a thread of its own, from a copy of the
// world as it was when it started: for a cache that starts with nothing traced
// (the viewer, the engine API), whose GPU tracer knows the sky's light alone. The
// frames go on meanwhile; their owner takes the result between two of them.
// OpenVDB-free interface.
#include "voxel/face_bake.h"
#include "voxel/light_edit.h"

#include <atomic>
#include <exception>
#include <thread>
#include <vector>

namespace grotto::voxel {

struct BakedLight {
    std::vector<ExposedFace> faces;     // exposedFaces of the world copied
    std::vector<FaceTexel> texels;      // bakeFaces, then bakeLight, with the settings given
    std::vector<GlowingFace> glowing;   // glowingFaces of it
    std::vector<glm::vec3> dayLight;    // with the day's sun: kDayLightWords a face (bakeLight)
};

class LightBakeThread {
public:
    // Starts at once. `settings.fullLight` must be set.
    LightBakeThread(const World& world, const FaceBakeSettings& settings);
    // Stops a bake still running at its next step, and waits for it.
    ~LightBakeThread();
    LightBakeThread(const LightBakeThread&) = delete;
    LightBakeThread& operator=(const LightBakeThread&) = delete;

    bool finished() const { return finished_.load(std::memory_order_acquire); }
    void wait();  // until finished
    // How far it got: 0 to 1 (the AO and sky rays the first half, the bounces the second).
    double done() const { return done_.load(std::memory_order_relaxed); }
    // Once finished: the bake, or the grotto::Error it threw (a world too large for
    // the memory budget, say). Once only.
    BakedLight take();

private:
    void run(World world, FaceBakeSettings settings);

    std::atomic<bool> stop_{false}, finished_{false};
    std::atomic<double> done_{0.0};
    BakedLight result_;
    std::exception_ptr error_;
    std::thread thread_;
};

}  // namespace grotto::voxel
