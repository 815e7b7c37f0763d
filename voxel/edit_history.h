#pragma once
// Internal to voxel/: what a World remembers of its edits, to undo them and to
// say how its voxels differ from its file. Plain data, OpenVDB-free.
#include "voxel/edit.h"

#include <cstddef>
#include <cstdint>
#include <deque>
#include <vector>

namespace grotto::voxel {

// A voxel's state before an edit changed it: its material id, 0 = empty.
struct VoxelBefore {
    glm::ivec3 voxel;
    int32_t material;
};

// A box within one brick whose voxels all had one state before an edit changed them all.
struct BoxBefore {
    IndexBox box;
    int32_t material;
};

struct UndoRecord {
    std::vector<VoxelBefore> before;  // the changed voxels only, never a grid copy
    std::vector<BoxBefore> boxes;     // ... or whole parts of bricks that changed together
    bool createdMaterials = false;    // the edit made the per-voxel material grid
};

// Undo keeps at most kMaxUndoEdits edits and kMaxUndoBytes of prior voxel
// states (the oldest are forgotten first). An edit whose prior states alone pass
// the byte cap cannot be undone, and no edit before it can be either.
inline constexpr size_t kMaxUndoEdits = 1024;
inline constexpr size_t kMaxUndoBytes = size_t(64) << 20;

struct EditHistory {
    std::vector<Edit> log;         // applied minus undone, in order; never capped
    std::deque<UndoRecord> undo;   // the last log entries' records, oldest first
    size_t undoBytes = 0;

    static size_t bytesOf(const UndoRecord& r) {
        return r.before.size() * sizeof(VoxelBefore) + r.boxes.size() * sizeof(BoxBefore);
    }
};

}  // namespace grotto::voxel
