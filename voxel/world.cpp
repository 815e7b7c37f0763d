#include "common/address_space.h"
#include "grotto/error.h"
#include "voxel/object_worlds.h"
#include "voxel/camera_frame.h"
#include "voxel/solid.h"
#include "voxel/vox_world.h"
#include "voxel/work_memory.h"

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdio>
#include <limits>

namespace grotto::voxel {

uint64_t brickCount(const openvdb::MaskTree& tree) {
    uint64_t bricks = tree.leafCount();
    auto it = tree.cbeginValueOn();
    it.setMaxDepth(openvdb::MaskTree::ValueOnCIter::LEAF_DEPTH - 1);
    for (; it; ++it) bricks += it.getVoxelCount() / 512;
    return bricks;
}

namespace {

// Above this many bricks a region's bricks come from walking the tree.
constexpr double kProbedBricks = 4096;

// The tree's bricks within the brick range [lo, hi]: its non-empty leaves, and
// its active tiles as the full bricks they stand for.
void collectBricks(const openvdb::MaskTree& tree, glm::ivec3 lo, glm::ivec3 hi, std::vector<Brick>& out) {
    auto inRange = [&](const openvdb::Coord& o) {
        const glm::ivec3 b = glm::ivec3(o.x(), o.y(), o.z()) >> 3;
        return b.x >= lo.x && b.y >= lo.y && b.z >= lo.z && b.x <= hi.x && b.y <= hi.y && b.z <= hi.z;
    };
    for (auto leaf = tree.cbeginLeaf(); leaf; ++leaf) {
        if (leaf->isEmpty() || !inRange(leaf->origin())) continue;
        Brick b;
        const openvdb::Coord o = leaf->origin();
        b.origin = {o.x(), o.y(), o.z()};
        const auto& mask = leaf->getValueMask();
        for (int w = 0; w < 8; ++w) b.occupancy[w] = mask.template getWord<uint64_t>(w);
        out.push_back(b);
    }
    auto it = tree.cbeginValueOn();
    it.setMaxDepth(openvdb::MaskTree::ValueOnCIter::LEAF_DEPTH - 1);
    for (; it; ++it) {
        openvdb::CoordBBox box;
        it.getBoundingBox(box);
        const glm::ivec3 from = glm::max(glm::ivec3(box.min().x(), box.min().y(), box.min().z()) >> 3, lo);
        const glm::ivec3 to = glm::min(glm::ivec3(box.max().x(), box.max().y(), box.max().z()) >> 3, hi);
        for (int x = from.x; x <= to.x; ++x)
            for (int y = from.y; y <= to.y; ++y)
                for (int z = from.z; z <= to.z; ++z) {
                    Brick b{{x * 8, y * 8, z * 8}, {}};
                    for (auto& w : b.occupancy) w = ~uint64_t(0);
                    out.push_back(b);
                }
    }
}

}  // namespace

World makeWorld(const openvdb::GridBase::Ptr& grid, WorldDesc desc) {
    auto impl = std::make_shared<World::Impl>();
    impl->desc = std::move(desc);
    const std::string file = impl->desc.gridFile.empty() ? "<memory>" : impl->desc.gridFile.string();
    const GridPlacement placement = readTransform(*grid, file);
    impl->voxelSize = placement.voxelSize;
    impl->origin = placement.origin;
    impl->sourceGridBytes = grid->memUsage();
    impl->gridName = grid->getName();
    impl->sourceType = grid->type();
    impl->sourceMeta = grid->copyMeta();
    buildSolid(grid, *impl);
    openvdb::CoordBBox box;
    if (impl->solid->tree().evalActiveVoxelBoundingBox(box)) {
        // Past this range the index arithmetic downstream (bricks, chunks, bounds
        // + 1) would overflow int32; refused before any of it runs.
        for (int axis = 0; axis < 3; ++axis)
            if (box.min()[axis] < -kMaxVoxelIndex || box.max()[axis] >= kMaxVoxelIndex)
                throw Error(file, "grid '" + grid->getName() + "' has solid voxels at index " +
                                      std::to_string(box.min()[axis] < -kMaxVoxelIndex ? box.min()[axis] : box.max()[axis]) +
                                      " on " + "xyz"[axis] + ", outside the supported index range",
                            "supported: -2^30 <= index < 2^30 on every axis; move the grid nearer the origin");
        impl->bounds = {{box.min().x(), box.min().y(), box.min().z()}, {box.max().x(), box.max().y(), box.max().z()}};
    }
    // A huge active tile, or a level set's interior, is small in OpenVDB but
    // expands into full bricks here: refused before any of them is made.
    const uint64_t bricks = brickCount(impl->solid->tree());
    const double bytes = double(bricks) * double(kBytesPerBrick);
    if (bytes > double(memoryRoom(impl->desc.memoryBudgetBytes)))
        throw Error(file, "grid '" + grid->getName() + "' is solid over " + overBudget(double(bricks), bytes, impl->desc.memoryBudgetBytes),
                    "raise 'memory_budget_mib' in the world file, or make the grid smaller or sparser");
    World::Impl& made = *impl;
    World world(std::move(impl));
    // A .vox's few bytes can place a model many times over, and its mesh, not its
    // grid, is most of what it costs: the whole work is estimated before it is done,
    // for a world's grid and an object's alike.
    if (isVoxFile(made.desc.gridFile)) made.workBytesEstimate = requireWorkFits(world).total();
    return world;
}

size_t memoryRoom(size_t budget) { return std::min(budget, addressSpaceLeft().value_or(budget)); }

std::string overBudget(double bricks, double bytes, size_t budget) {
    const size_t room = memoryRoom(budget);
    char figures[200];
    std::snprintf(figures, sizeof figures, "%.0f bricks of 8^3 voxels, an estimated %.1f MiB, more than the %s%.1f MiB%s",
                  bricks, bytes / (1 << 20), room < budget ? "" : "memory budget of ", double(room) / (1 << 20),
                  room < budget ? " of address space this process may still map (ulimit -v)" : "");
    return figures;
}

World World::load(const std::filesystem::path& path) {
    WorldDesc desc = loadWorldDesc(path);
    requireObjectsFit(desc);  // from their sizes: refused now, not after the world's grid is read
    openvdb::GridBase::Ptr grid = loadGrid(desc);
    World world = makeWorld(grid, std::move(desc));
    // Nothing solid would render sky and measure nothing: a file meant to be a
    // world is wrong (an empty world can still be made in memory and built up).
    if (world.bounds().empty())
        throw Error(world.desc().gridFile.string(), "grid '" + grid->getName() + "' has no solid voxels",
                    std::string("the solid rule is '") + solidRuleName(world.desc().rule) +
                        "'; check 'grid.rule' and 'grid.threshold' in the world file");
    return world;
}

World::World(std::shared_ptr<Impl> impl) : impl_(std::move(impl)) {}
World::World(World&&) noexcept = default;
World& World::operator=(World&&) noexcept = default;
World::~World() = default;

// Deep: the grids are copied, so edits on one world never show in another.
World::World(const World& other) : impl_(std::make_shared<Impl>(*other.impl_)) {
    impl_->solid = other.impl_->solid->deepCopy();
    if (other.impl_->materials) impl_->materials = other.impl_->materials->deepCopy();
}

World& World::operator=(const World& other) {
    if (this != &other) *this = World(other);
    return *this;
}

const WorldDesc& World::desc() const { return impl_->desc; }
void World::setLighting(const Lighting& lighting) { impl_->desc.lighting = lighting; }
double World::voxelSize() const { return impl_->voxelSize; }
glm::dvec3 World::origin() const { return impl_->origin; }

IndexBox World::bounds() const { return impl_->bounds; }

WorldStats World::stats() const {
    WorldStats s;
    const auto& tree = impl_->solid->tree();
    s.solidVoxels = tree.activeVoxelCount();
    s.bricks = brickCount(tree);
    s.hostBytes = impl_->solid->memUsage() + (impl_->materials ? impl_->materials->memUsage() : 0);
    s.sourceGridBytes = impl_->sourceGridBytes;
    s.workBytesEstimate = impl_->workBytesEstimate;
    return s;
}

std::vector<Brick> World::bricks() const {
    std::vector<Brick> out;
    const auto& tree = impl_->solid->tree();
    out.reserve(brickCount(tree));  // tiles included: no regrowth at the size the budget allowed
    collectBricks(tree, glm::ivec3(std::numeric_limits<int>::min() >> 3), glm::ivec3(std::numeric_limits<int>::max() >> 3), out);
    return out;
}

std::vector<Brick> World::bricks(const IndexBox& region) const {
    std::vector<Brick> out;
    if (region.empty()) return out;
    const glm::ivec3 lo = region.min >> 3, hi = region.max >> 3;
    const double span = double(hi.x - lo.x + 1) * double(hi.y - lo.y + 1) * double(hi.z - lo.z + 1);
    // A small region is probed brick by brick; a large one takes the tree's
    // bricks, so a carve across a sparse world costs its bricks, not its volume.
    if (span > kProbedBricks) {
        collectBricks(impl_->solid->tree(), lo, hi, out);
        return out;
    }
    openvdb::MaskGrid::ConstAccessor acc = impl_->solid->getConstAccessor();
    for (int x = lo.x; x <= hi.x; ++x)
        for (int y = lo.y; y <= hi.y; ++y)
            for (int z = lo.z; z <= hi.z; ++z) {
                Brick b{{x * 8, y * 8, z * 8}, {}};
                const openvdb::Coord c(b.origin.x, b.origin.y, b.origin.z);
                if (const auto* leaf = acc.probeConstLeaf(c)) {
                    if (leaf->isEmpty()) continue;
                    for (int w = 0; w < 8; ++w) b.occupancy[w] = leaf->getValueMask().template getWord<uint64_t>(w);
                } else if (acc.isValueOn(c)) {
                    for (auto& w : b.occupancy) w = ~uint64_t(0);
                } else {
                    continue;
                }
                out.push_back(b);
            }
    return out;
}

bool World::solid(glm::ivec3 v) const {
    return impl_->solid->tree().isValueOn(openvdb::Coord(v.x, v.y, v.z));
}

int World::material(glm::ivec3 v) const {
    const openvdb::Coord c(v.x, v.y, v.z);
    if (!impl_->solid->tree().isValueOn(c)) return 0;
    return impl_->materials ? impl_->materials->tree().getValue(c) : impl_->uniformMaterial;
}

CameraDesc World::camera(const std::string& name, double aspect) const {
    const WorldDesc& d = impl_->desc;
    const std::string& pick = name.empty() ? d.defaultCamera : name;
    if (!pick.empty()) {
        auto it = d.cameras.find(pick);
        if (it == d.cameras.end()) {
            std::string known;
            for (auto& [n, c] : d.cameras) known += (known.empty() ? "" : ", ") + n;
            throw Error(d.source.string(), "has no camera named '" + pick + "'",
                        known.empty() ? "the world defines no cameras" : "cameras: " + known);
        }
        return it->second;
    }
    IndexBox b = bounds();
    if (b.empty()) b = {glm::ivec3(0), glm::ivec3(0)};
    return frameBox(impl_->origin + glm::dvec3(b.min) * impl_->voxelSize,
                    impl_->origin + glm::dvec3(b.max + 1) * impl_->voxelSize, aspect);
}

}  // namespace grotto::voxel
