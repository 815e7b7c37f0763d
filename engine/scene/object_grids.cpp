#include "engine/scene/object_grids.h"

#include "grotto/error.h"
#include "shaders/shared/quad.h"
#include "voxel/brick_table.h"
#include "voxel/world.h"

#include <glm/gtc/quaternion.hpp>

#include <algorithm>
#include <string>

namespace grotto {

ObjectGrid objectGrid(const voxel::World& object) {
    ObjectGrid g;
    g.voxelSize = object.voxelSize();
    g.origin = object.origin();
    const IndexBox b = object.bounds();
    if (b.empty()) return g;
    g.lo = b.min;
    g.size = b.max - b.min + 1;
    const uint64_t cells = uint64_t(g.size.x) * uint64_t(g.size.y) * uint64_t(g.size.z);
    if (cells > (uint64_t(1) << 31))
        throw Error::internal("objectGrid", "an object's bounds hold more than 2^31 voxels");
    g.bits.assign(size_t((cells + 31) / 32), 0u);
    for (const voxel::Brick& brick : object.bricks())
        for (int x = 0; x < 8; ++x)
            for (int y = 0; y < 8; ++y)
                for (int z = 0; z < 8; ++z) {
                    if (!((brick.occupancy[x] >> (y * 8 + z)) & 1u)) continue;
                    const glm::ivec3 c = brick.origin + glm::ivec3(x, y, z) - g.lo;
                    const uint64_t bit = (uint64_t(c.x) * uint64_t(g.size.y) + uint64_t(c.y)) * uint64_t(g.size.z) + uint64_t(c.z);
                    g.bits[size_t(bit >> 5)] |= 1u << (bit & 31u);
                }
    if (std::any_of(object.desc().materials.begin(), object.desc().materials.end(),
                    [](const voxel::Material& m) { return m.emits(); })) {
        const voxel::BrickTable table(object);
        g.glowing = voxel::glowingFaces(object, voxel::exposedFaces(table, object));
    }
    return g;
}

void requireGlowFits(const std::string& where, std::span<const ObjectGrid> grids, const ObjectGrid* adding) {
    size_t faces = adding ? adding->glowing.size() : 0;
    for (const ObjectGrid& g : grids) faces += g.glowing.size();
    if (faces > GROTTO_MAX_GLOW_FACES)
        throw Error(where, "the objects glow on " + std::to_string(faces) + " faces in all",
                    "at most " + std::to_string(GROTTO_MAX_GLOW_FACES) + ": fewer or smaller glowing parts");
}

GpuObjectGrids uploadObjectGrids(vk::Context& ctx, std::span<const ObjectGrid> grids) {
    GpuObjectGrids out;
    std::vector<uint32_t> words;
    for (const ObjectGrid& g : grids) {
        out.first.push_back(uint32_t(words.size()));
        words.insert(words.end(), g.bits.begin(), g.bits.end());
    }
    if (words.empty()) words.push_back(0u);
    out.buffer = vk::uploadBuffer(ctx, words.data(), words.size() * sizeof(uint32_t), VK_BUFFER_USAGE_STORAGE_BUFFER_BIT);
    return out;
}

namespace {

// The rows mapping the rays' points (world voxels from `corner`) into grid g's
// cells at `pose`: cell = (toLocal(corner + p * voxelSize) - origin) / objectVoxel - lo.
void gridRows(glm::vec4 rows[3], const ObjectGrid& g, const voxel::ObjectPose& pose, glm::dvec3 corner, double voxelSize) {
    const glm::dmat3 a = glm::mat3_cast(glm::conjugate(pose.rotation)) * (voxelSize / g.voxelSize);
    const glm::dvec3 b = (pose.toLocal(corner) - g.origin) / g.voxelSize - glm::dvec3(g.lo);
    for (int row = 0; row < 3; ++row) rows[row] = glm::vec4(float(a[0][row]), float(a[1][row]), float(a[2][row]), float(b[row]));
}

}  // namespace

void setObjectTraces(gpu::TraceConstants& t, std::span<const ObjectGrid> grids, std::span<const uint32_t> first,
                     std::span<const voxel::ObjectPose> poses, std::span<const voxel::ObjectPose> previous,
                     double voxelSize, glm::dvec3 worldOrigin) {
    const size_t n = std::min({grids.size(), first.size(), poses.size(), size_t(GROTTO_MAX_OBJECTS)});
    // The rays' points are voxels from the camera voxel's corner, in the world's voxels.
    const glm::dvec3 corner = worldOrigin + glm::dvec3(t.cameraCell) * voxelSize;
    int used = 0;
    for (size_t k = 0; k < n; ++k) {
        const ObjectGrid& g = grids[k];
        if (g.bits.empty()) continue;
        gpu::ObjectTrace& o = t.objects[used++];
        gridRows(o.fromWorld, g, poses[k], corner, voxelSize);
        gridRows(o.previousFromWorld, g, k < previous.size() ? previous[k] : poses[k], corner, voxelSize);
        o.size = glm::ivec4(g.size, int(first[k]));
    }
    // The glowing faces, placed: each corner and edge through the object's pose
    // into the rays' voxels.
    uint32_t glow = 0;
    for (size_t k = 0; k < n; ++k) {
        const ObjectGrid& g = grids[k];
        const glm::dmat3 turn = glm::mat3_cast(poses[k].rotation);
        for (const voxel::GlowingFace& f : g.glowing) {
            if (glow == GROTTO_MAX_GLOW_FACES) break;  // refused where objects are added (requireGlowFits)
            const uint32_t dir = f.face.dir;
            glm::dvec3 c(f.face.cell), u(0.0), v(0.0);
            c[int(gpu::faceAxis(dir))] += gpu::facePositive(dir) ? 1.0 : 0.0;
            u[int(gpu::faceUAxis(dir))] = 1.0;  // cross(u, v) is the face's outward normal
            v[int(gpu::faceVAxis(dir))] = 1.0;
            const glm::dvec3 cornerWorld = poses[k].toWorld(g.origin + c * g.voxelSize);
            const double scale = g.voxelSize / voxelSize;
            gpu::GlowFace& out = t.glow[glow++];
            out.corner = glm::vec4(glm::vec3((cornerWorld - corner) / voxelSize), 0.0f);
            out.edgeU = glm::vec4(glm::vec3(turn * u * scale), 0.0f);
            out.edgeV = glm::vec4(glm::vec3(turn * v * scale), 0.0f);
            out.radiance = glm::vec4(glm::vec3(f.radiance), 0.0f);
        }
    }
    t.objectCount = glm::ivec4(used, int(glow), 0, 0);
}

}  // namespace grotto
