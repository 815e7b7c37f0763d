#pragma once
// The constants a frame's passes read, from the camera and the settings: the frame
// uniforms, the AO constants and the temporal reprojection.
#include "engine/ao_settings.h"
#include "engine/camera.h"
#include "shaders/shared/frame.h"
#include "shaders/shared/gtao.h"
#include "shaders/shared/temporal.h"
#include "voxel/world_desc.h"

namespace grotto {

gpu::FrameUniforms frameUniforms(const Camera& camera, const voxel::Lighting& lighting, const AoOptions& ao);

// The AO constants for a camera; `scale`: frame pixels per AO pixel (exposed for
// the CPU twin and its tests).
gpu::GtaoConstants gtaoConstants(const Camera& camera, const gpu::GtaoSettings& settings, uint32_t frameIndex,
                                 uint32_t scale = 2);
// How the current camera's view maps to the previous one's (from the rotation and
// the step between the cameras, in double, so it stays exact far from the origin),
// and the current view's axes in the world; reset when there is no history. No
// invalidated boxes (HistoryBoxes::write adds them).
gpu::TemporalConstants temporalConstants(const Camera& current, const Camera* previous);

// The world's tone map setting as the shared curve (shaders/shared/tone_map.h).
uint32_t toneMapCurve(voxel::ToneMap toneMap);

}  // namespace grotto
