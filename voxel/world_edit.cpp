// Edits on the grid: fill, carve and paint over boxes and spheres, and their undo.
// Every edit walks its region brick by brick, changes only voxels whose state
// (material id, 0 = empty) differs, and remembers their prior states for undo.
#include "common/error.h"
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
    bool createdMaterials() const { return created_; }
    // Does the brick at b (8-aligned) hold any solid voxel?
    bool anySolid(const openvdb::Coord& b) {
        if (const auto* leaf = solid_.probeConstLeaf(b)) return !leaf->isEmpty();
        return solid_.isValueOn(b);  // an active tile covers the whole brick
    }

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

// What changed, gathered as voxels change.
struct Changes {
    IndexBox voxels, nowSolid, nowEmpty;
    uint64_t count = 0;
    std::vector<glm::ivec3> emptiedBricks;

    void add(glm::ivec3 v, int before, int after) {
        const IndexBox one{v, v};
        voxels = voxels.merged(one);
        ++count;
        if (after == 0) {
            nowEmpty = nowEmpty.merged(one);
            if (emptiedBricks.empty() || emptiedBricks.back() != (v & ~7)) emptiedBricks.push_back(v & ~7);
        } else if (before == 0) {
            nowSolid = nowSolid.merged(one);
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

std::string num(double d) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%g", d);
    return buf;
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
        throw Error(where, "has radius " + num(e.radius), "accepted: a finite radius > 0 world units");
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

// A fill may create a brick per 8^3 voxels of its region: refused up front when
// that would pass the world's memory budget, as a grid that large is on load.
void requireFillFits(const Edit& e, const IndexBox& region, const World::Impl& w) {
    double bricks = 1.0;
    for (int a = 0; a < 3; ++a) bricks *= double((region.max[a] >> 3) - (region.min[a] >> 3) + 1);
    const double bytes = bricks * double(kBytesPerBrick);
    if (bytes > double(w.desc.memoryBudgetBytes))
        throw Error("edit '" + describe(e) + "'", "could make " + num(bricks) + " bricks of 8^3 voxels, an estimated " +
                                                      num(bytes / (1 << 20)) + " MiB, more than the memory budget of " +
                                                      num(double(w.desc.memoryBudgetBytes) / (1 << 20)) + " MiB",
                    "fill a smaller region, or raise 'memory_budget_mib' in the world file");
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

EditResult World::apply(const Edit& e) {
    Impl& w = *impl_;
    IndexBox region = regionOf(e, w);
    // Carve and paint change solid voxels only, and those lie within the bounds.
    if (e.op != Edit::Op::Fill) region = intersection(region, w.bounds);
    else requireFillFits(e, region, w);
    if (region.empty()) return {};

    const bool sphere = e.shape == Edit::Shape::Sphere;
    const double r2 = e.radius * e.radius;
    auto distance2 = [&](glm::dvec3 p) { return glm::dot(p - e.centre, p - e.centre); };
    Changes changes;
    UndoRecord record;
    bool recording = true;
    {
        VoxelStates states(w);
        auto editBrick = [&](glm::ivec3 b) {
            const IndexBox clip = intersection(region, {b, b + 7});
            if (sphere) {  // a brick wholly outside the sphere holds none of it
                const glm::dvec3 lo = w.origin + glm::dvec3(clip.min) * w.voxelSize;
                const glm::dvec3 hi = w.origin + glm::dvec3(clip.max + 1) * w.voxelSize;
                if (distance2(glm::clamp(e.centre, lo, hi)) > r2) return;
            }
            for (int x = clip.min.x; x <= clip.max.x; ++x)
                for (int y = clip.min.y; y <= clip.max.y; ++y)
                    for (int z = clip.min.z; z <= clip.max.z; ++z) {
                        const glm::ivec3 v(x, y, z);
                        if (sphere && distance2(w.origin + (glm::dvec3(v) + 0.5) * w.voxelSize) > r2) continue;
                        const openvdb::Coord c = coord(v);
                        const int before = states.get(c);
                        const int after = e.op == Edit::Op::Carve  ? 0
                                          : e.op == Edit::Op::Fill ? e.material
                                          : before != 0            ? e.material
                                                                   : 0;
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
