#pragma once
// `grotto reference --light full`: the path-traced light of one view, written to
// an EXR of scene-linear radiance (R, G, B) and its standard error per channel,
// with a summary of the error against the light itself.
#include "engine/camera.h"
#include "voxel/path_trace.h"
#include "voxel/world.h"

#include <filesystem>
#include <optional>
#include <span>

namespace grotto::app {

// With `requireRelative`, exits 3 (grotto::Error, regression) when the mean
// relative standard error over the surface pixels is above it; the EXR is
// written all the same.
void writeLightReference(const std::filesystem::path& out, const voxel::World& world, const Camera& camera,
                         const voxel::PathTraceSettings& settings, std::span<const voxel::PosedWorld> objects,
                         std::optional<double> requireRelative);

}  // namespace grotto::app
