#include "engine/path_edits.h"

#include "common/error.h"
#include "engine/renderer.h"

namespace grotto {

PathEdits::PathEdits(const voxel::CameraPathDesc& path, const voxel::World& world) : path_(path) {
    const size_t palette = world.desc().materials.size();
    for (const voxel::TimedEdit& e : path.edits)
        if (e.edit.op != voxel::Edit::Op::Carve && (e.edit.material < 1 || size_t(e.edit.material) > palette))
            throw Error(path.source.string(), "field '" + e.field + ".material': " + std::to_string(e.edit.material) +
                                                  " is not in the world's palette",
                        "material ids 1 to " + std::to_string(palette) + " ('materials' in the world file)");
}

voxel::WorldBox PathEdits::applyUpTo(double time, LiveScene& scene, Renderer* renderer) {
    voxel::WorldBox changed;
    for (; next_ < path_.edits.size() && path_.edits[next_].time <= time; ++next_) {
        const voxel::TimedEdit& e = path_.edits[next_];
        try {
            changed = changed.merged(scene.apply(e.edit).box);
        } catch (const Error& error) {
            throw Error(path_.source.string(), "field '" + e.field + "': " + error.problem(), error.hint(), error.kind());
        }
    }
    if (renderer && !changed.empty()) renderer->invalidateHistory(changed);
    return changed;
}

}  // namespace grotto
