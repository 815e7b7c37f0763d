// World::voxelsByMaterial: every solid voxel's material, counted without
// visiting the voxels of a tile one at a time where the material grid holds one
// value over the whole tile (as it does where the solid tiles came from it).
#include "voxel/solid.h"

namespace grotto::voxel {
namespace {

// The edge of the cube that the material tree's value at `c` stands for: a leaf
// voxel, a tile at one of the two internal levels, or a root-level tile or gap.
int uniformEdge(const openvdb::Int32Grid::ConstAccessor& acc, const openvdb::Coord& c) {
    switch (acc.getValueDepth(c)) {
    case 3: return 1;
    case 2: return int(openvdb::Int32Tree::LeafNodeType::DIM);
    case 1: return int(openvdb::Int32Tree::RootNodeType::ChildNodeType::ChildNodeType::DIM);
    default: return int(openvdb::Int32Tree::RootNodeType::ChildNodeType::DIM);
    }
}

// Adds the materials of the aligned cube at `lo` with edge `edge` (a power of two), every voxel solid.
void countCube(const openvdb::Int32Grid::ConstAccessor& acc, const openvdb::Coord& lo, int edge,
               std::vector<uint64_t>& counts) {
    if (uniformEdge(acc, lo) >= edge) {
        const int id = std::max(acc.getValue(lo), 0);
        if (size_t(id) >= counts.size()) counts.resize(size_t(id) + 1, 0);
        counts[size_t(id)] += uint64_t(edge) * uint64_t(edge) * uint64_t(edge);
        return;
    }
    const int half = edge / 2;
    for (int i = 0; i < 8; ++i)
        countCube(acc, lo.offsetBy(i & 1 ? half : 0, i & 2 ? half : 0, i & 4 ? half : 0), half, counts);
}

}  // namespace

std::vector<uint64_t> World::voxelsByMaterial() const {
    std::vector<uint64_t> counts(1, 0);
    const openvdb::MaskTree& solid = impl_->solid->tree();
    if (!impl_->materials) {
        counts.resize(size_t(std::max(impl_->uniformMaterial, 0)) + 1, 0);
        counts[size_t(std::max(impl_->uniformMaterial, 0))] += solid.activeVoxelCount();
        return counts;
    }
    const openvdb::Int32Grid::ConstAccessor acc = impl_->materials->getConstAccessor();
    for (auto it = solid.cbeginValueOn(); it; ++it) {
        const openvdb::CoordBBox box = it.getBoundingBox();
        countCube(acc, box.min(), box.dim().x(), counts);
    }
    return counts;
}

}  // namespace grotto::voxel
