#include "app/ao_cost.h"

namespace grotto::app {

AoCostTimer::AoCostTimer(vk::Context& ctx, GpuScene& scene, const voxel::Lighting& lighting, const AoOptions& ao,
                         uint32_t width, uint32_t height, const SceneObjects* objects) {
    if (!ao.enabled) return;
    AoOptions noAo = ao, noTemporal = ao;
    noAo.enabled = false;
    noTemporal.chain.temporalHistory = 0;
    withoutAo_ = std::make_unique<Renderer>(ctx, scene, lighting, noAo, width, height, objects);
    if (ao.chain.temporalHistory > 0)
        withoutTemporal_ = std::make_unique<Renderer>(ctx, scene, lighting, noTemporal, width, height, objects);
}

FrameStats AoCostTimer::render(Renderer& renderer, const Camera& camera, uint32_t index, bool record) {
    FrameStats f;
    double off = 0.0, noHistory = 0.0;
    for (Renderer* r : {withoutAo_.get(), withoutTemporal_.get()}) {
        if (!r) continue;
        r->setCulling(renderer.culling());  // the same quads drawn, so only the AO differs
        if (!renderer.objectPoses().empty()) r->setObjectPoses(renderer.objectPoses());
    }
    for (uint32_t turn = 0; turn < 3; ++turn) {
        const uint32_t which = (index + turn) % 3;
        if (which == 0) f = renderer.render(camera, index);
        if (which == 1 && withoutAo_) off = withoutAo_->render(camera, index).wallMs;
        if (which == 2 && withoutTemporal_) noHistory = withoutTemporal_->render(camera, index).wallMs;
    }
    if (record && withoutAo_) chainMs_.push_back(f.wallMs - off);
    if (record && withoutTemporal_) temporalMs_.push_back(f.wallMs - noHistory);
    return f;
}

}  // namespace grotto::app
