#pragma once
// What meshing a world takes in memory, counted before it is done: every chunk is
// meshed and welded as voxel::LiveMesh does it, measured and dropped, so the count
// needs the chunks' rectangles and boundary corners (a part of what it counts),
// not the whole mesh.
#include "voxel/live_mesh.h"

#include <cstdint>

namespace grotto::voxel {

// The heap bytes of one allocation of `bytes` (glibc: an 8-byte header, rounded to
// 16, 32 at least; none for nothing asked).
uint64_t heapBytes(uint64_t bytes);

struct MeshFootprint {
    uint64_t quads = 0;      // every level's
    uint64_t liveBytes = 0;  // a LiveMesh of them: its map, and each chunk's vectors at the capacity they grow to
    uint64_t listBytes = 0;  // LiveMesh::list()'s copy of them (exact capacities)
    uint64_t cornerBytes = 0;  // the boundary corners LiveMesh welds with, held while it welds
    bool complete = true;      // false: stopped early, and liveBytes + listBytes is a lower bound
};

// LiveMesh(world, options) and its list(), counted chunk by chunk. The count
// stops once liveBytes + listBytes of the chunks counted so far pass
// `stopAbove`: a mesh far over a budget is refused at the budget's cost, not its own.
MeshFootprint countMeshFootprint(const World& world, const MeshOptions& options, uint64_t stopAbove = UINT64_MAX);

// The same figures for a mesh already made.
MeshFootprint measureMesh(const LiveMesh& mesh);

}  // namespace grotto::voxel
