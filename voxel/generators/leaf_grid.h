#pragma once
// An int32 material grid built leaf by leaf in parallel: the generators whose
// every voxel is a function of its coordinates (caves, mine) make each 8^3 leaf
// on its own, so the result ignores thread count and order.
#include "voxel/openvdb_grids.h"

#include <functional>
#include <memory>
#include <vector>

namespace grotto::voxel {

using MaterialLeaf = openvdb::Int32Tree::LeafNodeType;
constexpr int kLeafDim = int(MaterialLeaf::DIM);  // 8

// The leaf at `origin`, or null where it holds nothing solid.
using MakeLeaf = std::function<std::unique_ptr<MaterialLeaf>(const openvdb::Coord& origin)>;

// The grid of the leaves `makeLeaf` gives at `origins` (leaf-aligned, distinct).
openvdb::Int32Grid::Ptr gridFromLeaves(const std::vector<openvdb::Coord>& origins, const MakeLeaf& makeLeaf,
                                       double voxelSize);

// v rounded down to a multiple of step (toward minus infinity).
int floorTo(int v, int step);

}  // namespace grotto::voxel
