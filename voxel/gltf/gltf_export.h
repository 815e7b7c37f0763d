#pragma once
// The world's surface as a glTF 2.0 mesh (.glb or .gltf) with its AO baked in, so
// a prototyper carries Grotto's exact AO into Godot, Unity or Blender.
//
// Each exposed voxel face is a quad of two triangles in world units, Y up as glTF
// has it; one primitive and one material (base colour = the Grotto material's
// albedo; emissiveFactor and, above intensity 1, KHR_materials_emissive_strength
// for a glowing one) per material. Vertices carry NORMAL and COLOR_0: grey = the AO from the
// face cache (voxel/face_cache.h) read at the corner, a linear multiplier of the
// base colour as glTF defines COLOR_0. Corners shared by coplanar faces of one
// material with the same AO are one vertex; every face meets its neighbours
// corner to corner, so nothing cracks. Each quad is split along the diagonal
// whose corners' AO differ less, so the AO gradient follows the corner values.
#include "voxel/face_bake.h"
#include "voxel/world.h"

#include <array>
#include <filesystem>
#include <vector>

namespace grotto::voxel {

// The mesh as written, in world units relative to `offset` (the glTF node's translation).
struct AoMesh {
    struct Primitive {
        int material = 1;
        std::vector<glm::vec3> positions, normals;
        std::vector<uint8_t> ao;          // per vertex, AO x 255 rounded
        std::vector<uint32_t> indices;    // triangles, counter-clockwise seen from outside
    };
    glm::dvec3 offset{0.0};
    std::vector<Primitive> primitives;  // by material id, ascending
    // Every exposed face (exposedFaces' order) and its corners' AO bytes, corner
    // (u, v) = (0,0), (1,0), (1,1), (0,1) along the face's U and V axes.
    std::vector<ExposedFace> faces;
    std::vector<std::array<uint8_t, 4>> cornerAo;
    // The face cache the corners were read from: k x k texels per face.
    std::vector<FaceTexel> texels;
    uint32_t texelsPerSide = 1;
};

// The AO the mesh's two triangles give at (u, v) in [0,1]^2 on a face with these corners.
double interpolateCornerAo(const std::array<uint8_t, 4>& corners, double u, double v);

// Bakes the face cache with `bake` (every core), telling `progress` of each run
// of faces, and builds the mesh.
AoMesh buildAoMesh(const World& world, const FaceBakeSettings& bake, const BakeProgress& progress = {});

// Writes `mesh` as FILE.glb (binary) or FILE.gltf (JSON, buffers embedded),
// atomically. Throws grotto::Error (input) for another extension or an unwritable path.
// Returns the bytes written.
uintmax_t writeGltfMesh(const World& world, const AoMesh& mesh, const std::filesystem::path& out);

// What the vertex colours carry of the AO, as a renderer interpolates them.
struct AoMeshError {
    size_t points = 0;
    double mae = 0.0, rmse = 0.0, bias = 0.0, max = 0.0;
    // The face cache's own reading at the same points (its k x k texels, bilinear):
    // what a lightmap of those texels would carry.
    double cacheMae = 0.0, cacheRmse = 0.0;
};
// Against `reference` rays per point (tracePoints) at `points` random points
// on random exposed faces (seeded): what the vertex colours carry of the AO.
AoMeshError measureAoMesh(const World& world, const AoMesh& mesh, const FaceBakeSettings& bake, size_t points,
                          uint32_t referenceRays, uint64_t seed);

}  // namespace grotto::voxel
