// World::save: the world's voxels back into a .vdb, with the source grid's name,
// transform and metadata, and beside it the world file naming that .vdb with
// every setting, camera, path and object: World::load of it is the same world.
#include "common/atomic_file.h"
#include "common/file_kind.h"
#include "grotto/error.h"
#include "voxel/solid.h"
#include "voxel/world_json.h"

#include <algorithm>
#include <cctype>
#include <fstream>

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

World::SavedFiles World::save(const std::filesystem::path& path) const { return save(path, impl_->desc); }

World::SavedFiles World::save(const std::filesystem::path& path, const WorldDesc& settings) const {
    namespace fs = std::filesystem;
    const std::string ext = lowerExtension(path);
    if (ext != ".vdb" && ext != ".json")
        throw Error(path.string(), "a world is saved as a world file and its grid, FILE.json and FILE.vdb",
                    "name either of them (FILE.json or FILE.vdb): both are written");
    const fs::path vdb = ext == ".vdb" ? path : fs::path(path).replace_extension(".vdb");
    const fs::path file = ext == ".json" ? path : fs::path(path).replace_extension(".json");
    requireOutputPath(file);  // before the grid is written, so a bad target writes nothing
    const Impl& w = *impl_;
    openvdb::GridBase::Ptr grid = voxelGrid(w);
    // OpenVDB writes the file_* statistics afresh; the source's would be stale.
    if (w.sourceMeta)
        for (auto it = w.sourceMeta->beginMeta(); it != w.sourceMeta->endMeta(); ++it)
            if (it->first.rfind("file_", 0) != 0) grid->insertMeta(it->first, *it->second);
    grid->setName(w.gridName);
    grid->setTransform(w.solid->transform().copy());
    grid->setGridClass(openvdb::GRID_UNKNOWN);  // no longer a level set or fog volume, if it was
    writeGridFile(grid, vdb);

    // The world file names the grid as just written: its voxels are the solid ones.
    WorldDesc saved = settings;
    saved.gridFile = vdb;
    saved.gridName = w.gridName;
    saved.rule = grid->isType<openvdb::Int32Grid>() ? SolidRule::Int32 : SolidRule::Mask;
    saved.threshold = WorldDesc{}.threshold;
    saved.material = w.uniformMaterial;
    const std::string text = worldFileJson(saved, file.parent_path()).dump(2, ' ', false, json::error_handler_t::replace);
    writeAtomically(file, text + "\n");
    return {file, vdb};
}

}  // namespace grotto::voxel
