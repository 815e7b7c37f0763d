// The glTF export read back with tinygltf: one primitive and material per Grotto
// material, the world's bounds in world units, outward normals that agree with
// the triangles' winding, and vertex AO that carries the face cache's reading and
// stays near the ray-traced reference; glowing materials carry their emission.
#include "common/json_text.h"
#include "grotto/error.h"
#include "tests/test_util.h"
#include "voxel/brick_table.h"
#include "voxel/gltf/gltf_export.h"
#include "voxel/gltf/gltf_file.h"

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include <cmath>
#include <random>

namespace grotto::voxel {
namespace {

// A 10 x 10 floor of stone with a 2 x 3 x 2 block of wood on it, 0.5 units a voxel, away from the origin.
World floorAndBlock() {
    const glm::ivec3 size(10, 4, 10);
    std::vector<uint8_t> m(size_t(size.x * size.y * size.z), 0);
    for (int z = 0; z < size.z; ++z)
        for (int y = 0; y < size.y; ++y)
            for (int x = 0; x < size.x; ++x) {
                const bool block = y >= 1 && x >= 4 && x < 6 && z >= 4 && z < 6;
                m[size_t(x + size.x * (y + size.y * z))] = y == 0 ? 1 : block ? 3 : 0;
            }
    return World::fromDense(size, m.data(), 0.5, glm::dvec3(100.0, -3.0, 20.0));
}

struct Triangle {
    glm::dvec3 a, b, c, normal;
    double aoA, aoB, aoC;
};

std::vector<Triangle> trianglesOf(const tinygltf::Model& m, const glm::dvec3& offset, const std::string& file) {
    std::vector<Triangle> out;
    for (const tinygltf::Primitive& p : m.meshes.at(0).primitives) {
        const std::vector<float> pos = gltfFloats(m, p.attributes.at("POSITION"), 3, file, "POSITION");
        const std::vector<float> nrm = gltfFloats(m, p.attributes.at("NORMAL"), 3, file, "NORMAL");
        const tinygltf::Accessor& colour = m.accessors.at(size_t(p.attributes.at("COLOR_0")));
        EXPECT_EQ(colour.componentType, TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE);
        EXPECT_TRUE(colour.normalized);
        const tinygltf::BufferView& cv = m.bufferViews.at(size_t(colour.bufferView));
        const unsigned char* ao = m.buffers.at(0).data.data() + cv.byteOffset + colour.byteOffset;
        const tinygltf::Accessor& ia = m.accessors.at(size_t(p.indices));
        EXPECT_EQ(ia.componentType, TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT);
        const tinygltf::BufferView& iv = m.bufferViews.at(size_t(ia.bufferView));
        const auto* index = reinterpret_cast<const uint32_t*>(m.buffers.at(0).data.data() + iv.byteOffset + ia.byteOffset);
        auto at = [&](uint32_t i) { return offset + glm::dvec3(pos[i * 3], pos[i * 3 + 1], pos[i * 3 + 2]); };
        for (size_t t = 0; t + 2 < ia.count + 0; t += 3) {
            const uint32_t i0 = index[t], i1 = index[t + 1], i2 = index[t + 2];
            Triangle tri{at(i0), at(i1), at(i2), glm::dvec3(nrm[i0 * 3], nrm[i0 * 3 + 1], nrm[i0 * 3 + 2]),
                         ao[i0 * 4] / 255.0, ao[i1 * 4] / 255.0, ao[i2 * 4] / 255.0};
            EXPECT_EQ(ao[i0 * 4], ao[i0 * 4 + 1]);  // grey
            out.push_back(tri);
        }
    }
    return out;
}

TEST(GltfExport, TheFileReadsBackWithTheWorldsMaterialsBoundsNormalsAndAo) {
    const World world = floorAndBlock();
    const FaceBakeSettings bake{.radius = 2.0, .texelsPerSide = 3, .rays = 256, .sunRays = 1};
    const AoMesh mesh = buildAoMesh(world, bake);
    const grotto::test::ScratchDir dir;
    const auto file = dir / "world.glb";
    const uintmax_t bytes = writeGltfMesh(world, mesh, file);
    EXPECT_EQ(bytes, std::filesystem::file_size(file));

    const tinygltf::Model m = readGltf(file);
    ASSERT_EQ(m.meshes.size(), 1u);
    ASSERT_EQ(m.meshes[0].primitives.size(), 2u);  // stone and wood
    ASSERT_EQ(m.materials.size(), 2u);
    const Material& stone = world.desc().materials[0];
    EXPECT_NEAR(m.materials[0].pbrMetallicRoughness.baseColorFactor[0], stone.albedo.r, 1e-6);
    ASSERT_EQ(m.nodes.size(), 1u);
    const glm::dvec3 offset(m.nodes[0].translation[0], m.nodes[0].translation[1], m.nodes[0].translation[2]);
    EXPECT_EQ(offset, glm::dvec3(100.0, -3.0, 20.0));

    const std::vector<Triangle> tris = trianglesOf(m, offset, file.string());
    EXPECT_EQ(tris.size(), 2 * mesh.faces.size());
    glm::dvec3 lo(1e9), hi(-1e9);
    for (const Triangle& t : tris) {
        for (const glm::dvec3& p : {t.a, t.b, t.c}) lo = glm::min(lo, p), hi = glm::max(hi, p);
        // Counter-clockwise seen from outside: the winding's normal is the vertex normal.
        const glm::dvec3 n = glm::normalize(glm::cross(t.b - t.a, t.c - t.a));
        EXPECT_NEAR(glm::dot(n, t.normal), 1.0, 1e-9);
    }
    EXPECT_LT(glm::length(lo - glm::dvec3(100.0, -3.0, 20.0)), 1e-5);
    EXPECT_LT(glm::length(hi - glm::dvec3(105.0, -1.0, 25.0)), 1e-5);  // 10 x 4 x 10 voxels of 0.5

    // The AO at random points, interpolated over the triangle holding each point,
    // against 4096-ray references there.
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    std::vector<glm::dvec3> points;
    std::vector<uint8_t> dirs;
    std::vector<double> fileAo;
    for (int i = 0; i < 400; ++i) {
        const size_t f = rng() % mesh.faces.size();
        const ExposedFace& face = mesh.faces[f];
        const double u = unit(rng), v = unit(rng);
        glm::dvec3 p(face.cell);  // voxel index units
        const int axis = face.dir / 2;
        if (face.dir % 2 == 0) p[axis] += 1.0;
        p[(axis + 1) % 3] += axis == 0 ? u : axis == 1 ? v : u;  // any point of the face will do
        p[(axis + 2) % 3] += axis == 0 ? v : axis == 1 ? u : v;
        const glm::dvec3 world_p = world.origin() + p * world.voxelSize();
        double found = -1.0;
        for (const Triangle& t : tris) {
            if (glm::dot(t.normal, faceNormal(face.dir)) < 0.5 || std::abs(glm::dot(world_p - t.a, t.normal)) > 1e-6) continue;
            // Barycentric coordinates within the triangle's plane.
            const glm::dvec3 e0 = t.b - t.a, e1 = t.c - t.a, w = world_p - t.a;
            const double d00 = glm::dot(e0, e0), d01 = glm::dot(e0, e1), d11 = glm::dot(e1, e1);
            const double d20 = glm::dot(w, e0), d21 = glm::dot(w, e1), den = d00 * d11 - d01 * d01;
            const double b1 = (d11 * d20 - d01 * d21) / den, b2 = (d00 * d21 - d01 * d20) / den, b0 = 1 - b1 - b2;
            if (b0 < -1e-9 || b1 < -1e-9 || b2 < -1e-9) continue;
            found = b0 * t.aoA + b1 * t.aoB + b2 * t.aoC;
            break;
        }
        ASSERT_GE(found, 0.0) << "no triangle holds a point of face " << f;
        points.push_back(p);
        dirs.push_back(face.dir);
        fileAo.push_back(found);
    }
    FaceBakeSettings reference = bake;
    reference.rays = 4096;
    const std::vector<FaceTexel> truth = tracePoints(BrickTable(world), world, points, dirs, reference, 11);
    double sum = 0.0, bias = 0.0;
    for (size_t i = 0; i < points.size(); ++i) sum += std::abs(fileAo[i] - truth[i].ao()), bias += fileAo[i] - truth[i].ao();
    const double mae = sum / double(points.size());
    EXPECT_LT(mae, 0.01);
    EXPECT_LT(std::abs(bias) / double(points.size()), 0.02);
    // Open floor far from the block reads fully open; the floor at the block's foot is dark.
    EXPECT_GT(*std::max_element(fileAo.begin(), fileAo.end()), 0.99);
    EXPECT_LT(*std::min_element(fileAo.begin(), fileAo.end()), 0.7);
    // measureAoMesh says the same of the mesh.
    const AoMeshError e = measureAoMesh(world, mesh, bake, 400, 4096, 3);
    EXPECT_LT(e.mae, 0.01);
    std::printf("vertex AO: file MAE %.4f, measureAoMesh MAE %.4f RMSE %.4f max %.3f\n", mae, e.mae, e.rmse, e.max);
}

TEST(GltfExport, TextGltfEmbedsItsBufferAndOtherNamesAreRefused) {
    const World world = floorAndBlock();
    const AoMesh mesh = buildAoMesh(world, {.radius = 1.0, .texelsPerSide = 1, .rays = 16, .sunRays = 1});
    const grotto::test::ScratchDir dir;
    writeGltfMesh(world, mesh, dir / "world.gltf");
    const tinygltf::Model m = readGltf(dir / "world.gltf");
    EXPECT_EQ(m.meshes.at(0).primitives.size(), 2u);
    EXPECT_EQ(std::filesystem::directory_iterator(dir.path)->path().filename(), "world.gltf");  // nothing beside it
    EXPECT_THROW(writeGltfMesh(world, mesh, dir / "world.obj"), Error);
}

// Three materials on a floor: stone that does not glow, a dim lamp (intensity 0.5)
// and a bright one (intensity 40). glTF's emissiveFactor stops at 1, so only the
// bright one needs KHR_materials_emissive_strength.
TEST(GltfExport, EmissiveMaterialsCarryTheirRadiance) {
    WorldDesc desc;
    desc.materials.resize(3);
    desc.materials[0].name = "stone";
    desc.materials[1].name = "ember";
    desc.materials[1].emissionColor = glm::vec3(1.0f, 0.5f, 0.25f);
    desc.materials[1].emissionIntensity = 0.5f;
    desc.materials[2].name = "lamp";
    desc.materials[2].emissionColor = glm::vec3(1.0f, 0.8f, 0.6f);
    desc.materials[2].emissionIntensity = 40.0f;
    const uint8_t ids[4] = {1, 2, 3, 1};
    const World world = World::fromDense(glm::ivec3(4, 1, 1), ids, 1.0, glm::dvec3(0.0), desc);
    const AoMesh mesh = buildAoMesh(world, {.radius = 1.0, .texelsPerSide = 1, .rays = 8, .sunRays = 1});
    const grotto::test::ScratchDir dir;
    writeGltfMesh(world, mesh, dir / "world.gltf");
    const tinygltf::Model m = readGltf(dir / "world.gltf");
    ASSERT_EQ(m.materials.size(), 3u);
    const char* ext = "KHR_materials_emissive_strength";
    EXPECT_EQ(m.extensionsUsed, std::vector<std::string>{ext});

    const tinygltf::Material& stone = m.materials[0];
    EXPECT_EQ(stone.emissiveFactor, (std::vector<double>{0.0, 0.0, 0.0}));
    EXPECT_TRUE(stone.extensions.empty());

    auto expectEmissiveFactor = [](const tinygltf::Material& mat, glm::dvec3 expected) {
        ASSERT_EQ(mat.emissiveFactor.size(), 3u) << mat.name;
        for (int c = 0; c < 3; ++c) EXPECT_NEAR(mat.emissiveFactor[size_t(c)], expected[c], 1e-6) << mat.name;
    };
    const tinygltf::Material& ember = m.materials[1];
    expectEmissiveFactor(ember, {0.5, 0.25, 0.125});  // colour x intensity
    EXPECT_TRUE(ember.extensions.empty());

    const tinygltf::Material& lamp = m.materials[2];
    expectEmissiveFactor(lamp, {1.0, 0.8, 0.6});  // the colour; the intensity in the extension
    ASSERT_EQ(lamp.extensions.count(ext), 1u);
    EXPECT_NEAR(lamp.extensions.at(ext).Get("emissiveStrength").GetNumberAsDouble(), 40.0, 1e-6);

    // The text names no emission where nothing glows: a stone floor's file is as before.
    const World plain = floorAndBlock();
    writeGltfMesh(plain, buildAoMesh(plain, {.radius = 1.0, .texelsPerSide = 1, .rays = 8, .sunRays = 1}), dir / "plain.gltf");
    const std::string text = readJsonText(dir / "plain.gltf", "");
    EXPECT_EQ(text.find("emissive"), std::string::npos);
    EXPECT_EQ(text.find(ext), std::string::npos);
}

}  // namespace
}  // namespace grotto::voxel
