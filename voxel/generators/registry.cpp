// The table of world kinds: option checks, dispatch, and writing the .vdb.
#include "common/file_kind.h"
#include "common/atomic_file.h"
#include "grotto/error.h"
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
openvdb::GridBase::Ptr generateHouses(const GeneratorOptions& options);
openvdb::GridBase::Ptr generateMine(const GeneratorOptions& options);

namespace {

// Upper bounds on each kind's bricks and leaves at size S, from how it builds
// (the comments at the top of each generator). B is the footprint's extent in
// bricks, one more on each side for a box that straddles brick boundaries.
double across(int S) { return S / 8.0 + 2.0; }
double ball(double radius) { return 4.0 / 3.0 * 3.14159265358979 * std::pow(std::max(radius, 0.0), 3.0) / 512.0; }
const double kDiagonal = 8.0 * std::sqrt(3.0);  // of a brick, in voxels

GeneratedSize roomsSize(int S) {  // a floor slab, 7 walls 3 thick and S/2 high, small furniture
    const double B = across(S), rows = std::max(12, S / 2) / 8.0 + 2.0;
    const double bricks = B * B + 7 * 2 * B * rows + B + 256;
    return {bricks, bricks, kValueLeafBytes};
}
GeneratedSize cavesSize(int S) {  // every column at most 96 voxels (12 bricks) high
    const double B = across(S);
    return {12 * B * B, 12 * B * B, kValueLeafBytes};
}
GeneratedSize thinSize(int S) {  // a floor slab, fences and poles along two sides, small fixed pieces
    const double B = across(S);
    return {B * B + 5 * B + 128, B * B + 5 * B + 128, kMaskLeafBytes};
}
GeneratedSize citySize(int S) {  // 17 brick rows from the slab to the tallest roof; walls on brick boundaries
    const double B = across(S);
    return {17 * B * B, 4 * B * B, kValueLeafBytes};  // leaves: the pavement and up to three roofs
}
GeneratedSize sphereSize(int S) {  // a ball of diameter S, its surface in a band of 3 voxels a side
    const double r = S / 2.0;
    return {ball(r + kDiagonal), ball(r + 3 + kDiagonal) - ball(r - 3 - kDiagonal), kValueLeafBytes};
}
GeneratedSize housesSize(int S) {  // a ground slab, three houses of 12 x 9 x 12 voxels: 3^3 bricks each at most
    const double B = across(S);
    return {B * B + 3 * 27, B * B + 3 * 27, kValueLeafBytes};
}
GeneratedSize mineSize(int S) {  // a block of rock 40 voxels (5 bricks) high over the footprint
    const double B = across(S);
    return {5 * B * B, 5 * B * B, kValueLeafBytes};
}
GeneratedSize meshSize(int S) {  // whatever the mesh, within a cube of S
    const double B = across(S);
    return {B * B * B, B * B * B, kValueLeafBytes};
}

struct Kind {
    std::string name;
    int defaultSize;
    int maxSize;
    const char* gridName;  // the convention in generators.h
    openvdb::GridBase::Ptr (*generate)(const GeneratorOptions&);
    GeneratedSize (*size)(int);
};

const std::vector<Kind>& kinds() {
    static const std::vector<Kind> table = {
        {"rooms", 64, 4096, "material", generateRooms, roomsSize},
        {"caves", 256, 4096, "material", generateCaves, cavesSize},
        {"thin", 64, 4096, "solid", generateThin, thinSize},
        {"city", 1024, 4096, "material", generateCity, citySize},
        {"sphere", 64, 4096, "surface", generateSphere, sphereSize},
        {"mesh", 128, 1024, "surface", generateMesh, meshSize},
        {"houses", 64, 4096, "material", generateHouses, housesSize},
        {"mine", 80, 1024, "material", generateMine, mineSize},
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
    if (options.lamps && kind.name != "houses")
        throw Error("--lamps", "only the houses kind has lamps, not " + kind.name, "drop --lamps, or make houses");
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

GeneratedSize generatedSize(const std::string& kindName, const GeneratorOptions& options) {
    const Kind& kind = findKind(kindName);
    return kind.size(resolve(kind, options).size);
}

void makeWorldFile(const std::string& kind, const GeneratorOptions& options,
                   const std::filesystem::path& out) {
    if (lowerExtension(out) != ".vdb")
        throw Error(out.string(), "the output of mkworld is an OpenVDB file", "name it with .vdb");
    requireOutputPath(out);  // fail before a long generation, not after
    openvdb::GridBase::Ptr grid = generateWorld(kind, options);
    writeGridFile(grid, out);
}

}  // namespace grotto::voxel
