#pragma once
// The sun a frame shows against exact rays: one from each sunlit-facing pixel's
// surface point toward the sun through the world's voxels and the objects' at
// their poses. The frame is rendered lit by the sun alone (sunAlone), so a
// pixel's sun visibility is its colour over albedo x the sun's radiance x
// cos(sun, normal) x exposure. What the face cache's sun (docs/face-cache.md)
// is measured by along a day.
#include "engine/camera.h"
#include "engine/frame/frame_images.h"
#include "voxel/reference_ao.h"
#include "voxel/world.h"

#include <cstddef>
#include <span>

namespace grotto {

// `lighting` with no ambient light: a frame under it shows the sun's light alone
// (and the glowing faces', which sunAgainstRays leaves out).
voxel::Lighting sunAlone(const voxel::Lighting& lighting);

struct SunAgreement {
    size_t surface = 0;  // pixels showing a surface of the world
    size_t facing = 0;   // of those, facing the sun (lit by it where nothing stands between)
    size_t off = 0;      // of those, whose sun visibility is off the exact ray's by over a half
    size_t aovOff = 0;   // of those, whose shadow AOV (the face cache's texels alone) is off by over a quarter
};

// `frame`: read back with AOVs, rendered under sunAlone(lighting) (lighting as
// given: the day's sun at its hour included); the world's pixels that glow and
// the objects' own pixels are not counted.
SunAgreement sunAgainstRays(const FrameImages& frame, const Camera& camera, const voxel::World& world,
                            std::span<const voxel::PosedWorld> objects, const voxel::Lighting& lighting);

}  // namespace grotto
