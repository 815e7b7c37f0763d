#pragma once
// `grotto bench --edits`: the CPU cost of live edits on a loaded world (the
// edit itself, the chunks it re-meshes, the brick table it updates), against
// re-meshing the whole world after every edit; with --ao cache, how long the GPU
// takes to trace again what a carve in view reached.
#include "engine/session.h"
#include "voxel/face_cache_edit.h"
#include "voxel/world.h"

#include <nlohmann/json_fwd.hpp>

#include <optional>

namespace grotto::app {

struct EditBenchOptions {
    int repetitions = 50;      // of the single-voxel and sphere edits
    int randomEdits = 1000;    // single-voxel edits at random places in the bounds
    int fullRemeshEdits = 20;  // of those, how many also time a whole-world re-mesh
    uint32_t seed = 1;
};

// Medians in milliseconds. Each "edit" is World::apply + LiveMesh::update +
// BrickTable::update, as a renderer keeping both up to date pays it.
struct EditBenchFigures {
    glm::ivec3 voxel{0};           // the voxel edited: the middle of the chunk with most quads
    double voxelEditMs = 0;        // setting that voxel (solid and empty in turn)
    double sphereCarveMs = 0;      // carving a sphere of radius 8 voxels around it
    uint64_t sphereVoxels = 0;     // voxels that carve changed
    // The face cache after that carve (voxel::updateAfterEdit at the default bake
    // settings, then laid out for the GPU), and what it traced and carried.
    double cacheEditMs = 0;
    voxel::CacheEditStats cacheEdit;
    // The same with the faces it reaches left to the GPU's tracer (what a live
    // session does): relisting, carrying over and laying out only.
    double cacheEditDeferredMs = 0;
    int randomEdits = 0;
    double randomEditMs = 0;       // a random single-voxel edit, incremental
    int fullRemeshEdits = 0;
    double fullRemeshMs = 0;       // the same edit followed by World::mesh() instead
    double remeshRatio = 0;        // fullRemeshMs / randomEditMs
};

// Edits a copy: `world` is left as it is.
EditBenchFigures benchEdits(const voxel::World& world, const EditBenchOptions& options = {});

// The figures as lines under `grotto bench`'s report, and as its JSON's "edits".
void printEditFigures(const EditBenchFigures& f);
nlohmann::json editFiguresJson(const EditBenchFigures& f);

// --edits with --ao cache, in the bench's own session: a sphere of radius 8 voxels
// carved where the view's centre ray meets the world, then frames of the camera
// until the GPU's tracer finds no face in view left to trace.
struct CacheCarveFigures {
    double ms = 0;      // from the edit until that frame has finished
    double editMs = 0;  // of it, the edit itself (world, mesh, cache re-listed)
    uint32_t frames = 0;
    // With a reference (timeCacheCarve's referenceSpp): each frame's AO against rays
    // of the carved world, with the time from the edit until that frame finished
    // (the read-backs left out), and the first frame within 2 dB of the last.
    struct Frame {
        double ms = 0, psnr = 0;
    };
    std::vector<Frame> converging;
    uint32_t referenceSpp = 0;
    size_t within2dB = 0;  // index into `converging`
};
// Nothing when the centre ray meets no voxel. `frameIndex`: the next frame's.
// `referenceSpp` > 0: each frame's AO is read back and measured against that
// many rays a pixel of radius `radius` (world units), traced once the frames end.
std::optional<CacheCarveFigures> timeCacheCarve(vk::Context& ctx, RenderSession& session, const Camera& camera,
                                                int frameIndex, uint32_t referenceSpp = 0, double radius = 0);
// A voxel of the world's brightest glowing material placed in front of what the
// centre ray meets: with full light, the edit lights again every face it moved.
// Nothing when the world has no glowing material or the ray meets no voxel.
std::optional<CacheCarveFigures> timeLampPlaced(RenderSession& session, const Camera& camera, int frameIndex);

}  // namespace grotto::app
