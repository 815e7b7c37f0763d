#include "engine/lab/surface_points.h"

#include "shaders/shared/objects.h"

#include <cmath>

namespace grotto {

namespace {

SurfacePoints snappedPoints(const FrameImages& f, const Camera& camera, double voxelSize, glm::dvec3 origin,
                            std::span<const voxel::PosedWorld> objects) {
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
            const uint32_t object = gpu::surfaceObject(f.surfaceIds[i]);
            if (object == 0) {
                const int a = n.x != 0.0 ? 0 : n.y != 0.0 ? 1 : 2;
                p[a] = origin[a] + std::round((p[a] - origin[a]) / voxelSize) * voxelSize;
            } else if (object <= objects.size()) {  // in the object's grid: its face is an axis there
                const voxel::PosedWorld& o = objects[object - 1];
                const glm::dvec3 localNormal = glm::conjugate(o.pose.rotation) * n, a3 = glm::abs(localNormal);
                const int a = a3.x >= a3.y && a3.x >= a3.z ? 0 : a3.y >= a3.z ? 1 : 2;
                glm::dvec3 local = o.pose.toLocal(p);
                const double vs = o.world->voxelSize(), from = o.world->origin()[a];
                local[a] = from + std::round((local[a] - from) / vs) * vs;
                p = o.pose.toWorld(local);
            }
            out.points.push_back(p);
            out.normals.push_back(n);
            out.pixels.push_back(uint32_t(i));
            out.owners.push_back(object <= objects.size() ? object : 0);
        }
    return out;
}

}  // namespace

SurfacePoints surfacePoints(const FrameImages& f, const Camera& camera, double voxelSize, glm::dvec3 origin) {
    return snappedPoints(f, camera, voxelSize, origin, {});
}

SurfacePoints surfacePoints(const FrameImages& f, const Camera& camera, const voxel::World& world,
                            std::span<const voxel::PosedWorld> objects) {
    return snappedPoints(f, camera, world.voxelSize(), world.origin(), objects);
}

}  // namespace grotto
