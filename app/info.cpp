// grotto info WORLD: what a world holds and what it costs, without a GPU. Names
// from the file are printed escaped (common/printable.h).
#include "app/commands.h"
#include "common/plural.h"
#include "common/printable.h"
#include "engine/scene/scene.h"
#include "voxel/emitters.h"
#include "voxel/face_bake.h"
#include "voxel/face_cache_layout.h"
#include "voxel/live_mesh.h"
#include "voxel/object_worlds.h"
#include "voxel/world.h"

#include <algorithm>
#include <cstdio>

namespace grotto::app {
namespace {

// "generator box 1x10x6, material 4", "generator caves (seed 1, size 64)" or "grid FILE (name N, rule R)".
std::string objectSource(const voxel::ObjectDesc& o) {
    char line[160];
    if (o.generator == "box")
        std::snprintf(line, sizeof line, "generator box %dx%dx%d, material %d", o.boxSize.x, o.boxSize.y, o.boxSize.z, o.material);
    else if (!o.generator.empty())
        std::snprintf(line, sizeof line, "generator %s (seed %u, size %d)", o.generator.c_str(), o.generatorOptions.seed,
                      o.generatorOptions.size);
    else
        return "grid " + o.gridFile.string() + " (" + (o.gridName.empty() ? "" : "name " + o.gridName + ", ") + "rule " +
               voxel::solidRuleName(o.rule) + ")";
    return line;
}

// "moves: 2 keys over 0 to 1.4 s" or "still at (x y z)".
std::string objectMotion(const voxel::ObjectDesc& o) {
    char line[160];
    if (o.moves())
        std::snprintf(line, sizeof line, "moves: %zu keys from %g to %g s", o.keys.size(), o.keys.front().time,
                      o.keys.back().time);
    else
        std::snprintf(line, sizeof line, "still at (%g %g %g)", o.keys.front().position.x, o.keys.front().position.y,
                      o.keys.front().position.z);
    return line;
}

// The glowing materials as lights, and all of them together (docs/lighting.md, "Units").
void printEmitters(const std::vector<voxel::Emitter>& emitters) {
    if (emitters.empty()) {
        std::printf("emitters       none (no material that glows shows a face)\n");
        return;
    }
    glm::dvec3 total(0.0);
    for (const voxel::Emitter& e : emitters) {
        const glm::dvec3 p = e.power();
        total += p;
        std::printf("emitter        material %d: radiance (%g %g %g) over %g square units, power (%g %g %g)\n",
                    e.material, e.radiance.r, e.radiance.g, e.radiance.b, e.area, p.r, p.g, p.b);
    }
    std::printf("emitters       %zu materials, total power (%g %g %g)\n", emitters.size(), total.r, total.g, total.b);
}

}  // namespace

void addInfoCommand(CLI::App& app) {
    auto world = std::make_shared<std::string>();
    CLI::App* cmd = app.add_subcommand("info", "Print a world's voxels, bricks, quads, memory, bounds, cameras, paths, objects and materials");
    cmd->add_option("world", *world, "World .json or .vdb")->required();
    cmd->callback([world] {
        const voxel::World w = voxel::World::load(*world);
        const voxel::WorldStats s = w.stats();
        // As a renderer uploads it: every chunk with its coarser levels of detail.
        const std::vector<voxel::MeshChunkQuads> chunks =
            voxel::LiveMesh(w, {.coarseLevels = voxel::kMaxCoarseLevels}).list();
        size_t quads = 0, coarse = 0;
        for (const voxel::MeshChunkQuads& c : chunks) {
            quads += c.quads.size();
            for (const voxel::MeshLevel& l : c.coarser) coarse += l.quads.size();
        }
        const voxel::IndexBox b = w.bounds();
        const size_t gpu = sceneBufferBytes(chunks);
        const size_t host = s.hostBytes + chunks.size() * sizeof(GpuChunk);
        const glm::dvec3 lo = w.origin() + glm::dvec3(b.min) * w.voxelSize();
        const glm::dvec3 hi = w.origin() + glm::dvec3(b.max + 1) * w.voxelSize();
        std::printf("world          %s\n", printable(w.desc().source.string()).c_str());
        std::printf("grid           %s (rule %s)\n", printable(w.desc().gridFile.string()).c_str(), voxel::solidRuleName(w.desc().rule));
        std::printf("voxel size     %g\n", w.voxelSize());
        std::printf("active voxels  %llu\n", (unsigned long long)s.solidVoxels);
        std::printf("bricks         %llu\n", (unsigned long long)s.bricks);
        std::printf("chunks         %zu\n", chunks.size());
        std::printf("quads          %zu (coarser levels of detail: %zu more)\n", quads, coarse);
        std::printf("host bytes     %zu (grid as loaded: %zu)\n", host, s.sourceGridBytes);
        std::printf("gpu bytes      %zu\n", gpu);
        if (s.workBytesEstimate)  // .vox worlds (voxel/work_memory.h): what this command takes beyond itself
            std::printf("memory         an estimated %.1f MiB to load and mesh (budget %zu MiB)\n",
                        double(s.workBytesEstimate) / (1 << 20), w.desc().memoryBudgetBytes >> 20);
        {  // what a bake at the default k adds (--ao cache, docs/face-cache.md)
            const voxel::ExposedFaceCount faces = voxel::countExposedFaces(w);
            const size_t bytes = voxel::faceCacheGpuBytes(faces, voxel::kDefaultBakeTexels);
            // A bake for the day's sun (lighting.sun.from day, a path's day track): a word a texel more.
            const size_t day = voxel::faceCacheGpuBytes(faces, voxel::kDefaultBakeTexels, true) - bytes;
            // With full light, its light over the day: sky weights a texel, day words a face.
            const size_t dayLight = voxel::faceCacheGpuBytes(faces, voxel::kDefaultBakeTexels, true, true) - bytes - day;
            const double perFace = faces.faces ? 1.0 / double(faces.faces) : 0.0;
            std::printf("face cache     %llu exposed faces; baked at %u x %u texels, %zu bytes on the GPU (%.1f a face); "
                        "for the day's sun %zu more (%.1f a face), with full light over the day %zu more (%.1f a face)\n",
                        (unsigned long long)faces.faces, voxel::kDefaultBakeTexels, voxel::kDefaultBakeTexels, bytes,
                        double(bytes) * perFace, day, double(day) * perFace, dayLight, double(dayLight) * perFace);
            // The atlas the composite reads it through, beside it (engine/scene/face_atlas.h).
            const size_t atlas = faceAtlasBufferBytes(chunks, voxel::kDefaultBakeTexels);
            std::printf("face atlas     %zu bytes on the GPU beside it (%.1f a face)\n", atlas, double(atlas) * perFace);
        }
        if (b.empty())
            std::printf("bounds         empty\n");
        else
            std::printf("bounds         index [%d %d %d]..[%d %d %d], world (%g %g %g)..(%g %g %g)\n", b.min.x,
                        b.min.y, b.min.z, b.max.x, b.max.y, b.max.z, lo.x, lo.y, lo.z, hi.x, hi.y, hi.z);
        // What --camera and --path accept, and what each material id draws as.
        const voxel::WorldDesc& d = w.desc();
        if (d.cameras.empty()) std::printf("cameras        none (the default view frames the bounds)\n");
        for (const auto& [name, c] : d.cameras)
            std::printf("camera         %s%s: position (%g %g %g), target (%g %g %g), fov %g\n", printable(name).c_str(),
                        name == d.defaultCamera ? " (default)" : "", c.position.x, c.position.y, c.position.z,
                        c.target.x, c.target.y, c.target.z, c.fovDegrees);
        if (d.paths.empty()) std::printf("paths          none\n");
        for (const auto& [name, p] : d.paths) {
            const size_t cuts = size_t(std::count_if(p.keys.begin(), p.keys.end(), [](const voxel::PathKey& k) { return k.cut; }));
            std::printf("path           %s: %zu keys over %g s, %zu shot%s", printable(name).c_str(), p.keys.size(),
                        p.keys.empty() ? 0.0 : p.keys.back().time, cuts + 1, cuts ? "s" : "");
            if (!p.day.empty()) std::printf(", a day from %g to %g h", p.day.front().hours, p.day.back().hours);
            std::printf("\n");
        }
        // Each object as loaded (or generated): where its voxels come from, how many, and how it moves.
        const std::vector<voxel::World> objects = voxel::loadObjectWorlds(d);
        if (objects.empty()) std::printf("objects        none\n");
        for (size_t i = 0; i < objects.size(); ++i) {
            const voxel::ObjectDesc& o = d.objects[i];
            const voxel::IndexBox ob = objects[i].bounds();
            const glm::dvec3 olo = objects[i].origin() + glm::dvec3(ob.min) * objects[i].voxelSize();
            const glm::dvec3 ohi = objects[i].origin() + glm::dvec3(ob.max + 1) * objects[i].voxelSize();
            // Its quads as a renderer uploads them: the exact voxels (objects have no coarser levels).
            std::printf("object         %s: %s, %llu voxels, %zu quads, own bounds (%g %g %g)..(%g %g %g), %s\n",
                        printable(o.name).c_str(), printable(objectSource(o)).c_str(),
                        (unsigned long long)objects[i].stats().solidVoxels, objects[i].mesh().quads.size(), olo.x,
                        olo.y, olo.z, ohi.x, ohi.y, ohi.z, objectMotion(o).c_str());
        }
        // The materials drawn, by the world and its objects; the rest of the palette
        // (most of a .vox model's colours are never placed) only counted.
        std::vector<uint64_t> drawn = w.voxelsByMaterial();
        for (const voxel::World& o : objects) {
            const std::vector<uint64_t> own = o.voxelsByMaterial();
            drawn.resize(std::max(drawn.size(), own.size()), 0);
            for (size_t id = 0; id < own.size(); ++id) drawn[id] += own[id];
        }
        size_t unused = 0;
        for (size_t i = 0; i < d.materials.size(); ++i) {
            const voxel::Material& m = d.materials[i];
            const uint64_t voxels = i + 1 < drawn.size() ? drawn[i + 1] : 0;
            if (voxels == 0) {
                ++unused;
                continue;
            }
            char glow[96] = "";
            if (m.emits())
                std::snprintf(glow, sizeof glow, ", emits (%g %g %g) x %g", m.emissionColor.r, m.emissionColor.g,
                              m.emissionColor.b, m.emissionIntensity);
            std::printf("material %-5zu %s: albedo (%g %g %g)%s, %s\n", i + 1, printable(m.name).c_str(), m.albedo.r,
                        m.albedo.g, m.albedo.b, glow, counted(voxels, "voxel").c_str());
        }
        if (unused)
            std::printf("materials      %zu used; the palette holds %zu more that no voxel uses (not listed)\n",
                        d.materials.size() - unused, unused);
        printEmitters(voxel::emitters(w, objects));
    });
}

}  // namespace grotto::app
