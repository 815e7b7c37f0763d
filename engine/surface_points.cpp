#include "engine/surface_points.h"

#include <cmath>

namespace grotto {

SurfacePoints surfacePoints(const FrameImages& f, const Camera& camera, double voxelSize, glm::dvec3 origin) {
    SurfacePoints out;
    for (uint32_t y = 0; y < f.height; ++y)
        for (uint32_t x = 0; x < f.width; ++x) {
            const size_t i = size_t(y) * f.width + x;
            if (f.surfaceIds[i] == 0 || !(f.depthBuffer[i] > 0.0f)) continue;  // sky
            // The view-axis distance from the raw depth value, in double: f.depth is a float.
            const double z = camera.linearDepth(double(f.depthBuffer[i]));
            if (!std::isfinite(z)) continue;
            glm::dvec3 p = camera.pointAt(x + 0.5, y + 0.5, z);
            const glm::dvec3 n(f.normal[3 * i], f.normal[3 * i + 1], f.normal[3 * i + 2]);
            const int a = n.x != 0.0 ? 0 : n.y != 0.0 ? 1 : 2;
            p[a] = origin[a] + std::round((p[a] - origin[a]) / voxelSize) * voxelSize;
            out.points.push_back(p);
            out.normals.push_back(n);
            out.pixels.push_back(uint32_t(i));
        }
    return out;
}

}  // namespace grotto
