// Edits on the grid: fill, carve and paint over boxes and spheres, and their undo.
// Every edit walks its region brick by brick and changes only voxels whose state
// (material id, 0 = empty) differs, remembering their prior states for undo. A
// brick the edit covers whole that holds one state throughout (empty, or a tile)
// changes as a whole: it becomes a tile, and its prior state is remembered once,
// so a fill of a large region costs its bricks, not its voxels.
#include "grotto/error.h"
#include "common/number_text.h"
#include "shaders/shared/frame.h"
#include "voxel/solid.h"

#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <glm/vector_relational.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <optional>

namespace grotto::voxel {
namespace {

// Reads and writes voxel states through cached accessors. Holds accessors: no
// tree topology may be removed while one lives (see dropEmptyLeaves).
class VoxelStates {
public:
    explicit VoxelStates(World::Impl& w) : w_(w), solid_(w.solid->getAccessor()) {
        if (w.materials) mat_.emplace(w.materials->getAccessor());
    }
    int get(const openvdb::Coord& c) {
        if (!solid_.isValueOn(c)) return 0;
        return mat_ ? mat_->getValue(c) : w_.uniformMaterial;
    }
    void set(const openvdb::Coord& c, int material) {
        if (material == 0) {
            solid_.setValueOff(c);
            if (mat_) mat_->setValueOff(c, 0);
            return;
        }
        if (!mat_ && material != w_.uniformMaterial) createMaterials();
        solid_.setValueOn(c);
        if (mat_) mat_->setValueOn(c, material);
    }
    // The one state every voxel of the brick at b (8-aligned) has, when it is
    // empty or a tile; nothing when it is a leaf with voxels of its own.
    std::optional<int> uniform(const openvdb::Coord& b) {
        if (const auto* leaf = solid_.probeConstLeaf(b)) return leaf->isEmpty() ? std::optional<int>(0) : std::nullopt;
        if (!solid_.isValueOn(b)) return 0;
        if (!mat_) return w_.uniformMaterial;
        if (mat_->probeConstLeaf(b)) return std::nullopt;
        return mat_->getValue(b);
    }
    // Every voxel of `box` (within one brick) to `material`: a whole brick
    // becomes a tile, part of one changes voxel by voxel.
    void setBox(const IndexBox& box, int material) {
        const glm::ivec3 brick = box.min & ~7;
        if (box.min != brick || box.max != brick + 7) {
            for (int x = box.min.x; x <= box.max.x; ++x)
                for (int y = box.min.y; y <= box.max.y; ++y)
                    for (int z = box.min.z; z <= box.max.z; ++z) set({x, y, z}, material);
            return;
        }
        if (material != 0 && !mat_ && material != w_.uniformMaterial) createMaterials();
        const openvdb::Coord b(brick.x, brick.y, brick.z);
        const bool replacesLeaf = solid_.probeConstLeaf(b) || (mat_ && mat_->probeConstLeaf(b));
        solid_.addTile(1, b, material != 0, material != 0);
        if (mat_) mat_->addTile(1, b, material, material != 0);
        if (replacesLeaf) {  // the leaf is gone, but the accessors may still point at it
            solid_.clear();
            if (mat_) mat_->clear();
        }
    }
    bool createdMaterials() const { return created_; }

private:
    // The per-voxel material grid, made from the solid voxels (all of the
    // uniform material) the first time an edit brings in another material.
    void createMaterials() {
        auto tree = std::make_shared<openvdb::Int32Tree>(w_.solid->tree(), 0, w_.uniformMaterial, openvdb::TopologyCopy());
        w_.materials = openvdb::Int32Grid::create(tree);
        w_.materials->setTransform(w_.solid->transform().copy());
        w_.materials->setName("material");
        mat_.emplace(w_.materials->getAccessor());
        created_ = true;
    }

    World::Impl& w_;
    openvdb::MaskGrid::Accessor solid_;
    std::optional<openvdb::Int32Grid::Accessor> mat_;
    bool created_ = false;
};

openvdb::Coord coord(glm::ivec3 v) { return {v.x, v.y, v.z}; }

// Leaves an edit emptied are removed, so bricks(), stats() and the chunk list
// count only bricks with solid voxels. No accessor may be alive here.
void dropEmptyLeaves(World::Impl& w, std::vector<glm::ivec3> bricks) {
    std::sort(bricks.begin(), bricks.end(), [](glm::ivec3 a, glm::ivec3 b) {
        return a.x != b.x ? a.x < b.x : a.y != b.y ? a.y < b.y : a.z < b.z;
    });
    bricks.erase(std::unique(bricks.begin(), bricks.end()), bricks.end());
    for (glm::ivec3 b : bricks) {
        const openvdb::Coord c = coord(b);
        if (const auto* leaf = w.solid->tree().probeConstLeaf(c); leaf && leaf->isEmpty())
            w.solid->tree().addTile(1, c, false, false);
        if (!w.materials) continue;
        if (const auto* leaf = w.materials->tree().probeConstLeaf(c); leaf && leaf->isEmpty())
            w.materials->tree().addTile(1, c, 0, false);
    }
}

uint64_t volume(const IndexBox& b) {
    return uint64_t(b.max.x - b.min.x + 1) * uint64_t(b.max.y - b.min.y + 1) * uint64_t(b.max.z - b.min.z + 1);
}

// What changed, gathered as voxels change: one voxel, or a box (within one
// brick) whose voxels all went from one state to another.
struct Changes {
    IndexBox voxels, nowSolid, nowEmpty;
    uint64_t count = 0;
    std::vector<glm::ivec3> emptiedBricks;

    void add(glm::ivec3 v, int before, int after) { add(IndexBox{v, v}, before, after); }
    void add(const IndexBox& box, int before, int after) {
        voxels = voxels.merged(box);
        count += volume(box);
        if (after == 0) {
            nowEmpty = nowEmpty.merged(box);
            const glm::ivec3 brick = box.min & ~7;
            if (emptiedBricks.empty() || emptiedBricks.back() != brick) emptiedBricks.push_back(brick);
        } else if (before == 0) {
            nowSolid = nowSolid.merged(box);
        }
    }
};

// Growing the bounds is a merge; shrinking needs the tree only when a voxel on
// the boundary went empty.
void updateBounds(World::Impl& w, const Changes& c) {
    const IndexBox& b = w.bounds;
    const IndexBox& e = c.nowEmpty;
    const bool touchesBoundary = !e.empty() && !b.empty() &&
                                 (glm::any(glm::equal(e.min, b.min)) || glm::any(glm::equal(e.max, b.max)));
    if (touchesBoundary) {
        openvdb::CoordBBox box;
        w.bounds = w.solid->tree().evalActiveVoxelBoundingBox(box)
                       ? IndexBox{{box.min().x(), box.min().y(), box.min().z()}, {box.max().x(), box.max().y(), box.max().z()}}
                       : IndexBox{};
    } else {
        w.bounds = w.bounds.merged(c.nowSolid);
    }
}

EditResult resultOf(const World::Impl& w, const Changes& c) {
    EditResult r;
    r.voxels = c.voxels;
    r.changed = c.count;
    if (!c.voxels.empty())
        r.box = {w.origin + glm::dvec3(c.voxels.min) * w.voxelSize, w.origin + glm::dvec3(c.voxels.max + 1) * w.voxelSize};
    return r;
}

bool withinIndexLimits(double lo, double hi) { return lo >= -double(kMaxVoxelIndex) && hi < double(kMaxVoxelIndex); }

// The voxels an edit may change: its box, or the voxel box around its sphere.
// Throws grotto::Error for an edit out of range.
IndexBox regionOf(const Edit& e, const World::Impl& w) {
    const std::string where = "edit '" + describe(e) + "'";
    const int palette = int(std::min<size_t>(w.desc.materials.size(), GROTTO_MAX_MATERIALS));
    if (e.op != Edit::Op::Carve && (e.material < 1 || e.material > palette))
        throw Error(where, "material " + std::to_string(e.material) + " is not in the world's palette",
                    "accepted: 1.." + std::to_string(palette) + (e.op == Edit::Op::Fill ? "; carve to make voxels empty" : ""));
    const std::string limits = "accepted: voxel indices -2^30 <= i < 2^30 on every axis";
    if (e.shape == Edit::Shape::Box) {
        if (e.box.empty()) throw Error(where, "has an empty box (min > max on an axis)", "accepted: min <= max on every axis");
        for (int a = 0; a < 3; ++a)
            if (!withinIndexLimits(e.box.min[a], e.box.max[a]))
                throw Error(where, std::string("reaches outside the supported index range on ") + "xyz"[a], limits);
        return e.box;
    }
    if (!(e.radius > 0.0 && std::isfinite(e.radius)))
        throw Error(where, "has radius " + numberText(e.radius), "accepted: a finite radius > 0 world units");
    if (!std::isfinite(e.centre.x + e.centre.y + e.centre.z))
        throw Error(where, "has a non-finite centre", "accepted: finite world coordinates");
    // Voxel i's centre is at index i + 0.5; one voxel of slack, the exact test decides.
    const glm::dvec3 c = (e.centre - w.origin) / w.voxelSize - 0.5;
    const double r = e.radius / w.voxelSize;
    IndexBox box;
    for (int a = 0; a < 3; ++a) {
        const double lo = std::floor(c[a] - r), hi = std::ceil(c[a] + r);
        if (!withinIndexLimits(lo, hi))
            throw Error(where, std::string("reaches outside the supported index range on ") + "xyz"[a], limits);
        box.min[a] = int(lo), box.max[a] = int(hi);
    }
    return box;
}

IndexBox intersection(const IndexBox& a, const IndexBox& b) {
    return {glm::max(a.min, b.min), glm::min(a.max, b.max)};
}

// Bricks within `r` voxels of a point: at most the ball's volume in bricks.
double ballBricks(double r) {
    const double d = std::max(r, 0.0);
    return 4.0 / 3.0 * 3.14159265358979 * d * d * d / 512.0;
}

// The bricks an edit touches, and of those the ones it covers only in part.
// Every brick touching a sphere lies within a brick's diagonal of its surface
// or inside it, so a sphere's counts follow from its radius.
std::pair<double, double> bricksOf(const Edit& e, const IndexBox& region, const World::Impl& w) {
    double touched = 1.0, whole = 1.0;
    for (int a = 0; a < 3; ++a) {
        touched *= double((region.max[a] >> 3) - (region.min[a] >> 3) + 1);
        whole *= double(std::max(((region.max[a] + 1) >> 3) - ((region.min[a] + 7) >> 3), 0));
    }
    if (e.shape == Edit::Shape::Box) return {touched, touched - whole};
    const double r = e.radius / w.voxelSize, diagonal = 8.0 * std::sqrt(3.0);
    const double ball = ballBricks(r + diagonal);
    return {std::min(touched, ball), std::min(touched, ball - ballBricks(r - diagonal))};
}

// An edit's memory, estimated before any voxel changes and refused when the world
// after it could pass the budget, as a grid that large is on load: the world's
// bricks and those a fill may add (kBytesPerBrick each, tiles included), a leaf
// for each brick the edit covers in part (a whole brick becomes a tile; a carve
// or a paint splits only tiles, as other bricks are leaves or empty already),
// and the per-voxel material grid when the edit brings in a second material.
void requireEditFits(const Edit& e, const IndexBox& region, const World::Impl& w) {
    const auto [touched, partial] = bricksOf(e, region, w);
    const openvdb::MaskTree& tree = w.solid->tree();
    const double worldBricks = double(brickCount(tree)), worldLeaves = double(tree.leafCount());
    const bool fill = e.op == Edit::Op::Fill;
    const bool newMaterials = e.op != Edit::Op::Carve && !w.materials && e.material != w.uniformMaterial;
    const double bricks = worldBricks + (fill ? touched : 0.0);
    const double leaves = fill ? partial : std::min(partial, worldBricks - worldLeaves);
    const double leafBytes = double(kMaskLeafBytes + (w.materials || newMaterials ? kValueLeafBytes : 0));
    const double bytes = bricks * double(kBytesPerBrick) + leaves * leafBytes +
                         (newMaterials ? worldLeaves * double(kValueLeafBytes) : 0.0);
    if (bytes > double(memoryRoom(w.desc.memoryBudgetBytes)))
        throw Error("edit '" + describe(e) + "'", "could make the world " + overBudget(bricks, bytes, w.desc.memoryBudgetBytes),
                    "edit a smaller region, or raise 'memory_budget_mib' in the world file");
}

// The voxels an edit may change, once it is known to be in range and within the
// budget: its region, clipped to the world's bounds for a carve or a paint
// (they change solid voxels only). Throws grotto::Error (input).
IndexBox checkedRegion(const Edit& e, const World::Impl& w) {
    IndexBox region = regionOf(e, w);
    if (e.op != Edit::Op::Fill) region = intersection(region, w.bounds);
    if (!region.empty()) requireEditFits(e, region, w);
    return region;
}

// Drops the oldest records past the caps; an edit too large to record ends the
// undo history there (the edits before it cannot be undone without it).
void remember(EditHistory& h, const Edit& e, std::optional<UndoRecord> record) {
    h.log.push_back(e);
    if (!record) {
        h.undo.clear();
        h.undoBytes = 0;
        return;
    }
    h.undoBytes += EditHistory::bytesOf(*record);
    h.undo.push_back(std::move(*record));
    while (h.undo.size() > kMaxUndoEdits || h.undoBytes > kMaxUndoBytes) {
        h.undoBytes -= EditHistory::bytesOf(h.undo.front());
        h.undo.pop_front();
    }
}

}  // namespace

void World::check(const Edit& e) const { checkedRegion(e, *impl_); }

EditResult World::apply(const Edit& e) {
    Impl& w = *impl_;
    const IndexBox region = checkedRegion(e, w);
    if (region.empty()) return {};

    const bool sphere = e.shape == Edit::Shape::Sphere;
    const double r2 = e.radius * e.radius;
    auto distance2 = [&](glm::dvec3 p) { return glm::dot(p - e.centre, p - e.centre); };
    auto centreOf = [&](glm::ivec3 v) { return w.origin + (glm::dvec3(v) + 0.5) * w.voxelSize; };
    auto stateAfter = [&](int before) {
        return e.op == Edit::Op::Carve ? 0 : e.op == Edit::Op::Fill ? e.material : before != 0 ? e.material : 0;
    };
    Changes changes;
    UndoRecord record;
    bool recording = true;
    {
        VoxelStates states(w);
        auto editBrick = [&](glm::ivec3 b) {
            const IndexBox clip = intersection(region, {b, b + 7});
            bool whole = true;  // does the edit cover all of the clip?
            if (sphere) {  // a brick wholly outside the sphere holds none of it
                const glm::dvec3 lo = w.origin + glm::dvec3(clip.min) * w.voxelSize;
                const glm::dvec3 hi = w.origin + glm::dvec3(clip.max + 1) * w.voxelSize;
                if (distance2(glm::clamp(e.centre, lo, hi)) > r2) return;
                const glm::dvec3 near = centreOf(clip.min), far = centreOf(clip.max);
                whole = distance2(glm::mix(near, far, glm::greaterThan(glm::abs(far - e.centre), glm::abs(near - e.centre)))) <= r2;
            }
            if (const std::optional<int> before = whole ? states.uniform(coord(b)) : std::nullopt) {
                const int after = stateAfter(*before);
                if (after == *before) return;
                states.setBox(clip, after);
                changes.add(clip, *before, after);
                if (recording) {
                    record.boxes.push_back({clip, *before});
                    recording = EditHistory::bytesOf(record) <= kMaxUndoBytes;
                }
                return;
            }
            for (int x = clip.min.x; x <= clip.max.x; ++x)
                for (int y = clip.min.y; y <= clip.max.y; ++y)
                    for (int z = clip.min.z; z <= clip.max.z; ++z) {
                        const glm::ivec3 v(x, y, z);
                        if (sphere && distance2(centreOf(v)) > r2) continue;
                        const openvdb::Coord c = coord(v);
                        const int before = states.get(c);
                        const int after = stateAfter(before);
                        if (before == after) continue;
                        states.set(c, after);
                        changes.add(v, before, after);
                        if (recording) {
                            record.before.push_back({v, before});
                            recording = EditHistory::bytesOf(record) <= kMaxUndoBytes;
                        }
                    }
        };
        if (e.op == Edit::Op::Fill) {
            for (int bx = region.min.x & ~7; bx <= region.max.x; bx += 8)
                for (int by = region.min.y & ~7; by <= region.max.y; by += 8)
                    for (int bz = region.min.z & ~7; bz <= region.max.z; bz += 8) editBrick({bx, by, bz});
        } else {
            // Carve and paint change solid voxels only: the bricks that have some.
            for (const Brick& b : bricks(region)) editBrick(b.origin);
        }
        record.createdMaterials = states.createdMaterials();
    }
    if (changes.count == 0) return {};
    dropEmptyLeaves(w, std::move(changes.emptiedBricks));
    updateBounds(w, changes);
    remember(w.history, e, recording ? std::optional<UndoRecord>(std::move(record)) : std::nullopt);
    return resultOf(w, changes);
}

EditResult World::undo() {
    Impl& w = *impl_;
    EditHistory& h = w.history;
    if (h.undo.empty()) return {};
    UndoRecord record = std::move(h.undo.back());
    h.undo.pop_back();
    h.undoBytes -= EditHistory::bytesOf(record);
    h.log.pop_back();
    Changes changes;
    {
        VoxelStates states(w);
        for (const BoxBefore& b : record.boxes) {
            const int now = states.get(coord(b.box.min));  // the edit left the box one state
            states.setBox(b.box, b.material);
            changes.add(b.box, now, b.material);
        }
        for (const VoxelBefore& v : record.before) {
            const openvdb::Coord c = coord(v.voxel);
            const int now = states.get(c);
            states.set(c, v.material);
            changes.add(v.voxel, now, v.material);
        }
    }
    // Every solid voxel is of the uniform material again: the grid made for the
    // edit goes with it, and the world saves as the kind it was.
    if (record.createdMaterials) w.materials.reset();
    dropEmptyLeaves(w, std::move(changes.emptiedBricks));
    updateBounds(w, changes);
    return resultOf(w, changes);
}

size_t World::undoDepth() const { return impl_->history.undo.size(); }

const std::vector<Edit>& World::editLog() const { return impl_->history.log; }

}  // namespace grotto::voxel
