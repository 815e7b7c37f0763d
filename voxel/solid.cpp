// The solid rule: which voxels of a grid are solid, and of what material.
#include "grotto/error.h"
#include "voxel/solid.h"

#include <openvdb/tools/LevelSetUtil.h>

#include <atomic>
#include <cmath>

namespace grotto::voxel {
namespace {

SolidRule ruleFor(const openvdb::GridBase& grid, SolidRule asked, const std::string& where) {
    const bool scalar = grid.isType<openvdb::FloatGrid>() || grid.isType<openvdb::DoubleGrid>();
    const bool mask = grid.isType<openvdb::BoolGrid>() || grid.isType<openvdb::MaskGrid>();
    const bool int32 = grid.isType<openvdb::Int32Grid>();
    const std::string supported =
        "supported: float/double (level set or fog volume), bool, mask, int32";
    if (!scalar && !mask && !int32)
        throw Error(where, "has unsupported grid type '" + grid.valueType() + "'", supported);
    SolidRule rule = asked;
    if (rule == SolidRule::Auto) {
        if (mask) rule = SolidRule::Mask;
        else if (int32) rule = SolidRule::Int32;
        else if (grid.getGridClass() == openvdb::GRID_LEVEL_SET) rule = SolidRule::LevelSet;
        else if (grid.getGridClass() == openvdb::GRID_FOG_VOLUME) rule = SolidRule::Fog;
        else
            throw Error(where, "is a " + grid.valueType() + " grid of unknown class",
                        "set 'grid.rule' to level_set or fog in the world file");
    }
    const bool fits = (rule == SolidRule::LevelSet || rule == SolidRule::Fog) ? scalar
                      : rule == SolidRule::Mask ? mask
                                                : int32;
    if (!fits)
        throw Error(where, std::string("rule '") + solidRuleName(rule) + "' does not apply to a " +
                    grid.valueType() + " grid", supported);
    return rule;
}

// Copies the active topology, then switches off what the predicate rejects:
// tiles as whole blocks, voxels one by one.
template <typename GridT, typename Keep>
openvdb::MaskGrid::Ptr activeWhere(const GridT& grid, Keep keep) {
    auto solid = openvdb::MaskGrid::create();
    solid->setTransform(grid.transform().copy());
    solid->tree().topologyUnion(grid.tree());
    openvdb::MaskGrid::Accessor acc = solid->getAccessor();
    for (auto it = grid.cbeginValueOn(); it; ++it) {
        if (keep(*it)) continue;
        if (it.isVoxelValue()) {
            acc.setValueOff(it.getCoord());
        } else {
            openvdb::CoordBBox box;
            it.getBoundingBox(box);
            solid->tree().fill(box, false, false);
        }
    }
    solid->tree().prune();
    return solid;
}

// A NaN or infinite value has no side of a level set or threshold: the grid is
// damaged, and guessing would make holes or walls out of it.
template <typename FloatT>
void requireFinite(const FloatT& grid, const std::string& where) {
    auto refuse = [&](const std::string& at) {
        throw Error(where, "holds a NaN or infinite value " + at, "every value of a float grid must be finite");
    };
    if (!std::isfinite(grid.background())) refuse("as its background");
    for (auto it = grid.cbeginValueAll(); it; ++it)
        if (!std::isfinite(*it)) {
            const openvdb::Coord c = it.getCoord();
            refuse("at index (" + std::to_string(c.x()) + ", " + std::to_string(c.y()) + ", " +
                   std::to_string(c.z()) + ")");
        }
}

template <typename FloatT>
openvdb::MaskGrid::Ptr levelSetInterior(const FloatT& grid) {
    // sdfInteriorMask follows the sign into inactive interior tiles and voxels.
    auto interior = openvdb::tools::sdfInteriorMask(grid, typename FloatT::ValueType(0));
    auto solid = openvdb::MaskGrid::create();
    solid->setTransform(grid.transform().copy());
    solid->tree().topologyUnion(interior->tree());
    return solid;
}

}  // namespace

void buildSolid(const openvdb::GridBase::Ptr& grid, World::Impl& impl) {
    const WorldDesc& d = impl.desc;
    const std::string where = d.gridFile.string() + ": grid '" + grid->getName() + "'";
    const SolidRule rule = ruleFor(*grid, d.rule, where);
    impl.uniformMaterial = d.material;
    if (size_t(d.material) > d.materials.size())
        throw Error(d.source.string(), "field 'grid.material': id " + std::to_string(d.material) +
                    " has no entry in 'materials'", "the palette has " +
                    std::to_string(d.materials.size()) + " materials");
    if (auto f = openvdb::gridPtrCast<openvdb::FloatGrid>(grid)) requireFinite(*f, where);
    if (auto f = openvdb::gridPtrCast<openvdb::DoubleGrid>(grid)) requireFinite(*f, where);
    switch (rule) {
        case SolidRule::LevelSet:
            if (auto f = openvdb::gridPtrCast<openvdb::FloatGrid>(grid)) impl.solid = levelSetInterior(*f);
            else impl.solid = levelSetInterior(*openvdb::gridPtrCast<openvdb::DoubleGrid>(grid));
            break;
        case SolidRule::Fog: {
            const double t = d.threshold;
            if (auto f = openvdb::gridPtrCast<openvdb::FloatGrid>(grid))
                impl.solid = activeWhere(*f, [t](float v) { return v >= t; });
            else
                impl.solid = activeWhere(*openvdb::gridPtrCast<openvdb::DoubleGrid>(grid),
                                         [t](double v) { return v >= t; });
            break;
        }
        case SolidRule::Mask:
            impl.solid = openvdb::MaskGrid::create();
            impl.solid->setTransform(grid->transform().copy());
            if (auto b = openvdb::gridPtrCast<openvdb::BoolGrid>(grid)) impl.solid->tree().topologyUnion(b->tree());
            else impl.solid->tree().topologyUnion(openvdb::gridPtrCast<openvdb::MaskGrid>(grid)->tree());
            break;
        case SolidRule::Int32: {
            auto ints = openvdb::gridPtrCast<openvdb::Int32Grid>(grid);
            const int paletteSize = int(d.materials.size());
            int32_t bad = 0;
            impl.solid = activeWhere(*ints, [&](int32_t v) {
                if (v < 0 || v > paletteSize) bad = v;
                return v != 0;
            });
            if (bad != 0)
                throw Error(where, "holds material id " + std::to_string(bad) +
                            " outside the palette of " + std::to_string(paletteSize) + " materials",
                            "ids must be 1.." + std::to_string(paletteSize) + " ('materials' in the world file)");
            impl.materials = ints;
            break;
        }
        case SolidRule::Auto: break;
    }
    impl.solid->setName("solid");
}

}  // namespace grotto::voxel
