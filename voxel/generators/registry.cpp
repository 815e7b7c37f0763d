// The table of world kinds: option checks, dispatch, and writing the .vdb.
#include "common/atomic_file.h"
#include "common/error.h"
#include "voxel/generators.h"
#include "voxel/solid.h"

#include <algorithm>
#include <cctype>
#include <cmath>

namespace grotto::voxel {

// Defined one per file in voxel/generators/. `size` is already resolved and checked.
openvdb::GridBase::Ptr generateRooms(const GeneratorOptions& options);
openvdb::GridBase::Ptr generateCaves(const GeneratorOptions& options);
openvdb::GridBase::Ptr generateThin(const GeneratorOptions& options);
openvdb::GridBase::Ptr generateCity(const GeneratorOptions& options);
openvdb::GridBase::Ptr generateSphere(const GeneratorOptions& options);
openvdb::GridBase::Ptr generateMesh(const GeneratorOptions& options);

namespace {

struct Kind {
    std::string name;
    int defaultSize;
    int maxSize;
    const char* gridName;  // the convention in generators.h
    openvdb::GridBase::Ptr (*generate)(const GeneratorOptions&);
};

const std::vector<Kind>& kinds() {
    static const std::vector<Kind> table = {
        {"rooms", 64, 4096, "material", generateRooms},
        {"caves", 256, 4096, "material", generateCaves},
        {"thin", 64, 4096, "solid", generateThin},
        {"city", 1024, 4096, "material", generateCity},
        {"sphere", 64, 4096, "surface", generateSphere},
        {"mesh", 128, 1024, "surface", generateMesh},
    };
    return table;
}

std::string kindList() {
    std::string s;
    for (const Kind& k : kinds()) s += (s.empty() ? "" : ", ") + k.name;
    return s;
}

const Kind& findKind(const std::string& name) {
    for (const Kind& k : kinds())
        if (k.name == name) return k;
    throw Error("mkworld", "unknown world kind '" + name + "'", "accepted: " + kindList());
}

GeneratorOptions resolve(const Kind& kind, GeneratorOptions options) {
    if (options.size == 0) options.size = kind.defaultSize;
    if (options.size < 8 || options.size > kind.maxSize)
        throw Error("--size", std::to_string(options.size) + " is out of range for " + kind.name,
                    "accepted: 8.." + std::to_string(kind.maxSize) +
                        " voxels, or 0 for the default " + std::to_string(kind.defaultSize));
    if (!std::isfinite(options.voxelSize) || options.voxelSize <= 0.0)
        throw Error("--voxel-size", "voxel size must be a positive number",
                    "e.g. 1.0 or 0.25 world units per voxel");
    if (kind.name == "mesh" && options.meshFile.empty())
        throw Error("--mesh", "the mesh kind needs a mesh file", "give an .obj or ASCII .ply file");
    return options;
}

}  // namespace

const std::vector<std::string>& worldKinds() {
    static const std::vector<std::string> names = [] {
        std::vector<std::string> v;
        for (const Kind& k : kinds()) v.push_back(k.name);
        return v;
    }();
    return names;
}

openvdb::GridBase::Ptr generateWorld(const std::string& kindName, const GeneratorOptions& options) {
    const Kind& kind = findKind(kindName);
    const GeneratorOptions resolved = resolve(kind, options);
    initializeOpenVdb();
    openvdb::GridBase::Ptr grid = kind.generate(resolved);
    grid->setName(kind.gridName);
    grid->insertMeta("grotto_kind", openvdb::StringMetadata(kind.name));
    grid->insertMeta("grotto_seed", openvdb::Int64Metadata(static_cast<int64_t>(resolved.seed)));
    return grid;
}

void makeWorldFile(const std::string& kind, const GeneratorOptions& options,
                   const std::filesystem::path& out) {
    std::string ext = out.extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(),
                   [](unsigned char c) { return std::tolower(c); });
    if (ext != ".vdb")
        throw Error(out.string(), "the output of mkworld is an OpenVDB file", "name it with .vdb");
    requireOutputPath(out);  // fail before a long generation, not after
    openvdb::GridBase::Ptr grid = generateWorld(kind, options);
    writeGridFile(grid, out);
}

}  // namespace grotto::voxel
