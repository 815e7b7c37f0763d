#include "voxel/object_worlds.h"

#include "grotto/error.h"
#include "voxel/generators.h"
#include "voxel/solid.h"

#include <cmath>

namespace grotto::voxel {
namespace {

// A solid box of `size` voxels from index 0, every voxel `material` (an int32
// grid): whole 8^3 blocks and larger are active tiles, so a large box costs its
// faces, not its volume.
openvdb::GridBase::Ptr boxGrid(glm::ivec3 size, int material, double voxelSize) {
    auto grid = openvdb::Int32Grid::create(0);
    grid->setTransform(openvdb::math::Transform::createLinearTransform(voxelSize));
    grid->fill(openvdb::CoordBBox(openvdb::Coord(0), openvdb::Coord(size.x - 1, size.y - 1, size.z - 1)), material, true);
    grid->setName("material");
    return grid;
}

GeneratedSize boxSize(glm::ivec3 size) {
    double bricks = 1.0, whole = 1.0;
    for (int a = 0; a < 3; ++a) bricks *= std::ceil(size[a] / 8.0), whole *= std::floor(size[a] / 8.0);
    return {bricks, bricks - whole, kValueLeafBytes};
}

// A generator's error names mkworld's flags: named here as the object's field in the world file.
Error asObjectField(const WorldDesc& world, const std::string& field, const Error& e) {
    return Error(world.source.string(), "field '" + field + ".generator': " + e.problem(), e.hint());
}

// A generated object is refused from its size alone, before any of it is made,
// when the world made of it could pass the budget: kBytesPerBrick a brick (tiles
// included, as on load) and its grid's and the solid mask's leaves.
void requireGeneratedFits(const WorldDesc& world, const ObjectDesc& o, const std::string& field) {
    GeneratedSize s;
    try {
        s = o.generator == "box" ? boxSize(o.boxSize) : generatedSize(o.generator, o.generatorOptions);
    } catch (const Error& e) {
        throw asObjectField(world, field, e);
    }
    const double bytes = s.bricks * double(kBytesPerBrick) + s.leaves * double(s.leafBytes + kMaskLeafBytes);
    if (bytes > double(memoryRoom(world.memoryBudgetBytes)))
        throw Error(world.source.string(),
                    "field '" + field + ".generator.size': object '" + o.name + "' could make " +
                        overBudget(s.bricks, bytes, world.memoryBudgetBytes),
                    "make it smaller, or raise 'memory_budget_mib' in the world file");
}

// The object's voxels, from its grid file or its generator.
World objectVoxels(const WorldDesc& world, const ObjectDesc& o, const std::string& field) {
    WorldDesc d;
    d.source = o.gridFile.empty() ? world.source : o.gridFile;
    d.gridFile = o.gridFile;
    d.gridName = o.gridName;
    d.rule = o.rule;
    d.threshold = o.threshold;
    d.material = o.material;
    d.materials = world.materials;
    d.lighting = world.lighting;
    d.memoryBudgetBytes = world.memoryBudgetBytes;
    if (!o.gridFile.empty()) {
        openvdb::GridBase::Ptr grid = loadGrid(d);  // before d moves into the world
        return makeWorld(grid, std::move(d));
    }
    requireGeneratedFits(world, o, field);
    try {
        openvdb::GridBase::Ptr grid = o.generator == "box" ? boxGrid(o.boxSize, o.material, o.generatorOptions.voxelSize)
                                                           : generateWorld(o.generator, o.generatorOptions);
        return makeWorld(grid, std::move(d));
    } catch (const Error& e) {
        throw asObjectField(world, field, e);
    }
}

World loadObject(const WorldDesc& world, const ObjectDesc& o, const std::string& field) {
    World w = objectVoxels(world, o, field);
    if (w.bounds().empty())
        throw Error(world.source.string(), "field '" + field + "': object '" + o.name + "' has no solid voxels",
                    "check its grid, rule and threshold");
    return w;
}

}  // namespace

void requireObjectsFit(const WorldDesc& desc) {
    for (size_t i = 0; i < desc.objects.size(); ++i)
        if (desc.objects[i].gridFile.empty()) requireGeneratedFits(desc, desc.objects[i], "objects[" + std::to_string(i) + "]");
}

std::vector<World> loadObjectWorlds(const WorldDesc& desc) {
    requireObjectsFit(desc);  // all of them before any is made
    std::vector<World> out;
    out.reserve(desc.objects.size());
    for (size_t i = 0; i < desc.objects.size(); ++i)
        out.push_back(loadObject(desc, desc.objects[i], "objects[" + std::to_string(i) + "]"));
    return out;
}

}  // namespace grotto::voxel
