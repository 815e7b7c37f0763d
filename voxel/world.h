#pragma once
// A loaded voxel world: solid occupancy, materials and everything its file says.
// OpenVDB stays behind this interface, so the engine can use it without OpenVDB.
#include "voxel/edit.h"
#include "voxel/mesh.h"
#include "voxel/world_desc.h"

#include <glm/vec3.hpp>

#include <cstdint>
#include <filesystem>
#include <memory>
#include <optional>
#include <vector>

namespace grotto::voxel {

// Solid voxels must lie within -kMaxVoxelIndex <= index < kMaxVoxelIndex on
// every axis (2^30): a grid reaching further is refused on load, so no index
// computation (bricks, chunks, bounds) can overflow.
constexpr int kMaxVoxelIndex = 1 << 30;

// The voxel sizes and grid translations a world may have (world units): within
// them every position stays finite and well resolved in doubles, and the
// camera's near plane (1e-4 at least) fits the smallest world.
constexpr double kMinVoxelSize = 1e-4, kMaxVoxelSize = 1e6;
constexpr double kMaxWorldOffset = 1e12;

// An 8^3 brick: one OpenVDB leaf node (or one block of an active tile) with its
// occupancy as 512 bits, bit x*64 + y*8 + z as OpenVDB orders leaf voxels.
struct Brick {
    glm::ivec3 origin;
    uint64_t occupancy[8];
};

struct RayHit {
    double distance;      // world units along the (normalised) ray
    glm::ivec3 voxel;     // the solid voxel hit
    int face;             // face entered through: 0..5 = +X -X +Y -Y +Z -Z
};

// Where an exact ray starts, as the GPU's traversal takes it (shaders/shared/voxel_ray.h):
// a voxel and the position within it, 0..1 on each axis.
struct RayStart {
    glm::ivec3 voxel{0};
    glm::vec3 fraction{0.0f};
};

struct WorldStats {
    uint64_t solidVoxels = 0;
    uint64_t bricks = 0;
    size_t hostBytes = 0;        // our solid + material grids
    size_t sourceGridBytes = 0;  // OpenVDB's memUsage() of the grid as loaded
    // A .vox world's estimate of loading and meshing it (voxel/work_memory.h),
    // checked against its memory budget on load; 0 for other worlds.
    uint64_t workBytesEstimate = 0;
};

// A world is live: edits change its grid in place. Copies are deep (an edited
// copy leaves the original as it was); moves are cheap.
class World {
public:
    // Loads a world .json or a bare .vdb. Throws grotto::Error (input) on bad input.
    static World load(const std::filesystem::path& path);
    // A world from memory: a dense array of material ids (0 = empty), x fastest,
    // then y, then z, with voxel (0,0,0) at `origin` (world units). Error on bad sizes.
    // An empty desc.materials means defaultMaterials(), as for a bare .vdb.
    static World fromDense(glm::ivec3 size, const uint8_t* materials, double voxelSize, glm::dvec3 origin,
                           WorldDesc desc = {});

    const WorldDesc& desc() const;
    // Replaces the lighting (a command line's or a viewer's time of day); the voxels stay.
    void setLighting(const Lighting& lighting);
    double voxelSize() const;
    glm::dvec3 origin() const;   // world position of voxel corner (0, 0, 0)
    IndexBox bounds() const;
    WorldStats stats() const;

    std::vector<Brick> bricks() const;  // with solid voxels; tiles split into full bricks
    // The same, for the bricks overlapping `region` only: after an edit, the
    // bricks of its changed box are all a copy of the bricks needs (those of
    // the box not listed are empty now).
    std::vector<Brick> bricks(const IndexBox& region) const;
    Mesh mesh(const MeshOptions& options = {}) const;

    // Solid-voxel test and exact voxel traversal (DDA) in world units. The traversal
    // is the GPU's own code (shaders/shared/voxel_ray.h): a ray through an edge or a
    // corner enters a voxel beside it, never slipping between two solid voxels.
    bool solid(glm::ivec3 voxel) const;
    std::optional<RayHit> raycast(glm::dvec3 origin, glm::dvec3 direction, double maxDistance) const;
    // The same from a start given as the GPU gives it, along a unit direction (a ray
    // that starts in a solid voxel hits it at 0, face -1); maxDistance in world units.
    std::optional<RayHit> raycast(const RayStart& start, glm::vec3 direction, double maxDistance) const;
    // Where a ray leaving a point on a voxel face starts, as the sun shadows have it:
    // `start` is the point in the open voxel in front of the face (axis normalAxis);
    // one placed a hair inside the solid voxel beside that one (at a concave edge)
    // moves onto the open voxel's edge.
    RayStart faceRayStart(const RayStart& start, int normalAxis) const;
    // How far a ray from a start in a solid voxel runs through solid voxels before
    // it enters an open one, in world units, up to maxDistance (0 when the start
    // voxel is open): VBAO's voxels thickness, as the GPU traces it.
    double solidRun(const RayStart& start, glm::vec3 direction, double maxDistance) const;

    // Material id of a voxel, 0 when empty.
    int material(glm::ivec3 voxel) const;
    // How many solid voxels each material id draws, indexed by id (at least id 0,
    // which counts none): which of the palette a world uses.
    std::vector<uint64_t> voxelsByMaterial() const;

    // A named camera, or the default one when name is empty: the world's default
    // camera, else one framing the bounds tightly in an image of `aspect`
    // (width / height; voxel/camera_frame.h).
    CameraDesc camera(const std::string& name, double aspect) const;

    // Edits (voxel/edit.h). Each returns what it changed; an edit that changes
    // nothing returns an empty result and is not recorded. Throws grotto::Error
    // (input) for an edit out of range (material, radius, index limits).
    EditResult apply(const Edit& edit);
    // Throws what apply would refuse before changing anything (range, palette,
    // the memory budget), without applying it: edits read from files are checked
    // when they are read, not when their time comes.
    void check(const Edit& edit) const;
    // Reverts the last recorded edit; an empty result when there is none. Undo
    // keeps the last 1024 edits and at most 64 MiB of the voxels' prior states
    // (16 bytes per changed voxel, 28 per changed part of a brick that held one
    // state throughout); an edit larger than that cannot be undone,
    // nor can any before it.
    EditResult undo();
    size_t undoDepth() const;
    // Edits applied since load, in order, minus those undone: what the world's
    // voxels differ from its file by (the reference cache keys on it).
    const std::vector<Edit>& editLog() const;

    // Writes the world as FILE.vdb, the grid (voxels, materials, transform and the
    // source grid's metadata), and FILE.json, the world file naming it with the
    // palette, lighting, AO, detail, cameras, paths and objects of `settings`
    // (the world's own by default); `path` names either. Each file is written
    // atomically. World::load of FILE.json is the same world; of FILE.vdb alone,
    // the same voxels and materials.
    struct SavedFiles {
        std::filesystem::path world, grid;  // FILE.json, FILE.vdb
    };
    SavedFiles save(const std::filesystem::path& path) const;
    SavedFiles save(const std::filesystem::path& path, const WorldDesc& settings) const;

    // Chunks (origins, GROTTO_CHUNK_SIZE aligned) whose mesh may differ after the
    // voxels in `changed` did: those holding the box grown by one voxel.
    std::vector<glm::ivec3> chunksTouching(const IndexBox& changed) const;
    // The voxel indices of the corners of the chunks that may hold quads (those
    // touched by a leaf or an active tile), in World::mesh()'s order.
    std::vector<glm::ivec3> chunkOrigins() const;
    // The greedy rectangles of one chunk (and of its coarser levels), as World::mesh()
    // makes them before it welds them with the neighbours' into quads (voxel/watertight.h):
    // `quads` and the face counts are left empty.
    MeshChunkQuads meshChunk(glm::ivec3 chunkOrigin, const MeshOptions& options = {}) const;

    World(const World& other);
    World& operator=(const World& other);
    World(World&&) noexcept;
    World& operator=(World&&) noexcept;
    ~World();

    struct Impl;
    explicit World(std::shared_ptr<Impl> impl);
    const Impl& impl() const { return *impl_; }

private:
    std::shared_ptr<Impl> impl_;
};

}  // namespace grotto::voxel
