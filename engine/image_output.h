#pragma once
// Writes a read-back frame with OpenImageIO, atomically. PNG: 8-bit sRGB colour.
// EXR: float RGBA, with AOVs also Z, N.x N.y N.z and albedo.R albedo.G albedo.B.
// Both carry the camera as the standard worldtocamera / worldtoscreen attributes.
#include "engine/camera.h"
#include "engine/renderer.h"

#include <filesystem>

namespace grotto {

enum class ImageFormat { Png, Exr };

// From the extension (.png or .exr); throws grotto::Error (input) for anything else.
ImageFormat imageFormatFor(const std::filesystem::path& path);

void writeFrame(const std::filesystem::path& path, const FrameImages& frame, const Camera& camera, bool aovs);

// Linear [0, 1] -> 8-bit sRGB (clamped; NaN -> 0).
uint8_t toSrgb8(float linear);

}  // namespace grotto
