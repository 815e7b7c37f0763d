// grotto info WORLD: what a world holds and what it costs, without a GPU.
#include "app/commands.h"
#include "engine/scene.h"
#include "voxel/world.h"

#include <cstdio>

namespace grotto::app {

void addInfoCommand(CLI::App& app) {
    auto world = std::make_shared<std::string>();
    CLI::App* cmd = app.add_subcommand("info", "Print a world's voxels, bricks, quads, memory and bounds");
    cmd->add_option("world", *world, "World .json or .vdb")->required();
    cmd->callback([world] {
        const voxel::World w = voxel::World::load(*world);
        const voxel::WorldStats s = w.stats();
        const voxel::Mesh mesh = w.mesh();
        const voxel::IndexBox b = w.bounds();
        const size_t gpu = sceneBufferBytes(mesh);
        const size_t host = s.hostBytes + mesh.chunks.size() * sizeof(GpuChunk);
        const glm::dvec3 lo = w.origin() + glm::dvec3(b.min) * w.voxelSize();
        const glm::dvec3 hi = w.origin() + glm::dvec3(b.max + 1) * w.voxelSize();
        std::printf("world          %s\n", w.desc().source.c_str());
        std::printf("grid           %s (rule %s)\n", w.desc().gridFile.c_str(), voxel::solidRuleName(w.desc().rule));
        std::printf("voxel size     %g\n", w.voxelSize());
        std::printf("active voxels  %llu\n", (unsigned long long)s.solidVoxels);
        std::printf("bricks         %llu\n", (unsigned long long)s.bricks);
        std::printf("chunks         %zu\n", mesh.chunks.size());
        std::printf("quads          %zu\n", mesh.quads.size());
        std::printf("host bytes     %zu (grid as loaded: %zu)\n", host, s.sourceGridBytes);
        std::printf("gpu bytes      %zu\n", gpu);
        if (b.empty())
            std::printf("bounds         empty\n");
        else
            std::printf("bounds         index [%d %d %d]..[%d %d %d], world (%g %g %g)..(%g %g %g)\n", b.min.x,
                        b.min.y, b.min.z, b.max.x, b.max.y, b.max.z, lo.x, lo.y, lo.z, hi.x, hi.y, hi.z);
    });
}

}  // namespace grotto::app
