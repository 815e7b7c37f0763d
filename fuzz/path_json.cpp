// Fuzzes the camera-path .json reader, then evaluates every path it accepts the
// way a flythrough does: an accepted path must give finite poses at its keys and
// between them. Bad input must end in grotto::Error of kind Input.
#include "grotto/error.h"
#include "engine/camera_path.h"
#include "fuzz/input_file.h"
#include "voxel/camera_path_desc.h"

#include <cmath>
#include <cstdio>
#include <cstdlib>

namespace {

bool finite(const grotto::CameraPose& p) {
    bool ok = std::isfinite(p.fovDegrees);
    for (int c = 0; c < 3; ++c) {
        ok = ok && std::isfinite(p.position[c]);
        for (int r = 0; r < 3; ++r) ok = ok && std::isfinite(p.basis[c][r]);
    }
    return ok;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    const auto file = grotto::fuzz::writeInput(data, size, "path.json");
    grotto::voxel::CameraPathDesc desc;
    try {
        desc = grotto::voxel::loadCameraPath(file);
    } catch (const grotto::Error& e) {
        if (e.kind() != grotto::Error::Kind::Input) throw;
        return 0;
    }
    const grotto::CameraPath path(desc, grotto::voxel::CameraDesc{});
    for (size_t i = 0; i < desc.keys.size(); ++i) {
        const double t = desc.keys[i].time;
        const double next = i + 1 < desc.keys.size() ? desc.keys[i + 1].time : t;
        for (double time : {t, t + 0.5 * (next - t)})
            if (!finite(path.pose(time))) {
                std::fprintf(stderr, "non-finite pose at time %.17g\n", time);
                std::abort();
            }
    }
    (void)path.frameCount(30.0);
    return 0;
}
