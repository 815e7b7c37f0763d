#include "app/ao_measure.h"

#include "app/options.h"
#include "grotto/error.h"
#include "engine/image_output.h"

#include <algorithm>
#include <cmath>

#include <memory>

namespace grotto::app {

void requireSurface(const ReferenceView& reference, const voxel::World& world, const std::string& camera) {
    if (std::find(reference.surface.begin(), reference.surface.end(), uint8_t(1)) != reference.surface.end()) return;
    const std::string view = camera.empty() ? "the default camera" : "camera '" + camera + "'";
    throw Error(world.desc().source.string(), view + " sees no surface: there is nothing to measure",
                "accepted: a view that shows the world's surfaces; pick another --camera");
}

double imageChange(const std::vector<float>& withAo, const std::vector<float>& withoutAo,
                   const std::vector<uint8_t>& surface) {
    double sum = 0.0;
    size_t n = 0;
    for (size_t i = 0; i < surface.size(); ++i) {
        if (!surface[i]) continue;
        for (int c = 0; c < 3; ++c)
            sum += std::abs(double(toSrgb8(withAo[4 * i + c])) - double(toSrgb8(withoutAo[4 * i + c]))) / 255.0;
        n += 3;
    }
    return n ? sum / double(n) : 0.0;
}

AoMeasurement measureAo(vk::Context& ctx, RenderSession& session, const Camera& camera,
                        const AoOptions& ao, const CullingOptions& culling, const ReferenceView& reference,
                        int frames, int warmup, bool timed, std::vector<float>* color) {
    // Costs as wall-time differences against the same frames without AO, rendered
    // interleaved: lavapipe's timestamps miss passes that follow a barrier.
    const voxel::Lighting& lighting = session.world().desc().lighting;
    auto make = [&](const AoOptions& options, const voxel::Lighting& light) {
        auto r = std::make_unique<Renderer>(ctx, session.scene().gpu(), light, options, camera.width, camera.height,
                                            session.objects());
        r->setCulling(culling);
        if (session.objects()) r->setObjectPoses(session.poses());
        return r;
    };
    const std::unique_ptr<Renderer> renderer = make(ao, lighting);
    AoOptions off = ao;
    off.enabled = false;
    // The face cache's sun takes the shadow pass's place: its frames without AO
    // are timed without sun shadows too, so its cost is AO and sun together.
    voxel::Lighting unshadowed = lighting;
    unshadowed.sunShadows = false;
    const bool withSun = faceCached(ao) && lighting.sunShadows;
    std::unique_ptr<Renderer> withoutAo;
    if (timed) withoutAo = make(off, withSun ? unshadowed : lighting);
    std::vector<double> aoMs, frameMs, gbufferMs;
    FrameStats last;
    for (int i = 0; i < frames; ++i) {
        // The two take turns going first, so what one frame leaves behind (caches,
        // clocks) does not always favour the same one.
        const double wallOffFirst = withoutAo && i % 2 ? withoutAo->render(camera, uint32_t(i)).wallMs : 0.0;
        last = renderer->render(camera, uint32_t(i));
        if (i >= warmup)
            for (const auto& [pass, ms] : last.passMs)
                if (pass == "gbuffer") gbufferMs.push_back(ms);
        if (!withoutAo) continue;
        const double wallOff = i % 2 ? wallOffFirst : withoutAo->render(camera, uint32_t(i)).wallMs;
        if (i < warmup) continue;
        aoMs.push_back(last.wallMs - wallOff);
        frameMs.push_back(last.wallMs);
    }
    FrameImages img = renderer->readback(camera, true);
    if (!withoutAo || withSun) {  // the image without AO keeps the sun's shadows
        withoutAo = make(off, lighting);
        withoutAo->render(camera, uint32_t(frames - 1));
    }
    const FrameImages plain = withoutAo->readback(camera, false);
    std::vector<float> shown = displayColor(img);
    AoMeasurement m{aoError(img.ao, reference.ao, reference.surface), costDifference(aoMs), median(frameMs),
                    imageChange(shown, displayColor(plain), reference.surface)};
    m.msGbuffer = median(gbufferMs);
    m.quadsDrawn = last.quadsDrawn;
    m.culling = last.culling;
    m.linearColor = std::move(img.color);
    if (color) *color = std::move(shown);
    return m;
}

}  // namespace grotto::app
