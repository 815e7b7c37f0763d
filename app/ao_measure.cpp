#include "app/ao_measure.h"

#include "app/options.h"
#include "engine/renderer.h"

namespace grotto::app {

AoMeasurement measureAo(vk::Context& ctx, const GpuScene& scene, const voxel::World& world, const Camera& camera,
                        const AoOptions& ao, const ReferenceView& reference, int frames, int warmup) {
    Renderer renderer(ctx, scene, world.desc().lighting, ao, camera.width, camera.height);
    std::vector<double> aoMs, frameMs;
    for (int i = 0; i < frames; ++i) {
        const FrameStats f = renderer.render(camera, uint32_t(i));
        if (i < warmup) continue;
        double chain = 0.0, all = 0.0;
        for (const auto& [name, ms] : f.passMs) {
            all += ms;
            if (name != "gbuffer" && name != "composite") chain += ms;  // the rest is the AO chain
        }
        aoMs.push_back(chain);
        frameMs.push_back(all);
    }
    const FrameImages img = renderer.readback(camera, true);
    return {aoError(img.ao, reference.ao, reference.surface), median(aoMs), median(frameMs)};
}

}  // namespace grotto::app
