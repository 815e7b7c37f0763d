#pragma once
// A renderer's frame of a test world with one set of AO options, read back with
// the constants its AO passes ran with, so tests can rebuild any pixel on the CPU
// (GtaoTwin) or compare estimators on the same view.
#include "engine/renderer.h"
#include "tests/gpu_fixture.h"

#include <string>

namespace grotto::test {

struct Rendered {
    FrameImages img;
    Camera camera;
    gpu::GtaoConstants constants;
};

class AoFixture : public GpuTest {
protected:
    // The world's own lighting unless `lighting` is given.
    Rendered render(const voxel::World& world, const voxel::CameraDesc& cd, uint32_t w, uint32_t h,
                    const AoOptions& ao, const voxel::Lighting* lighting = nullptr) {
        return render(*upload(world, ao), world, cd, w, h, ao, lighting);
    }
    // The world's occupancy only where the AO traces it.
    std::unique_ptr<GpuScene> upload(const voxel::World& world, const AoOptions& ao) {
        return tracesVoxels(ao.method) || voxelThickness(ao) ? uploadScene(ctx(), world)
                                                             : uploadScene(ctx(), world.mesh(), world.desc());
    }
    // A scene from upload(world, ao) for many views: meshing it again for each is what costs.
    Rendered render(GpuScene& scene, const voxel::World& world, const voxel::CameraDesc& cd, uint32_t w, uint32_t h,
                    const AoOptions& ao, const voxel::Lighting* lighting = nullptr) {
        Rendered r{{}, makeCamera(cd, w, h), {}};
        Renderer renderer(ctx(), scene, lighting ? *lighting : world.desc().lighting, ao, w, h);
        renderer.render(r.camera);
        r.img = renderer.readback(r.camera, true);
        r.constants = gtaoConstants(r.camera, gpuSettings(ao), 0, ao.chain.fullResolution ? 1 : 2);
        return r;
    }
    // A preset's settings with the radius in world units.
    static AoOptions options(const std::string& quality, double radius = 4.0, AoMethod method = AoMethod::Gtao) {
        AoOptions o;
        o.method = method;
        o.quality = quality;
        o.estimator = estimatorPreset(quality, radius);
        return o;
    }
    // World position seen at a full-res pixel.
    static glm::dvec3 worldAt(const Rendered& r, uint32_t x, uint32_t y) {
        return r.camera.pointAt(x + 0.5, y + 0.5, r.img.depth[size_t(y) * r.img.width + x]);
    }
};

}  // namespace grotto::test
