// Reading a grid from a .vdb as OpenVDB gives it, with the checks that need no
// voxels first (transform, budget). What the reader process runs (vdb_reader.cpp).
#include "voxel/vdb_read.h"
#include "common/number_text.h"

#include "grotto/error.h"
#include "voxel/world.h"

#include <cmath>
#include <cstdio>
#include <mutex>

namespace grotto::voxel {
namespace {

std::string gridNames(openvdb::io::File& file) {
    std::string s;
    for (auto it = file.beginName(); it != file.endName(); ++it)
        s += (s.empty() ? "" : ", ") + it.gridName();
    return s;
}

// A grid's in-memory size, estimated from the metadata OpenVDB writes with it.
size_t estimatedBytes(const openvdb::GridBase& meta) {
    if (auto m = meta.getMetadata<openvdb::Int64Metadata>("file_mem_bytes"))
        return size_t(m->value());
    return 0;
}

std::string mib(size_t bytes) {
    char buf[32];
    snprintf(buf, sizeof buf, "%.1f MiB", double(bytes) / (1 << 20));
    return buf;
}

}  // namespace

void initializeOpenVdb() {
    static std::once_flag once;
    std::call_once(once, [] { openvdb::initialize(); });
}

GridPlacement readTransform(const openvdb::GridBase& grid, const std::string& file) {
    const openvdb::math::Transform& xf = grid.transform();
    const openvdb::Vec3d vs = xf.voxelSize();
    const std::string where = file + ": grid '" + grid.getName() + "' transform";
    bool axisAligned = xf.isLinear();
    if (axisAligned) {
        const openvdb::Mat4d m = xf.baseMap()->getAffineMap()->getMat4();
        for (int r = 0; r < 3; ++r)
            for (int c = 0; c < 3; ++c)
                if (r != c ? std::abs(m(r, c)) > 1e-9 * vs.x() : m(r, c) <= 0.0) axisAligned = false;
    }
    if (!axisAligned)
        throw Error(where, "is not an axis-aligned scale and translation (" + xf.mapType() + ")",
                    "resample the grid to a uniform, unrotated voxel transform");
    const double tol = 1e-6 * vs.x();
    if (std::abs(vs.x() - vs.y()) > tol || std::abs(vs.x() - vs.z()) > tol)
        throw Error(where, "has non-uniform voxel size (" + std::to_string(vs.x()) + ", " +
                    std::to_string(vs.y()) + ", " + std::to_string(vs.z()) + ")",
                    "Grotto needs cubic voxels; resample with a uniform voxel size");
    if (!(vs.x() >= kMinVoxelSize && vs.x() <= kMaxVoxelSize))
        throw Error(where, "has voxel size " + numberText(vs.x()) + ", outside the supported range",
                    "supported: " + numberText(kMinVoxelSize) + " to " + numberText(kMaxVoxelSize) +
                        " world units; rescale the grid's transform");
    GridPlacement placement;
    placement.voxelSize = vs.x();
    // OpenVDB puts voxel centres at integer index coordinates; our voxel i spans [i, i+1).
    openvdb::Vec3d corner = xf.indexToWorld(openvdb::Vec3d(-0.5));
    for (int axis = 0; axis < 3; ++axis)
        if (!(std::abs(corner[axis]) <= kMaxWorldOffset))
            throw Error(where, "places voxel 0 at " + numberText(corner[axis]) + " on " + "xyz"[axis] +
                                   ", outside the supported range",
                        "supported: translations within +-" + numberText(kMaxWorldOffset) + " world units");
    placement.origin = glm::dvec3(corner.x(), corner.y(), corner.z());
    return placement;
}

openvdb::GridBase::Ptr readGridUnguarded(const WorldDesc& desc, const std::function<void(size_t)>& onEstimate,
                                         const std::filesystem::path& openAs) {
    initializeOpenVdb();
    const std::string path = desc.gridFile.string();
    openvdb::io::File file(openAs.empty() ? path : openAs.string());
    try {
        file.open(false);  // no delayed loading: a truncated file fails here or in readGrid
    } catch (const std::bad_alloc&) {
        throw;  // the reader's memory limit: reported as such
    } catch (const std::exception& e) {
        throw Error(path, std::string("is not a readable OpenVDB file: ") + e.what(),
                    "expected a .vdb written by OpenVDB");
    }
    std::string name = desc.gridName;
    if (name.empty()) {
        if (file.beginName() == file.endName())
            throw Error(path, "contains no grids", "write at least one grid into the file");
        name = file.beginName().gridName();
    } else if (!file.hasGrid(name)) {
        throw Error(path, "has no grid named '" + name + "'",
                    "grids in the file: " + gridNames(file));
    }
    openvdb::GridBase::Ptr grid;
    try {
        openvdb::GridBase::Ptr meta = file.readGridMetadata(name);
        readTransform(*meta, path);  // refuses a bad transform before any voxels are read
        const size_t estimate = estimatedBytes(*meta);
        if (estimate > desc.memoryBudgetBytes)
            throw Error(path, "grid '" + name + "' needs an estimated " + mib(estimate) +
                        ", more than the memory budget of " + mib(desc.memoryBudgetBytes),
                        "raise 'memory_budget_mib' in the world file or use a smaller grid");
        if (onEstimate) onEstimate(estimate);
        grid = file.readGrid(name);
    } catch (const Error&) {
        throw;
    } catch (const std::bad_alloc&) {
        throw;  // the reader's memory limit: reported as such
    } catch (const std::exception& e) {
        throw Error(path, "grid '" + name + "' cannot be read: " + e.what(),
                    "the file may be truncated or damaged");
    }
    file.close();
    return grid;
}

}  // namespace grotto::voxel
