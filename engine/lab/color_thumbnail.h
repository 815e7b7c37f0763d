#pragma once
// A frame's display colour in a few hundred bytes: the 8-bit sRGB pixels a PNG of
// the frame holds, averaged over a coarse grid of cells. Small enough for a
// stability baseline to keep one every few frames, fine enough that a change to
// shading, shadows or the tone map moves some cells by more than a rounding step.
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace grotto {

// Cells across the image's longer side; the shorter side gets as many as keep the
// cells near square (at least one, and never more than the image has pixels).
inline constexpr uint32_t kThumbnailCells = 16;

struct ColorThumbnail {
    uint32_t width = 0, height = 0;  // cells
    std::vector<uint8_t> rgb;        // each cell's mean, rounded to 8 bits; 3 bytes a cell, row 0 on top
};

// From 8-bit sRGB pixels (3 bytes a pixel, row 0 on top: srgb8Pixels).
ColorThumbnail colorThumbnail(const std::vector<uint8_t>& srgb8, uint32_t width, uint32_t height);

// Root mean square difference over every cell and channel, in [0, 1] (1 = 255 levels).
// Thumbnails of different grids have none: NaN.
double thumbnailRmse(const ColorThumbnail& a, const ColorThumbnail& b);

// The bytes as lowercase hex, two digits a byte; and back (nullopt for anything
// but an even number of hex digits).
std::string toHex(const std::vector<uint8_t>& bytes);
std::optional<std::vector<uint8_t>> fromHex(const std::string& hex);

}  // namespace grotto
