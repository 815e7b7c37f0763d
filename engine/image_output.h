#pragma once
// Writes a read-back frame with OpenImageIO, atomically. PNG: 8-bit sRGB colour.
// EXR: float RGBA, with AOVs also Z, N.x N.y N.z and albedo.R albedo.G albedo.B.
// With AOVs the EXR also holds AO (final), AO_raw, AO_spatial, AO_temporal and
// AO_history (half res, stored by nearest) and edges. Both carry the camera as the standard worldtocamera / worldtoscreen attributes.
#include "engine/camera.h"
#include "engine/frame_images.h"

#include <filesystem>
#include <span>
#include <string>
#include <vector>

namespace grotto {

enum class ImageFormat { Png, Exr };

// From the extension (.png or .exr); throws grotto::Error (input) for anything else.
ImageFormat imageFormatFor(const std::filesystem::path& path);

void writeFrame(const std::filesystem::path& path, const FrameImages& frame, const Camera& camera, bool aovs);

// An EXR of named float channels, each width * height values (row 0 on top), with
// the same camera attributes as writeFrame; written atomically.
struct Channel {
    std::string name;
    const std::vector<float>* values;
};
void writeChannels(const std::filesystem::path& path, uint32_t width, uint32_t height, std::span<const Channel> channels,
                   const Camera& camera);

// Linear [0, 1] -> 8-bit sRGB (clamped; NaN -> 0).
uint8_t toSrgb8(float linear);
// An sRGB-encoded value in [0, 1] -> linear.
float srgbToLinear(float srgb);

// An 8-bit sRGB PNG of `rgb` (3 bytes a pixel, row 0 on top), written atomically.
void writeSrgb8(const std::filesystem::path& path, uint32_t width, uint32_t height, std::span<const uint8_t> rgb);

// The AOVs showAov draws.
inline constexpr const char* kShownAovs = "ao, normal, depth, edges, shadow, raw, spatial, temporal, history";
// Replaces the colour with one AOV for eyeballing (kShownAovs; raw, spatial,
// temporal: the AO chain's stages; history: its length over 64 frames), so
// that a PNG's 8-bit values are the AOV's values (normals as n * 0.5 + 0.5, depth
// log-scaled from near white to far black, sky black). Needs a readback with AOVs.
void showAov(FrameImages& frame, const std::string& which);

}  // namespace grotto
