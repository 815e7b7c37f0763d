// Times edits on a copy of the world, each followed by the updates a live
// renderer makes: the touched chunks' meshes and the brick table.
#include "app/bench_edits.h"

#include "voxel/luminance.h"

#include "app/options.h"
#include "common/elapsed.h"
#include "engine/lab/ao_metrics.h"
#include "engine/lab/reference_view.h"
#include "voxel/brick_table.h"
#include "voxel/daylight.h"
#include "voxel/face_cache_layout.h"
#include "voxel/live_mesh.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <random>

namespace grotto::app {
namespace {

using Clock = std::chrono::steady_clock;

// The world with the mesh and table a renderer keeps beside it.
struct LiveWorld {
    voxel::World world;
    voxel::LiveMesh mesh{world};
    voxel::BrickTable table{world};

    // Milliseconds for the edit and both updates.
    double timedEdit(const voxel::Edit& e, voxel::EditResult* result = nullptr) {
        const auto t = Clock::now();
        const voxel::EditResult r = world.apply(e);
        mesh.update(world, r.voxels);
        table.update(world, r.voxels);
        const double ms = msSince(t);
        if (result) *result = r;
        return ms;
    }
    void undo() {
        const voxel::EditResult r = world.undo();
        mesh.update(world, r.voxels);
        table.update(world, r.voxels);
    }
};

// The middle voxel of the chunk with the most quads: an edit where the surface is.
glm::ivec3 busiestChunkMiddle(const voxel::World& world) {
    const voxel::Mesh mesh = world.mesh();
    const auto most = std::max_element(mesh.chunks.begin(), mesh.chunks.end(),
                                       [](const auto& a, const auto& b) { return a.quadCount() < b.quadCount(); });
    return (most == mesh.chunks.end() ? glm::ivec3(0) : most->origin) + int(GROTTO_CHUNK_SIZE / 2);
}

}  // namespace

EditBenchFigures benchEdits(const voxel::World& source, const EditBenchOptions& o) {
    EditBenchFigures f;
    LiveWorld live{source};
    f.voxel = busiestChunkMiddle(source);
    const glm::dvec3 centre = source.origin() + (glm::dvec3(f.voxel) + 0.5) * source.voxelSize();

    std::vector<double> ms;
    for (int i = 0; i < o.repetitions; ++i)
        ms.push_back(live.timedEdit(voxel::Edit::setVoxel(f.voxel, live.world.solid(f.voxel) ? 0 : 1)));
    f.voxelEditMs = median(ms);

    ms.clear();
    for (int i = 0; i < o.repetitions; ++i) {
        voxel::EditResult r;
        ms.push_back(live.timedEdit(voxel::Edit::carveSphere(centre, 8.0 * source.voxelSize()), &r));
        f.sphereVoxels = r.changed;
        live.undo();  // untimed: every repetition carves the same voxels
    }
    f.sphereCarveMs = median(ms);

    // The same carve with the face cache kept up to date (its texels' values do
    // not change the cost: unbaked ones will do).
    const voxel::Lighting light = voxel::lightingInEffect(source.desc().lighting);
    const voxel::FaceBakeSettings bake{.radius = kDefaultRadiusVoxels * source.voxelSize(),
                                       .sunDirection = glm::dvec3(light.sunDirection),
                                       .sunAngleDegrees = double(light.sunAngle)};
    const std::vector<voxel::ExposedFace> faces = voxel::exposedFaces(live.table, live.world);
    ms.clear();
    for (int i = 0; i < 3; ++i) {
        std::vector<voxel::ExposedFace> now = faces;
        std::vector<voxel::FaceTexel> texels(now.size() * bake.texelsPerSide * bake.texelsPerSide);
        const auto t = Clock::now();
        voxel::EditResult r;
        live.timedEdit(voxel::Edit::carveSphere(centre, 8.0 * source.voxelSize()), &r);
        voxel::updateAfterEdit(live.table, live.world, r.voxels, bake, now, texels, &f.cacheEdit);
        const voxel::FaceCacheArrays arrays = voxel::layFaceCache(now, texels, bake.texelsPerSide);
        ms.push_back(msSince(t));
        live.undo();
    }
    f.cacheEditMs = median(ms);
    ms.clear();
    for (int i = 0; i < 3; ++i) {
        std::vector<voxel::ExposedFace> now = faces;
        std::vector<voxel::FaceTexel> texels(now.size() * bake.texelsPerSide * bake.texelsPerSide);
        std::vector<voxel::FaceReach> reach;
        const auto t = Clock::now();
        voxel::EditResult r;
        live.timedEdit(voxel::Edit::carveSphere(centre, 8.0 * source.voxelSize()), &r);
        voxel::updateAfterEdit(live.table, live.world, r.voxels, bake, now, texels, nullptr, false, &reach);
        const voxel::FaceCacheArrays arrays = voxel::layFaceCache(now, texels, bake.texelsPerSide);
        ms.push_back(msSince(t));
        live.undo();
    }
    f.cacheEditDeferredMs = median(ms);

    // Random single voxels within the bounds, each toggled (so none is a no-op).
    const voxel::IndexBox b = source.bounds();
    std::mt19937 rng(o.seed);
    auto randomEdit = [&] {
        glm::ivec3 v;
        for (int a = 0; a < 3; ++a) v[a] = std::uniform_int_distribution<int>(b.min[a], b.max[a])(rng);
        return voxel::Edit::setVoxel(v, live.world.solid(v) ? 0 : 1);
    };
    ms.clear();
    for (int i = 0; i < o.randomEdits; ++i) ms.push_back(live.timedEdit(randomEdit()));
    f.randomEdits = o.randomEdits;
    f.randomEditMs = median(ms);

    ms.clear();
    for (int i = 0; i < o.fullRemeshEdits; ++i) {
        const voxel::Edit e = randomEdit();
        const auto t = Clock::now();
        live.world.apply(e);
        const voxel::Mesh whole = live.world.mesh();
        ms.push_back(msSince(t));
    }
    f.fullRemeshEdits = o.fullRemeshEdits;
    f.fullRemeshMs = median(ms);
    f.remeshRatio = f.randomEditMs > 0 ? f.fullRemeshMs / f.randomEditMs : 0;
    return f;
}

std::optional<CacheCarveFigures> timeCacheCarve(vk::Context& ctx, RenderSession& session, const Camera& camera,
                                                int frameIndex, uint32_t referenceSpp, double radius) {
    const voxel::World& world = session.world();
    const glm::dvec3 forward = -camera.basis[2];
    const std::optional<voxel::RayHit> hit = world.raycast(camera.position, forward, 1e9);
    if (!hit) return std::nullopt;
    const glm::dvec3 centre = camera.position + forward * hit->distance;
    CacheCarveFigures f;
    f.referenceSpp = referenceSpp;
    const auto t = Clock::now();
    session.apply(voxel::Edit::carveSphere(centre, 8.0 * world.voxelSize()));
    f.editMs = msSince(t);
    Renderer& renderer = session.renderer();
    double ms = f.editMs;  // the frames' own time: the read-backs are left out
    std::vector<std::vector<float>> shown;
    bool converged = false;
    do {
        const auto frame = Clock::now();
        renderer.render(camera, uint32_t(frameIndex++));
        ++f.frames;
        converged = session.faceCacheConverged();  // waits for the frame
        ms += msSince(frame);
        if (referenceSpp == 0) continue;
        f.converging.push_back({.ms = ms});
        shown.push_back(renderer.readback(camera, true).ao);
    } while (!converged && f.frames < 1000);
    f.ms = referenceSpp == 0 ? msSince(t) : ms;
    if (referenceSpp == 0) return f;
    const ReferenceView ref = referenceView(world, camera, radius, referenceSpp, &ctx, session.posedObjects());
    for (size_t i = 0; i < shown.size(); ++i) f.converging[i].psnr = aoError(shown[i], ref.ao, ref.surface).psnr;
    const double last = f.converging.back().psnr;
    while (f.converging[f.within2dB].psnr < last - 2.0) ++f.within2dB;
    return f;
}

std::optional<CacheCarveFigures> timeLampPlaced(RenderSession& session, const Camera& camera, int frameIndex) {
    const voxel::World& world = session.world();
    const std::vector<voxel::Material>& materials = world.desc().materials;
    int lamp = 0;  // the brightest glowing material
    for (size_t m = 0; m < materials.size(); ++m)
        if (voxel::luminance(glm::dvec3(materials[m].emission())) > 0.0 &&
            (lamp == 0 || voxel::luminance(glm::dvec3(materials[m].emission())) >
                              voxel::luminance(glm::dvec3(materials[size_t(lamp) - 1].emission()))))
            lamp = int(m) + 1;
    const glm::dvec3 forward = -camera.basis[2];
    const std::optional<voxel::RayHit> hit = world.raycast(camera.position, forward, 1e9);
    if (lamp == 0 || !hit) return std::nullopt;
    // The open voxel in front of the face the ray met.
    glm::ivec3 at = hit->voxel;
    at[hit->face / 2] += hit->face % 2 == 0 ? 1 : -1;
    CacheCarveFigures f;
    const auto t = Clock::now();
    session.apply(voxel::Edit::setVoxel(at, uint8_t(lamp)));
    f.editMs = msSince(t);
    Renderer& renderer = session.renderer();
    do {
        renderer.render(camera, uint32_t(frameIndex++));
        ++f.frames;
    } while (!session.faceCacheConverged() && f.frames < 1000);
    f.ms = msSince(t);
    return f;
}

void printEditFigures(const EditBenchFigures& f) {
    std::printf("  edits (CPU: apply + LiveMesh::update + BrickTable::update, medians):\n");
    std::printf("    voxel set    %8.3f ms at (%d, %d, %d)\n", f.voxelEditMs, f.voxel.x, f.voxel.y, f.voxel.z);
    std::printf("    sphere carve %8.3f ms, radius 8 voxels there, %llu voxels changed\n", f.sphereCarveMs,
                (unsigned long long)f.sphereVoxels);
    std::printf("    face cache   %8.3f ms after that carve: %llu faces traced again, %llu carried (%llu with sky "
                "light left for later)\n",
                f.cacheEditMs, (unsigned long long)f.cacheEdit.traced, (unsigned long long)f.cacheEdit.carried,
                (unsigned long long)f.cacheEdit.skyFar);
    std::printf("    face cache   %8.3f ms with those faces left to the GPU's tracer (a live session's way)\n",
                f.cacheEditDeferredMs);
    std::printf("    random voxel %8.3f ms each over %d edits; re-meshing the whole world instead: %.3f ms each "
                "(%d edits), %.0fx\n",
                f.randomEditMs, f.randomEdits, f.fullRemeshMs, f.fullRemeshEdits, f.remeshRatio);
}

nlohmann::json editFiguresJson(const EditBenchFigures& f) {
    return {{"voxel", {f.voxel.x, f.voxel.y, f.voxel.z}},
            {"voxel_edit_ms_median", f.voxelEditMs},
            {"sphere_carve_ms_median", f.sphereCarveMs},
            {"sphere_carve_voxels", f.sphereVoxels},
            {"face_cache_edit_ms", f.cacheEditMs},
            {"face_cache_faces_traced", f.cacheEdit.traced},
            {"face_cache_edit_deferred_ms", f.cacheEditDeferredMs},
            {"random_edits", f.randomEdits},
            {"random_edit_ms_median", f.randomEditMs},
            {"full_remesh_edits", f.fullRemeshEdits},
            {"full_remesh_edit_ms_median", f.fullRemeshMs},
            {"full_remesh_to_incremental_ratio", f.remeshRatio}};
}

}  // namespace grotto::app
