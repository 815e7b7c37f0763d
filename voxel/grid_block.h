#pragma once
// The "grid" block a world file and each of its objects give: the .vdb (relative
// to the file naming it), the grid's name and the rule that makes it solid.
// Internal to voxel/: it reads through the strict JSON reader.
#include "voxel/json_reader.h"
#include "voxel/world_desc.h"

#include <filesystem>
#include <string>

namespace grotto::voxel {

// Reads a solid rule field; "auto" when absent.
SolidRule parseSolidRule(Reader& reader, const std::string& key);

// Fills the grid fields (gridFile, gridName, rule, threshold, material) that
// WorldDesc and ObjectDesc share.
template <typename Desc>
void readGridBlock(Reader g, const std::filesystem::path& file, Desc& d) {
    if (!g.has("file")) g.fail("file", "missing");
    const std::string f = g.string("file", "");
    if (f.empty()) g.fail("file", "must not be empty");
    d.gridFile = std::filesystem::path(f).is_absolute() ? std::filesystem::path(f) : file.parent_path() / f;
    d.gridName = g.string("name", "");
    d.rule = parseSolidRule(g, "rule");
    d.threshold = g.number("threshold", d.threshold, -1e30, 1e30);
    d.material = int(g.integer("material", d.material, 1, 255));
}

}  // namespace grotto::voxel
