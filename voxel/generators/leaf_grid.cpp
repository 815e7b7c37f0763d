#include "voxel/generators/leaf_grid.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

namespace grotto::voxel {

openvdb::Int32Grid::Ptr gridFromLeaves(const std::vector<openvdb::Coord>& origins, const MakeLeaf& makeLeaf,
                                       double voxelSize) {
    std::vector<std::unique_ptr<MaterialLeaf>> leaves(origins.size());
    tbb::parallel_for(tbb::blocked_range<size_t>(0, origins.size(), 16), [&](const tbb::blocked_range<size_t>& r) {
        for (size_t n = r.begin(); n != r.end(); ++n) leaves[n] = makeLeaf(origins[n]);
    });
    auto grid = openvdb::Int32Grid::create(0);
    grid->setTransform(openvdb::math::Transform::createLinearTransform(voxelSize));
    grid->setName("material");
    for (auto& leaf : leaves)
        if (leaf) grid->tree().addLeaf(leaf.release());
    return grid;
}

int floorTo(int v, int step) { return v >= 0 ? v / step * step : -((-v + step - 1) / step) * step; }

}  // namespace grotto::voxel
