#pragma once
// Where edits restart the temporal AO history in the next frame: the world boxes
// that changed, collected between frames and handed to the temporal pass
// camera-relative. At most GROTTO_TEMPORAL_MAX_BOXES; beyond that the two boxes
// whose union adds the least volume merge, which only ever invalidates more.
#include "engine/ao_settings.h"
#include "shaders/shared/temporal.h"
#include "voxel/edit.h"

#include <vector>

namespace grotto {

// How far a voxel's change can move the AO of a surface point (world units): the
// estimator's search reach, the radius times GTAO's multiplier (SSAO's falloff
// ends at 1.25 radii, HBAO's at the radius).
double aoReach(const AoOptions& ao);

class HistoryBoxes {
public:
    void add(const voxel::WorldBox& box);  // empty boxes are ignored
    // Writes the boxes grown by `margin`, less the camera position (in double, so
    // they stay exact far from the origin), into t.boxMin / boxMax / boxCount.
    void write(const glm::dvec3& camera, double margin, gpu::TemporalConstants& t) const;
    void clear() { boxes_.clear(); }
    const std::vector<voxel::WorldBox>& boxes() const { return boxes_; }

private:
    std::vector<voxel::WorldBox> boxes_;
};

}  // namespace grotto
