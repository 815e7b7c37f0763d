#pragma once
// The wall-time cost of the AO chain and of the temporal pass: every frame is
// also rendered without AO and without the temporal pass, the three renderers
// taking turns to go first (so whatever one frame leaves behind, caches or
// clocks, does not always favour the same one), and the differences are kept.
// Lavapipe's timestamps miss passes that follow a barrier; these do not.
// Shared by `grotto bench` and `grotto stability`.
#include "engine/renderer.h"

#include <memory>
#include <vector>

namespace grotto::app {

class AoCostTimer {
public:
    AoCostTimer(vk::Context& ctx, GpuScene& scene, const voxel::Lighting& lighting, const AoOptions& ao,
                uint32_t width, uint32_t height, const SceneObjects* objects = nullptr);

    // Renders frame `index` with `renderer` (made with the same settings) and with
    // the two comparisons (at the renderer's object poses, with its levels of detail
    // and culling); keeps the differences when `record` is set.
    FrameStats render(Renderer& renderer, const Camera& camera, uint32_t index, bool record = true);

    // Per recorded frame; empty where there is nothing to compare (AO off, no temporal pass).
    const std::vector<double>& chainMs() const { return chainMs_; }
    const std::vector<double>& temporalMs() const { return temporalMs_; }

private:
    std::unique_ptr<Renderer> withoutAo_, withoutTemporal_;
    std::vector<double> chainMs_, temporalMs_;
};

}  // namespace grotto::app
