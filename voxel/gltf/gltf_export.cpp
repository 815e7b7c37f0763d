#include "voxel/gltf/gltf_export.h"

#include "common/atomic_file.h"
#include "grotto/error.h"
#include "shaders/shared/quad.h"
#include "voxel/brick_table.h"
#include "voxel/face_cache_lookup.h"

#include <tiny_gltf.h>

#include <glm/common.hpp>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <map>
#include <random>
#include <sstream>
#include <unordered_map>

namespace grotto::voxel {
namespace fs = std::filesystem;

namespace {

// Corner c of a face (0..3: (0,0), (1,0), (1,1), (0,1) in U, V), in voxel-corner index units:
// counter-clockwise about the face's outward normal.
glm::ivec3 faceCorner(const ExposedFace& f, int c) {
    glm::ivec3 p = f.cell;
    p[int(gpu::faceAxis(f.dir))] += gpu::facePositive(f.dir) ? 1 : 0;
    p[int(gpu::faceUAxis(f.dir))] += (c == 1 || c == 2) ? 1 : 0;
    p[int(gpu::faceVAxis(f.dir))] += (c >= 2) ? 1 : 0;
    return p;
}

uint8_t aoByte(double ao) { return uint8_t(std::lround(std::clamp(ao, 0.0, 1.0) * 255.0)); }

// Split along the diagonal whose ends differ less in AO: a dark corner then
// shades its own triangle instead of streaking across the face.
bool splitAlong02(const std::array<uint8_t, 4>& a) { return std::abs(a[0] - a[2]) <= std::abs(a[1] - a[3]); }

struct VertexKey {
    glm::ivec3 corner;
    uint8_t dir, ao;
    bool operator==(const VertexKey&) const = default;
};
struct VertexKeyHash {
    size_t operator()(const VertexKey& k) const {
        return size_t(uint32_t(k.corner.x)) * 73856093u ^ size_t(uint32_t(k.corner.y)) * 19349663u ^
               size_t(uint32_t(k.corner.z)) * 83492791u ^ size_t(k.dir) * 2654435761u ^ size_t(k.ao) << 40;
    }
};

}  // namespace

double interpolateCornerAo(const std::array<uint8_t, 4>& c, double u, double v) {
    const double a0 = c[0], a1 = c[1], a2 = c[2], a3 = c[3];
    double ao;
    if (splitAlong02(c))
        ao = u >= v ? a0 * (1 - u) + a1 * (u - v) + a2 * v : a0 * (1 - v) + a2 * u + a3 * (v - u);
    else
        ao = u + v <= 1 ? a0 * (1 - u - v) + a1 * u + a3 * v : a1 * (1 - v) + a2 * (u + v - 1) + a3 * (1 - u);
    return ao / 255.0;
}

AoMesh buildAoMesh(const World& world, const FaceBakeSettings& bake, const BakeProgress& progress) {
    const BrickTable table(world);
    AoMesh mesh;
    mesh.faces = exposedFaces(table, world);
    const uint32_t k = bake.texelsPerSide;
    mesh.texelsPerSide = k;
    mesh.texels.resize(mesh.faces.size() * k * k);
    bakeFacesInSteps(table, world, mesh.faces, bake, mesh.texels, progress);
    const FaceCacheLookup lookup(mesh.faces, mesh.texels, k);

    const IndexBox bounds = world.bounds();
    const glm::ivec3 base = bounds.empty() ? glm::ivec3(0) : bounds.min;
    mesh.offset = world.origin() + glm::dvec3(base) * world.voxelSize();
    std::map<int, AoMesh::Primitive> byMaterial;
    std::map<int, std::unordered_map<VertexKey, uint32_t, VertexKeyHash>> vertexIndex;
    mesh.cornerAo.reserve(mesh.faces.size());
    for (const ExposedFace& f : mesh.faces) {
        const glm::dvec3 centre = glm::dvec3(faceCorner(f, 0) + faceCorner(f, 2)) * 0.5;
        std::array<uint8_t, 4> ao{};
        for (int c = 0; c < 4; ++c) {
            // A hair inside the face, so the corner reads this face's plane and neighbours.
            const glm::dvec3 p = glm::mix(glm::dvec3(faceCorner(f, c)), centre, 1e-6);
            ao[size_t(c)] = aoByte(lookup.at(p, f.dir).ao);
        }
        mesh.cornerAo.push_back(ao);
        const int material = world.material(f.cell);
        AoMesh::Primitive& prim = byMaterial[material];
        prim.material = material;
        auto& index = vertexIndex[material];
        std::array<uint32_t, 4> v{};
        for (int c = 0; c < 4; ++c) {
            const glm::ivec3 corner = faceCorner(f, c);
            const auto [it, added] = index.try_emplace(VertexKey{corner, f.dir, ao[size_t(c)]}, uint32_t(prim.ao.size()));
            if (added) {
                prim.positions.push_back(glm::vec3(glm::dvec3(corner - base) * world.voxelSize()));
                prim.normals.push_back(glm::vec3(faceNormal(f.dir)));
                prim.ao.push_back(ao[size_t(c)]);
            }
            v[size_t(c)] = it->second;
        }
        const std::array<int, 6> tris = splitAlong02(ao) ? std::array<int, 6>{0, 1, 2, 0, 2, 3}
                                                         : std::array<int, 6>{0, 1, 3, 1, 2, 3};
        for (int t : tris) prim.indices.push_back(v[size_t(t)]);
    }
    for (auto& [id, prim] : byMaterial) mesh.primitives.push_back(std::move(prim));
    return mesh;
}

namespace {

// Appends `bytes` to the buffer (4-byte aligned) as a buffer view; returns its index.
int addView(tinygltf::Model& m, const void* bytes, size_t size, int target) {
    std::vector<unsigned char>& data = m.buffers[0].data;
    data.resize((data.size() + 3) & ~size_t(3));
    tinygltf::BufferView view;
    view.buffer = 0;
    view.byteOffset = data.size();
    view.byteLength = size;
    view.target = target;
    data.insert(data.end(), static_cast<const unsigned char*>(bytes), static_cast<const unsigned char*>(bytes) + size);
    m.bufferViews.push_back(view);
    return int(m.bufferViews.size() - 1);
}

int addAccessor(tinygltf::Model& m, int view, int componentType, int type, size_t count, bool normalized = false) {
    tinygltf::Accessor a;
    a.bufferView = view;
    a.componentType = componentType;
    a.type = type;
    a.count = count;
    a.normalized = normalized;
    m.accessors.push_back(a);
    return int(m.accessors.size() - 1);
}

constexpr const char* kEmissiveStrength = "KHR_materials_emissive_strength";

// glTF's emissiveFactor is a colour in [0, 1]: an intensity up to 1 is folded into
// it; above 1 the colour stays as it is and the extension carries the intensity, so
// a lamp's radiance survives the trip. A material that does not glow writes nothing.
void setEmission(tinygltf::Material& mat, const Material& src, tinygltf::Model& m) {
    if (!src.emits()) return;
    const glm::vec3 c = src.emissionIntensity > 1.0f ? src.emissionColor : src.emission();
    mat.emissiveFactor = {c.r, c.g, c.b};
    if (src.emissionIntensity <= 1.0f) return;
    tinygltf::Value::Object strength{{"emissiveStrength", tinygltf::Value(double(src.emissionIntensity))}};
    mat.extensions[kEmissiveStrength] = tinygltf::Value(strength);
    if (std::find(m.extensionsUsed.begin(), m.extensionsUsed.end(), kEmissiveStrength) == m.extensionsUsed.end())
        m.extensionsUsed.push_back(kEmissiveStrength);
}

}  // namespace

uintmax_t writeGltfMesh(const World& world, const AoMesh& mesh, const fs::path& out) {
    const std::string ext = out.extension().string();
    if (ext != ".glb" && ext != ".gltf") throw Error(out.string(), "a glTF file ends in .glb or .gltf");
    requireOutputPath(out);
    if (mesh.primitives.empty()) throw Error(out.string(), "the world has no exposed faces to write", "glTF has no empty meshes");
    tinygltf::Model m;
    m.asset.version = "2.0";
    m.asset.generator = "grotto " GROTTO_VERSION;
    m.buffers.resize(1);
    tinygltf::Mesh gmesh;
    gmesh.name = world.desc().source.stem().string();
    const std::vector<Material>& palette = world.desc().materials;
    for (const AoMesh::Primitive& prim : mesh.primitives) {
        tinygltf::Material mat;
        const Material& src = palette.at(size_t(prim.material - 1));
        mat.name = src.name;
        mat.pbrMetallicRoughness.baseColorFactor = {src.albedo.r, src.albedo.g, src.albedo.b, 1.0};
        mat.pbrMetallicRoughness.metallicFactor = 0.0;
        mat.pbrMetallicRoughness.roughnessFactor = 1.0;
        setEmission(mat, src, m);
        m.materials.push_back(mat);

        std::vector<uint8_t> colours(prim.ao.size() * 4);
        for (size_t i = 0; i < prim.ao.size(); ++i)
            std::memset(&colours[i * 4], prim.ao[i], 3), colours[i * 4 + 3] = 255;
        const size_t n = prim.positions.size();
        tinygltf::Primitive p;
        p.mode = TINYGLTF_MODE_TRIANGLES;
        p.material = int(m.materials.size() - 1);
        const int pos = addAccessor(m, addView(m, prim.positions.data(), n * 12, TINYGLTF_TARGET_ARRAY_BUFFER),
                                    TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_TYPE_VEC3, n);
        glm::vec3 lo(std::numeric_limits<float>::max()), hi(-std::numeric_limits<float>::max());
        for (const glm::vec3& q : prim.positions) lo = glm::min(lo, q), hi = glm::max(hi, q);
        m.accessors[size_t(pos)].minValues = {lo.x, lo.y, lo.z};
        m.accessors[size_t(pos)].maxValues = {hi.x, hi.y, hi.z};
        p.attributes["POSITION"] = pos;
        p.attributes["NORMAL"] = addAccessor(m, addView(m, prim.normals.data(), n * 12, TINYGLTF_TARGET_ARRAY_BUFFER),
                                             TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_TYPE_VEC3, n);
        p.attributes["COLOR_0"] = addAccessor(m, addView(m, colours.data(), colours.size(), TINYGLTF_TARGET_ARRAY_BUFFER),
                                              TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE, TINYGLTF_TYPE_VEC4, n, true);
        p.indices = addAccessor(m, addView(m, prim.indices.data(), prim.indices.size() * 4, TINYGLTF_TARGET_ELEMENT_ARRAY_BUFFER),
                                TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT, TINYGLTF_TYPE_SCALAR, prim.indices.size());
        gmesh.primitives.push_back(p);
    }
    m.meshes.push_back(gmesh);
    tinygltf::Node node;
    node.name = gmesh.name;
    node.mesh = 0;
    // Positions are stored relative to the world's corner, in floats; the corner
    // itself, in doubles, keeps a world far from the origin exact.
    if (mesh.offset != glm::dvec3(0.0)) node.translation = {mesh.offset.x, mesh.offset.y, mesh.offset.z};
    m.nodes.push_back(node);
    tinygltf::Scene scene;
    scene.nodes = {0};
    m.scenes.push_back(scene);
    m.defaultScene = 0;

    std::ostringstream bytes;
    tinygltf::TinyGLTF writer;
    if (!writer.WriteGltfSceneToStream(&m, bytes, ext == ".gltf", ext == ".glb"))
        throw Error::internal(out.string(), "tinygltf could not write the glTF file");
    const std::string data = std::move(bytes).str();
    writeAtomically(out, data);
    return data.size();
}

AoMeshError measureAoMesh(const World& world, const AoMesh& mesh, const FaceBakeSettings& bake, size_t points,
                          uint32_t referenceRays, uint64_t seed) {
    AoMeshError e;
    if (mesh.faces.empty() || points == 0) return e;
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    std::vector<glm::dvec3> where;
    std::vector<uint8_t> dirs;
    std::vector<double> vertexAo, cacheAo;
    const FaceCacheLookup lookup(mesh.faces, mesh.texels, mesh.texelsPerSide);
    for (size_t i = 0; i < points; ++i) {
        const size_t f = size_t(rng() % mesh.faces.size());
        const ExposedFace& face = mesh.faces[f];
        const double u = unit(rng), v = unit(rng);
        glm::dvec3 p = glm::dvec3(faceCorner(face, 0));
        p[int(gpu::faceUAxis(face.dir))] += u;
        p[int(gpu::faceVAxis(face.dir))] += v;
        where.push_back(p);
        dirs.push_back(face.dir);
        vertexAo.push_back(interpolateCornerAo(mesh.cornerAo[f], u, v));
        cacheAo.push_back(lookup.at(p, face.dir).ao);
    }
    const BrickTable table(world);
    FaceBakeSettings reference = bake;
    reference.rays = referenceRays;
    reference.sunRays = 1;
    const std::vector<FaceTexel> truth = tracePoints(table, world, where, dirs, reference, seed ^ 0x9e3779b97f4a7c15ull);
    double sum = 0.0, sq = 0.0, bias = 0.0, cacheSum = 0.0, cacheSq = 0.0;
    for (size_t i = 0; i < points; ++i) {
        const double d = vertexAo[i] - truth[i].ao(), c = cacheAo[i] - truth[i].ao();
        sum += std::abs(d), sq += d * d, bias += d;
        cacheSum += std::abs(c), cacheSq += c * c;
        e.max = std::max(e.max, std::abs(d));
    }
    e.cacheMae = cacheSum / double(points);
    e.cacheRmse = std::sqrt(cacheSq / double(points));
    e.points = points;
    e.mae = sum / double(points);
    e.rmse = std::sqrt(sq / double(points));
    e.bias = bias / double(points);
    return e;
}

}  // namespace grotto::voxel
