#include "voxel/emitters.h"

#include <glm/geometric.hpp>

#include <map>

namespace grotto::voxel {
namespace {

// Adds each quad's area (world units squared) to its material's sum.
void addFaceAreas(const World& world, std::map<int, double>& area) {
    const Mesh& mesh = world.mesh();
    const double unit = world.voxelSize() * world.voxelSize();
    for (const MeshChunk& chunk : mesh.chunks)
        for (uint32_t q = chunk.firstQuad; q < chunk.firstQuad + chunk.quadCount(); ++q) {
            const MeshQuad& quad = mesh.quads[q];
            // A convex quadrilateral's area is half its diagonals' cross product
            // (a triangle repeats its third corner, and the formula still holds).
            const glm::dvec3 d0 = glm::dvec3(quad.corner(2) - quad.corner(0)), d1 = glm::dvec3(quad.corner(3) - quad.corner(1));
            area[int(quad.material())] += 0.5 * glm::length(glm::cross(d0, d1)) * unit;
        }
}

}  // namespace

std::vector<Emitter> emitters(const World& world, std::span<const World> objects) {
    const std::vector<Material>& palette = world.desc().materials;
    bool any = false;
    for (const Material& m : palette) any = any || m.emits();
    if (!any) return {};
    std::map<int, double> area;
    addFaceAreas(world, area);
    for (const World& o : objects) addFaceAreas(o, area);
    std::vector<Emitter> out;
    for (const auto& [id, a] : area) {
        if (id < 1 || size_t(id) > palette.size() || !palette[size_t(id) - 1].emits()) continue;
        out.push_back({id, glm::dvec3(palette[size_t(id) - 1].emission()), a});
    }
    return out;
}

}  // namespace grotto::voxel
