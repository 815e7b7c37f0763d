// The uniforms and constants each frame writes into its slot: the frame's, the
// AO's and the temporal pass's (whose history follows consecutive frame indices),
// the voxel traces' and the objects' normal tables.
#include "engine/renderer.h"

#include "engine/frame/frame_constants.h"
#include "engine/frame/object_frame.h"
#include "engine/passes/trace_inputs.h"

#include <bit>
#include <cmath>
#include <cstring>

namespace grotto {

void Renderer::writeConstants(const Camera& camera, uint32_t frameIndex) {
    FrameSlot& s = slot();
    gpu::FrameUniforms uniforms = frameUniforms(camera, lighting_, ao_);
    if (plan_.scene.faceCache) {
        const GpuFaceCache& cache = *scene_.faceCache();
        uniforms.faceCache = {cache.table(), cache.texelsPerSide()};
        // What the cache's light words hold decides how the composite reads them:
        // a world switched to full light over a sky-light cache keeps the sky's
        // light, and a full-light cache has no sky weights to give.
        if (plan_.faceCache && uniforms.ambient.w >= 0.5f) uniforms.ambient.w = plan_.cacheFullLight ? 2.0f : 1.0f;
        const CameraVoxel v = cameraVoxel(camera, scene_.voxelSize, scene_.worldOrigin);
        uniforms.cameraCell = glm::ivec4(v.cell, int32_t(frameIndex & 0x7fffffffu));
        uniforms.cameraFraction = glm::vec4(v.fraction, float(1.0 / scene_.voxelSize));
        // The day's sun from the cache: the positions either side of the hour.
        if (plan_.daySun) {
            const voxel::SunPath& path = *cache.sun().day;
            const int count = int(voxel::kDaySunPositions);
            const voxel::SunPositionSpan span = voxel::sunPositionSpan(path, double(given_.timeOfDay), count);
            const uint32_t before = uint32_t(span.before), after = uint32_t(span.before + 1);
            // Before sunrise and after sunset the disc's last sliver lies beyond the
            // positions (the first and last stand at the horizon): traced per pixel.
            uniforms.daySun = glm::uvec4(cache.daySunFirst(), before, after, span.beyond ? 1u : 0u);
            uniforms.daySunBefore = glm::vec4(glm::vec3(voxel::sunDirectionAt(path, voxel::sunPositionHour(path, int(before), count))), 0.0f);
            uniforms.daySunAfter = glm::vec4(glm::vec3(voxel::sunDirectionAt(path, voxel::sunPositionHour(path, int(after), count))), 0.0f);
        }
        // Full light over the day: the bounce positions either side of the hour.
        if (plan_.cacheDayLight) {
            const voxel::SunPositionSpan at =
                voxel::sunPositionSpan(*cache.sun().day, double(given_.timeOfDay), int(voxel::kDaySunPositions));
            const voxel::DayBounceSpan b = voxel::dayBounceSpan(at.before + at.toward);
            uniforms.dayLight = glm::uvec4(cache.dayLightFirst(), cache.dayFacesFirst(), b.before | b.after << 16,
                                           std::bit_cast<uint32_t>(float(b.toward)));
        }
    }
    std::memcpy(s.frame.mapped(), &uniforms, sizeof uniforms);
    if (plan_.chain) {
        const uint32_t scale = ao_.chain.fullResolution ? 1 : 2;
        gpu::GtaoConstants constants = gtaoConstants(camera, gpuSettings(ao_), frameIndex, scale);
        if (objects_) normalTable(constants.viewNormals, glm::transpose(camera.basis), poses_);
        std::memcpy(s.aoConstants.mapped(), &constants, sizeof constants);
        if (plan_.temporal) {
            // A frame index that does not follow the last (wrapping) starts a new
            // sequence. A zoom or new clip planes need no reset: the history is
            // reprojected through the previous projection and holds linear depth.
            if (frameIndex != previousFrame_ + 1u) previousCamera_.reset();
            gpu::TemporalConstants t = temporalConstants(camera, previousCamera_ ? &*previousCamera_ : nullptr);
            invalidated_.write(camera.position, aoReach(ao_), t);
            std::memcpy(s.temporalConstants.mapped(), &t, sizeof t);
            previousCamera_ = camera;
            previousFrame_ = frameIndex;
        }
    }
    writeTraceConstants(camera, frameIndex, uniforms);  // before the edits are cleared: they restart a soft sun's history
    invalidated_.clear();  // edits before this frame; later ones go to the next
    // The frame before (for motion and the temporal plane test); this one's own where there was none.
    if (objects_) {
        const gpu::ObjectUniforms o =
            objectUniforms(poses_, lastCamera_ ? *lastCamera_ : camera, lastCamera_ ? lastPoses_ : poses_);
        std::memcpy(s.objectUniforms.mapped(), &o, sizeof o);
    }
}

void Renderer::refreshObjectGrids() {
    const uint64_t version = objects_ ? objects_->gridsVersion : 0;
    if (objectGrids_.buffer.buffer && version == objectGridsVersion_) return;
    finishFrames();  // no frame in flight may read the grids replaced
    vk::destroy(ctx_, objectGrids_.buffer);
    objectGrids_ = uploadObjectGrids(ctx_, objects_ ? std::span<const ObjectGrid>(objects_->grids) : std::span<const ObjectGrid>());
    objectGridsVersion_ = version;
}

void Renderer::writeTraceConstants(const Camera& camera, uint32_t frameIndex, const gpu::FrameUniforms& frame) {
    if (!plan_.scene.occupancy) return;
    const double radius = ao_.enabled ? ao_.estimator.radius : 1.0;
    gpu::TraceConstants t = traceConstants(camera, *scene_.occupancy(), scene_.voxelSize, scene_.worldOrigin,
                                           lighting_.sunDirection, ao_.estimator.rays, radius);
    if (objects_)
        setObjectTraces(t, objects_->grids, objectGrids_.first, poses_, lastCamera_ ? lastPoses_ : poses_, scene_.voxelSize,
                        scene_.worldOrigin);
    if (plan_.objectLight) {
        // Objects over the face cache's full light: the light world faces send
        // (their texels and materials), the sky's and the sun's, in its units.
        const GpuFaceCache& cache = *scene_.faceCache();
        const bool full = lighting_.ambientFrom == voxel::AmbientSource::Full && cache.sky().fullLight;
        t.faceCache = glm::uvec4(cache.table(), cache.texelsPerSide(), cache.materialsFirst(), full ? 1u : 0u);
        t.skyZenith = glm::vec4(lighting_.skyZenith * lighting_.ambientIntensity, 0.0f);
        t.skyHorizon = glm::vec4(lighting_.skyHorizon * lighting_.ambientIntensity, 0.0f);
        t.sunRadiance = glm::vec4(lighting_.sunColor * lighting_.sunIntensity, 0.0f);
        t.dayLight = full ? frame.dayLight : glm::uvec4(0u);
        t.daySun = frame.daySun;
    }
    t.sunCosRadius = float(std::cos(glm::radians(0.5 * double(lighting_.sunAngle))));
    t.frameIndex = frameIndex;
    if (plan_.surfaceHistory) {
        // As the AO's history: consecutive frames only. An edit anywhere may move a
        // shadow anywhere along the sun's rays (or change what an object hides), so
        // it restarts the whole history.
        if (frameIndex != surfaceFrame_ + 1u || !invalidated_.boxes().empty()) surfaceCamera_.reset();
        const gpu::TemporalConstants r = temporalConstants(camera, surfaceCamera_ ? &*surfaceCamera_ : nullptr);
        t.currentToPrevious = r.currentToPrevious;
        t.previousNdcToViewMul_Add = r.previousNdcToViewMul_Add;
        t.shadowHistory = ao_.chain.temporalHistory > 0 ? ao_.chain.temporalHistory : kDefaultTemporalHistory;
        t.shadowReset = (r.reset != 0u ? 1u : 0u) | (objects_ && objects_->moving ? 2u : 0u);
        surfaceCamera_ = camera;
        surfaceFrame_ = frameIndex;
    }
    std::memcpy(slot().traceConstants.mapped(), &t, sizeof t);
}

}  // namespace grotto
