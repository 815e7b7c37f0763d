#include "engine/frame/chunk_culling.h"

#include "engine/frame/frustum.h"

#include <algorithm>
#include <cmath>

namespace grotto {

namespace {

constexpr double kCoarserMargin = 1.25;  // hysteresis: a coarser cell must be this far below the bias

}  // namespace

double nearestDepth(const Camera& camera, glm::vec3 lo, glm::vec3 hi) {
    const glm::dvec3 forward = -camera.basis[2];
    double d = 0.0;
    for (int k = 0; k < 3; ++k) d += forward[k] * (forward[k] >= 0.0 ? lo[k] : hi[k]);
    return std::max(d, camera.nearPlane);
}

int chooseLevel(double voxelPixels, double bias, int previous, int levels) {
    if (bias <= 0.0 || levels <= 1) return 0;
    auto cell = [&](int level) { return std::ldexp(voxelPixels, level); };
    int level = previous < 0 ? 0 : std::min(previous, levels - 1);
    const double coarser = previous < 0 ? bias : bias / kCoarserMargin;
    while (level + 1 < levels && cell(level + 1) <= coarser) ++level;
    while (level > 0 && cell(level) > bias) --level;
    return level;
}

bool hiddenBehind(const DepthTiles& tiles, const glm::dmat4& viewProj, glm::vec3 lo, glm::vec3 hi) {
    if (tiles.farthest.empty()) return false;
    glm::dvec2 pmin(1e30), pmax(-1e30);
    double nearest = 0.0;  // reverse-Z: the largest depth
    for (int k = 0; k < 8; ++k) {
        const glm::dvec4 clip = viewProj * glm::dvec4(k & 1 ? hi.x : lo.x, k & 2 ? hi.y : lo.y, k & 4 ? hi.z : lo.z, 1.0);
        if (clip.w <= 1e-9) return false;  // behind the camera: reaches the near plane
        const glm::dvec3 ndc = glm::dvec3(clip) / clip.w;
        if (ndc.z >= 1.0) return false;    // in front of the near plane
        const glm::dvec2 pixel((ndc.x + 1.0) * 0.5 * tiles.width, (ndc.y + 1.0) * 0.5 * tiles.height);
        pmin = glm::min(pmin, pixel);
        pmax = glm::max(pmax, pixel);
        nearest = std::max(nearest, ndc.z);
    }
    // A pixel's margin against rounding; tiles clamped to the image.
    const int x0 = std::max(0, int(std::floor(pmin.x - 1.0)) / int(kHizTile));
    const int y0 = std::max(0, int(std::floor(pmin.y - 1.0)) / int(kHizTile));
    const int x1 = std::min(int(tiles.tilesX) - 1, int(std::floor(pmax.x + 1.0)) / int(kHizTile));
    const int y1 = std::min(int(tiles.tilesY) - 1, int(std::floor(pmax.y + 1.0)) / int(kHizTile));
    if (pmax.x < -1.0 || pmax.y < -1.0 || x0 > x1 || y0 > y1) return false;  // off screen: the frustum's call
    // The GPU's depths carry float rounding: a margin of 1e-5 relative.
    const float threshold = float(nearest * (1.0 + 1e-5));
    for (int y = y0; y <= y1; ++y)
        for (int x = x0; x <= x1; ++x)
            if (!(tiles.farthest[size_t(y) * tiles.tilesX + x] > threshold)) return false;
    return true;
}

void ChunkCulling::append(std::vector<QuadDraw>& draws, uint32_t chunk, const QuadCluster& c) {
    if (!draws.empty() && draws.back().chunk == chunk && draws.back().first + draws.back().count == c.first)
        draws.back().count += c.count;  // next in the buffer: one draw
    else
        draws.push_back({chunk, c.first, c.count});
}

const std::vector<QuadDraw>& ChunkCulling::begin(const GpuScene& scene, const Camera& camera,
                                                 const CullingOptions& options) {
    scene_ = &scene;
    viewProj_ = camera.viewProjRelativeDouble();
    candidates_.clear();
    early_.clear();
    late_.clear();
    stats_ = {};
    const Frustum frustum(camera);
    // The pixels one world unit spans at unit view distance.
    const double focalPixels = double(camera.height) / (2.0 * std::tan(0.5 * camera.fovY));

    struct Visible { uint32_t index; glm::vec3 offset; float distance; };
    std::vector<Visible> visible;
    for (uint32_t i = 0; i < scene.chunks.size(); ++i) {
        const GpuChunk& c = scene.chunks[i];
        const glm::vec3 offset(c.origin - camera.position);
        if (frustum.outside(offset + c.lo, offset + c.hi)) continue;
        const glm::vec3 centre = offset + 0.5f * (c.lo + c.hi);
        visible.push_back({i, offset, glm::dot(centre, centre)});
    }
    // Nearest first, so early depth tests reject more.
    std::sort(visible.begin(), visible.end(), [](const Visible& a, const Visible& b) { return a.distance < b.distance; });

    const float voxel = float(scene.voxelSize);
    for (const Visible& v : visible) {
        const GpuChunk& c = scene.chunks[v.index];
        ChunkState& state = state_[c.index];
        const double voxelPixels = scene.voxelSize * focalPixels / nearestDepth(camera, v.offset + c.lo, v.offset + c.hi);
        int level = chooseLevel(voxelPixels, options.lodBias, state.level, int(c.levels.size()));
        // Grown cells may make more faces than the voxels (thin, ragged shapes): a
        // coarser level is drawn only where it saves quads.
        while (level > 0 && c.levels[size_t(level)].quads() >= c.levels[size_t(level) - 1].quads()) --level;
        const GpuLevel& l = c.levels[size_t(level)];
        if (level != state.level || state.visible.size() != l.clusters.size()) {
            state.level = level;
            state.visible.assign(l.clusters.size(), 0);  // unknown: tested in the second phase
        }
        ++stats_.chunksAtLevel[size_t(std::min(level, 3))];
        for (uint32_t f = 0; f < 6; ++f) {
            const uint32_t axis = gpu::faceAxis(f);
            for (uint32_t k = l.faceClusters[f]; k < l.faceClusters[f + 1]; ++k) {
                const QuadCluster& q = l.clusters[k];
                const glm::vec3 lo = v.offset + q.lo * voxel, hi = v.offset + q.hi * voxel;
                // A +axis face is seen only from above its plane: skip when the camera
                // (at the origin) is below the lowest one, and likewise for -axis faces.
                if (gpu::facePositive(f) ? lo[axis] >= 0.0f : hi[axis] <= 0.0f) continue;
                if (frustum.outside(lo, hi)) continue;
                const bool early = !options.occlusion || state.visible[k];
                candidates_.push_back({&state, v.index, k, lo, hi, early});
                if (early) {
                    append(early_, v.index, q);
                    stats_.quadsEarly += q.count;
                }
            }
        }
    }
    stats_.clustersInView = uint32_t(candidates_.size());
    return early_;
}

const std::vector<QuadDraw>& ChunkCulling::late(const DepthTiles& tiles) {
    late_.clear();
    for (const Candidate& c : candidates_) {
        const QuadCluster& q = scene_->chunks[c.chunk].levels[size_t(c.state->level)].clusters[c.cluster];
        const bool hidden = hiddenBehind(tiles, viewProj_, c.lo, c.hi);
        c.state->visible[c.cluster] = !hidden;
        stats_.clustersHidden += hidden;
        if (!c.early && !hidden) {
            append(late_, c.chunk, q);
            stats_.quadsLate += q.count;
        }
    }
    return late_;
}

}  // namespace grotto
