#include "voxel/ply_export.h"

#include "common/atomic_file.h"
#include "grotto/error.h"


namespace grotto::voxel {

void writePly(const Mesh& mesh, const std::filesystem::path& path) {
    writeAtomically(path, [&](std::ostream& out) {
        const size_t n = mesh.quads.size();
        out << "ply\nformat binary_little_endian 1.0\ncomment grotto voxel quads and triangles, world units\n"
            << "element vertex " << 4 * n << "\nproperty float x\nproperty float y\nproperty float z\n"
            << "element face " << n << "\nproperty list uchar uint vertex_indices\n"
            << "property uchar material\nend_header\n";
        for (const MeshChunk& c : mesh.chunks)
            for (uint32_t i = 0; i < c.quadCount(); ++i)
                for (const glm::ivec3& v : mesh.corners(c, mesh.quads[c.firstQuad + i])) {
                    const glm::dvec3 p = mesh.origin + glm::dvec3(v) * mesh.voxelSize;
                    const float xyz[3] = {float(p.x), float(p.y), float(p.z)};
                    out.write(reinterpret_cast<const char*>(xyz), sizeof xyz);
                }
        for (uint32_t q = 0; q < n; ++q) {
            const MeshQuad& quad = mesh.quads[q];
            const uint8_t count = quad.corners[2] == quad.corners[3] ? 3 : 4;  // a triangle repeats its last corner
            const uint32_t idx[4] = {4 * q, 4 * q + 1, 4 * q + 2, 4 * q + 3};
            const uint8_t material = uint8_t(quad.material());
            out.write(reinterpret_cast<const char*>(&count), 1);
            out.write(reinterpret_cast<const char*>(idx), count * sizeof(uint32_t));
            out.write(reinterpret_cast<const char*>(&material), 1);
        }
    });
}

}  // namespace grotto::voxel
