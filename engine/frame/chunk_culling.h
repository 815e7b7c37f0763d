#pragma once
// Which of a scene's quads a frame draws, decided on the CPU:
//  - a level of detail per chunk from the size its voxels project to on screen
//    (lod_bias), with hysteresis so a chunk near a threshold does not flip level
//    from frame to frame, and only where the coarser level has fewer quads;
//  - frustum culling of chunks and of their clusters (QuadCluster), and of faces
//    seen only from behind;
//  - two-phase occlusion culling: the clusters visible last frame are drawn first,
//    their depth is reduced to tiles (HizPass), then every other cluster in view is
//    tested against the tiles and drawn unless hidden behind them. The tiles hold
//    part of the frame's final geometry, never more, so the test cannot hide a
//    cluster the frame shows.
#include "engine/camera.h"
#include "engine/passes/hiz_pass.h"
#include "engine/scene/scene.h"
#include "voxel/world_desc.h"

#include <array>
#include <map>
#include <vector>

namespace grotto {

struct CullingOptions {
    // The largest size, in pixels, a coarse cell (2, 4 or 8 voxels) may project to;
    // 0 = the exact voxels everywhere.
    double lodBias = 0.0;
    bool occlusion = true;
};

// A world file's detail block as culling options.
inline CullingOptions cullingOptions(const voxel::Detail& d) { return {.lodBias = d.lodBias, .occlusion = d.occlusionCulling}; }

// A run of quads of one chunk (its index in GpuScene::chunks): one draw.
struct QuadDraw {
    uint32_t chunk = 0, first = 0, count = 0;
};

struct CullingStats {
    uint64_t quadsEarly = 0, quadsLate = 0;          // drawn in each phase
    uint32_t clustersInView = 0, clustersHidden = 0;  // after frustum and face culling; of those, occluded
    std::array<uint32_t, 4> chunksAtLevel{};          // drawn chunks per level of detail
};

// The level a chunk of voxels `voxelPixels` across on screen is drawn at, given
// the level it had (-1: none) and the levels it has; `bias` as CullingOptions::lodBias.
// A chunk goes coarser only once the coarser cell is a quarter below the bias,
// and finer as soon as its cell exceeds it.
int chooseLevel(double voxelPixels, double bias, int previous, int levels);
// The nearest view-axis distance of a camera-relative box, at least the near plane.
double nearestDepth(const Camera& camera, glm::vec3 lo, glm::vec3 hi);

// True when every depth tile the box (camera-relative world units) covers holds
// geometry nearer than the box's nearest point. Boxes reaching the near plane
// are never hidden.
bool hiddenBehind(const DepthTiles& tiles, const glm::dmat4& viewProj, glm::vec3 lo, glm::vec3 hi);

class ChunkCulling {
public:
    // Starts a frame: levels, frustum and face culling. Returns the first phase's
    // draws (every draw when occlusion culling is off), nearest chunks first.
    const std::vector<QuadDraw>& begin(const GpuScene& scene, const Camera& camera, const CullingOptions& options);
    // The second phase: the clusters in view not drawn yet and not hidden behind
    // the first phase's depth tiles. Also records, for the next frame, which
    // clusters were visible.
    const std::vector<QuadDraw>& late(const DepthTiles& tiles);
    // Forgets last frame's visibility and levels (a camera cut, a new scene).
    void reset() { state_.clear(); }
    const CullingStats& stats() const { return stats_; }

private:
    struct Less {
        bool operator()(const glm::ivec3& a, const glm::ivec3& b) const {
            return a.x != b.x ? a.x < b.x : a.y != b.y ? a.y < b.y : a.z < b.z;
        }
    };
    struct ChunkState {
        int level = -1;
        std::vector<uint8_t> visible;  // per cluster of that level, last frame
    };
    struct Candidate {
        ChunkState* state;  // map nodes stay put
        uint32_t chunk, cluster;
        glm::vec3 lo, hi;  // camera-relative bounds
        bool early;
    };
    static void append(std::vector<QuadDraw>& draws, uint32_t chunk, const QuadCluster& c);

    std::map<glm::ivec3, ChunkState, Less> state_;
    std::vector<Candidate> candidates_;
    std::vector<QuadDraw> early_, late_;
    const GpuScene* scene_ = nullptr;
    glm::dmat4 viewProj_{1.0};
    CullingStats stats_;
};

}  // namespace grotto
