#include "engine/lab/temporal_metrics.h"

#include "engine/image_output.h"
#include "shaders/shared/objects.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace grotto {

AoFrame aoFrame(const FrameImages& f, const Camera& camera, uint32_t scale) {
    AoFrame a;
    a.scale = scale;
    a.width = (f.width + scale - 1) / scale;
    a.height = (f.height + scale - 1) / scale;
    const size_t n = size_t(a.width) * a.height;
    a.world.resize(n);
    a.normal.resize(n);
    a.surface.assign(n, 0);
    a.object.assign(n, 0);
    a.raw.resize(n), a.spatial.resize(n), a.temporal.resize(n);
    const std::vector<uint8_t> rgb = f.color.empty() ? std::vector<uint8_t>() : srgb8Pixels(f);
    if (!rgb.empty())
        for (std::vector<float>& channel : a.display) channel.resize(n);
    for (uint32_t y = 0; y < a.height; ++y)
        for (uint32_t x = 0; x < a.width; ++x) {
            const size_t i = size_t(y) * a.width + x, full = size_t(scale * y) * f.width + scale * x;
            a.raw[i] = f.aoRaw[full];
            a.spatial[i] = f.aoSpatial[full];
            a.temporal[i] = f.aoTemporal[full];
            if (!rgb.empty())
                for (int c = 0; c < 3; ++c) a.display[c][i] = float(rgb[3 * full + c]) / 255.0f;
            const double depth = f.depth[full];
            if (!std::isfinite(depth)) continue;
            a.world[i] = camera.pointAt(scale * x + 0.5, scale * y + 0.5, depth);
            a.normal[i] = glm::dvec3(f.normal[3 * full], f.normal[3 * full + 1], f.normal[3 * full + 2]);
            a.surface[i] = 1;
            if (!f.surfaceIds.empty()) a.object[i] = uint8_t(gpu::surfaceObject(f.surfaceIds[full]));
        }
    return a;
}

Reprojection reproject(const AoFrame& now, const AoFrame& before, const Camera& beforeCamera, double tolerance,
                       std::span<const voxel::ObjectPose> poses, std::span<const voxel::ObjectPose> beforePoses) {
    Reprojection r;
    r.nearest.assign(now.world.size(), -1);
    r.taps.assign(now.world.size(), {-1, -1, -1, -1});
    r.weights.assign(now.world.size(), {0.0f, 0.0f, 0.0f, 0.0f});
    // Relative to the camera, so positions far from the origin keep their precision.
    const glm::dmat4 clipFromView = beforeCamera.projection();
    const glm::dmat3 viewFromWorld = glm::transpose(beforeCamera.basis);
    for (size_t i = 0; i < now.world.size(); ++i) {
        if (!now.surface[i]) continue;
        // Where the surface point was: an object's point moved with its object.
        const uint8_t object = now.object.empty() ? 0 : now.object[i];
        glm::dvec3 point = now.world[i], normal = now.normal[i];
        if (object > 0 && object <= poses.size() && object <= beforePoses.size()) {
            const voxel::ObjectPose &a = poses[object - 1], &b = beforePoses[object - 1];
            point = b.toWorld(a.toLocal(point));
            normal = b.rotation * (glm::conjugate(a.rotation) * normal);
        }
        auto sameObject = [&](size_t j) { return (before.object.empty() ? 0 : before.object[j]) == object; };
        const glm::dvec3 view = viewFromWorld * (point - beforeCamera.position);
        if (view.z >= 0.0) continue;  // behind the previous camera
        const glm::dvec4 clip = clipFromView * glm::dvec4(view, 1.0);
        const double px = (clip.x / clip.w * 0.5 + 0.5) * beforeCamera.width;
        const double py = (clip.y / clip.w * 0.5 + 0.5) * beforeCamera.height;
        // In AO pixel units (AO pixel k sits at full-res scale k + 0.5); the nearest one.
        const double u = (px - 0.5) / before.scale, v = (py - 0.5) / before.scale;
        const double qx = std::floor(u + 0.5), qy = std::floor(v + 0.5);
        if (!(qx >= 0 && qy >= 0 && qx < before.width && qy < before.height)) continue;
        const size_t j = size_t(qy) * before.width + size_t(qx);
        if (!before.surface[j] || !sameObject(j) || glm::length(before.world[j] - point) > tolerance) continue;
        r.nearest[i] = int32_t(j);
        // Bilinear taps around the exact position.
        const double bx = std::floor(u), by = std::floor(v), fx = u - bx, fy = v - by;
        const double planeTolerance = 1e-3 * -view.z;
        float sum = 0.0f;
        for (int k = 0; k < 4; ++k) {
            const double tx = bx + (k & 1), ty = by + (k >> 1);
            if (!(tx >= 0 && ty >= 0 && tx < before.width && ty < before.height)) continue;
            const size_t t = size_t(ty) * before.width + size_t(tx);
            if (!before.surface[t] || !sameObject(t) || glm::dot(before.normal[t], normal) < 0.9999 ||
                std::abs(glm::dot(before.world[t] - point, normal)) > planeTolerance)
                continue;
            const float w = float(((k & 1) ? fx : 1.0 - fx) * ((k >> 1) ? fy : 1.0 - fy));
            r.taps[i][k] = int32_t(t);
            r.weights[i][k] = w;
            sum += w;
        }
        if (sum > 1e-6f) {
            for (float& w : r.weights[i]) w /= sum;
        } else {  // only the nearest pixel is on the plane
            r.taps[i] = {int32_t(j), -1, -1, -1};
            r.weights[i] = {1.0f, 0.0f, 0.0f, 0.0f};
        }
    }
    return r;
}

double flicker(const std::vector<float>& now, const std::vector<float>& before, const Reprojection& r) {
    double sum = 0.0;
    size_t n = 0;
    for (size_t i = 0; i < r.nearest.size(); ++i) {
        if (r.nearest[i] < 0) continue;
        double previous = 0.0;
        for (int k = 0; k < 4; ++k)
            if (r.taps[i][k] >= 0) previous += r.weights[i][k] * before[size_t(r.taps[i][k])];
        sum += std::abs(double(now[i]) - previous), ++n;
    }
    return n ? sum / double(n) : 0.0;
}

double colorFlicker(const AoFrame& now, const AoFrame& before, const Reprojection& r) {
    if (now.display[0].empty() || before.display[0].empty()) return 0.0;  // no colour read back
    double sum = 0.0;
    for (int c = 0; c < 3; ++c) sum += flicker(now.display[c], before.display[c], r);
    return sum / 3.0;
}

std::vector<uint16_t> disocclusionAge(const Reprojection& r, const std::vector<uint16_t>& previous, size_t pixels) {
    std::vector<uint16_t> age(pixels, 0);
    for (size_t i = 0; i < pixels; ++i)
        if (r.nearest[i] >= 0)
            age[i] = uint16_t(std::min<int>(previous[size_t(r.nearest[i])] + 1, std::numeric_limits<uint16_t>::max()));
    return age;
}

}  // namespace grotto
