#include "app/ao_measure.h"

#include "app/options.h"
#include "common/error.h"
#include "engine/renderer.h"

#include <algorithm>

#include <memory>

namespace grotto::app {

void requireSurface(const ReferenceView& reference, const voxel::World& world, const std::string& camera) {
    if (std::find(reference.surface.begin(), reference.surface.end(), uint8_t(1)) != reference.surface.end()) return;
    const std::string view = camera.empty() ? "the default camera" : "camera '" + camera + "'";
    throw Error(world.desc().source.string(), view + " sees no surface: there is nothing to measure",
                "accepted: a view that shows the world's surfaces; pick another --camera");
}

AoMeasurement measureAo(vk::Context& ctx, GpuScene& scene, const voxel::World& world, const Camera& camera,
                        const AoOptions& ao, const ReferenceView& reference, int frames, int warmup,
                        bool timed) {
    // Costs as wall-time differences against the same frames without AO, rendered
    // interleaved: lavapipe's timestamps miss passes that follow a barrier.
    Renderer renderer(ctx, scene, world.desc().lighting, ao, camera.width, camera.height);
    AoOptions off = ao;
    off.enabled = false;
    std::unique_ptr<Renderer> withoutAo;
    if (timed) withoutAo = std::make_unique<Renderer>(ctx, scene, world.desc().lighting, off, camera.width, camera.height);
    std::vector<double> aoMs, frameMs;
    for (int i = 0; i < frames; ++i) {
        // The two take turns going first, so what one frame leaves behind (caches,
        // clocks) does not always favour the same one.
        const double wallOffFirst = withoutAo && i % 2 ? withoutAo->render(camera, uint32_t(i)).wallMs : 0.0;
        const double wall = renderer.render(camera, uint32_t(i)).wallMs;
        if (!withoutAo) continue;
        const double wallOff = i % 2 ? wallOffFirst : withoutAo->render(camera, uint32_t(i)).wallMs;
        if (i < warmup) continue;
        aoMs.push_back(wall - wallOff);
        frameMs.push_back(wall);
    }
    const FrameImages img = renderer.readback(camera, true);
    return {aoError(img.ao, reference.ao, reference.surface), costDifference(aoMs), median(frameMs)};
}

}  // namespace grotto::app
