// World::save: the world's voxels back into a .vdb that World::load reads as the
// same voxels and materials, with the source grid's name, transform and metadata.
#include "common/error.h"
#include "voxel/solid.h"

#include <algorithm>
#include <cctype>

namespace grotto::voxel {
namespace {

// Material ids when the grid's kind alone cannot say them (a bare .vdb that is
// not int32 loads as material 1); otherwise the solid voxels as a mask, or as a
// bool grid for a bool source. Level sets and fog volumes become masks: their
// values are not kept by the world, only which voxels are solid.
openvdb::GridBase::Ptr voxelGrid(const World::Impl& w) {
    if (w.materials) {
        auto ids = w.materials->deepCopy();
        ids->tree().topologyIntersection(w.solid->tree());  // active = solid, nothing more
        return ids;
    }
    if (w.uniformMaterial != 1)
        return openvdb::Int32Grid::create(
            std::make_shared<openvdb::Int32Tree>(w.solid->tree(), 0, w.uniformMaterial, openvdb::TopologyCopy()));
    if (w.sourceType == openvdb::BoolGrid::gridType())
        return openvdb::BoolGrid::create(
            std::make_shared<openvdb::BoolTree>(w.solid->tree(), false, true, openvdb::TopologyCopy()));
    return w.solid->deepCopy();
}

}  // namespace

void World::save(const std::filesystem::path& path) const {
    std::string ext = path.extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
    if (ext != ".vdb") throw Error(path.string(), "a world is saved as an OpenVDB file", "name it with .vdb");
    const Impl& w = *impl_;
    openvdb::GridBase::Ptr grid = voxelGrid(w);
    // OpenVDB writes the file_* statistics afresh; the source's would be stale.
    if (w.sourceMeta)
        for (auto it = w.sourceMeta->beginMeta(); it != w.sourceMeta->endMeta(); ++it)
            if (it->first.rfind("file_", 0) != 0) grid->insertMeta(it->first, *it->second);
    grid->setName(w.gridName);
    grid->setTransform(w.solid->transform().copy());
    grid->setGridClass(openvdb::GRID_UNKNOWN);  // no longer a level set or fog volume, if it was
    writeGridFile(grid, path);
}

}  // namespace grotto::voxel
