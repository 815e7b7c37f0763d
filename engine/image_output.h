#pragma once
// Writes a read-back frame with OpenImageIO, atomically. PNG: the tone-mapped
// colour as 8-bit sRGB, display-referred (a chosen zlib level, rows filtered with
// PNG's "up" predictor). EXR: the scene-linear colour (exposure applied, no tone
// map; tagged "Linear" with Rec. 709 chromaticities) as float (or half) RGBA, with AOVs also Z, N.x N.y N.z and albedo.R albedo.G albedo.B, AO
// (final), AO_raw, AO_spatial, AO_temporal and AO_history (half res, stored by
// nearest), edges and shadow, or a chosen few of those layers (FrameEncoding).
// Both carry the camera as the standard worldtocamera / worldtoscreen attributes.
#include "engine/camera.h"
#include "engine/frame/frame_images.h"

#include <filesystem>
#include <span>
#include <string>
#include <vector>

namespace grotto {

enum class ImageFormat { Png, Exr };

// From the extension (.png or .exr); throws grotto::Error (input) for anything else.
ImageFormat imageFormatFor(const std::filesystem::path& path);

void writeFrame(const std::filesystem::path& path, const FrameImages& frame, const Camera& camera, bool aovs);

// The AOV layers an EXR frame can hold, in the order they are written; "N" is
// N.x N.y N.z and "albedo" albedo.R albedo.G albedo.B, the others one channel each.
inline constexpr const char* kExrAovs[] = {"Z",           "N",          "albedo", "AO",    "AO_raw",
                                           "AO_spatial", "AO_temporal", "AO_history", "edges", "shadow"};
// VBAO's bent normal (world-space xyz, the AO pixel's): written beside those for
// a frame that has it (FrameImages::bentNormal), and only asked for by name.
inline constexpr const char* kBentNormalAov = "bent_normal";
// The face cache's light (FrameImages::light, light.R light.G light.B): likewise
// for a frame lit from a face cache.
inline constexpr const char* kCacheLightAov = "light";
// How a frame is encoded. PNG: the zlib level, 0 (none, fastest) to 9 (smallest).
// EXR: which AOV layers beside the colour (kExrAovs names; the frame must have
// been read back with AOVs when any is asked for), and half-float channels
// instead of float ones (Z stays float: half's 65504 range and 11-bit precision
// would garble depth).
struct FrameEncoding {
    int pngLevel = kDefaultPngLevel;
    std::vector<std::string> exrAovs;
    bool exrHalf = false;
    static constexpr int kDefaultPngLevel = 6;  // zlib's own default, as OpenImageIO's
};
void writeFrame(const std::filesystem::path& path, const FrameImages& frame, const Camera& camera,
                const FrameEncoding& encoding);

// An EXR of named float channels, each width * height values (row 0 on top), with
// the same camera attributes as writeFrame; written atomically.
struct Channel {
    std::string name;
    const std::vector<float>* values;
};
void writeChannels(const std::filesystem::path& path, uint32_t width, uint32_t height, std::span<const Channel> channels,
                   const Camera& camera);

// Whether an image file is width x height and decodes whole, every pixel of
// every channel: how a resumed flythrough tells a finished frame from a damaged one.
bool imageDecodes(const std::filesystem::path& path, uint32_t width, uint32_t height);

// Linear [0, 1] -> 8-bit sRGB (clamped; NaN -> 0).
uint8_t toSrgb8(float linear);
// An sRGB-encoded value in [0, 1] -> linear.
float srgbToLinear(float srgb);

// The colour as a display shows it: the frame's tone map (shaders/shared/tone_map.h)
// of its scene-linear colour, RGBA in [0, 1], alpha as it was.
std::vector<float> displayColor(const FrameImages& frame);
// The colour as 8-bit sRGB, 3 bytes a pixel: the pixels a PNG of the frame holds,
// toSrgb8 of displayColor.
std::vector<uint8_t> srgb8Pixels(const FrameImages& frame);
// Display-linear RGBA in [0, 1] (displayColor, aovDisplay) as 8-bit sRGB, 3 bytes a pixel.
std::vector<uint8_t> encodeSrgb8(std::span<const float> rgba);

// An 8-bit sRGB PNG of `rgb` (3 bytes a pixel, row 0 on top), written atomically,
// with the camera attributes when given one; zlib level 0 to 9.
void writeSrgb8(const std::filesystem::path& path, uint32_t width, uint32_t height, std::span<const uint8_t> rgb,
                const Camera* camera = nullptr, int pngLevel = FrameEncoding::kDefaultPngLevel);

// The AOVs showAov draws.
inline constexpr const char* kShownAovs =
    "ao, normal, depth, edges, shadow, raw, spatial, temporal, history, bent_normal, light";
// One AOV drawn for eyeballing (kShownAovs; raw, spatial, temporal: the AO
// chain's stages; history: its length over 64 frames; light: the face cache's
// light through the frame's tone map, without exposure), as display-linear RGBA
// like displayColor's, so that 8-bit sRGB values are the AOV's values (normals as
// n * 0.5 + 0.5, depth log-scaled from near white to far black, sky black). Needs
// a readback with AOVs.
std::vector<float> aovDisplay(const FrameImages& frame, const std::string& which);

}  // namespace grotto
