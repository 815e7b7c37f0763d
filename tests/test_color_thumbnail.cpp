// Colour thumbnails (engine/lab/color_thumbnail.h): cell grids for any image shape,
// cell means of the 8-bit display colour, their RMSE, and hex round trips.
#include "engine/lab/color_thumbnail.h"

#include <gtest/gtest.h>

#include <cmath>

namespace grotto {
namespace {

std::vector<uint8_t> uniform(uint32_t w, uint32_t h, uint8_t r, uint8_t g, uint8_t b) {
    std::vector<uint8_t> px;
    for (size_t i = 0; i < size_t(w) * h; ++i) px.insert(px.end(), {r, g, b});
    return px;
}

TEST(ColorThumbnail, CellsNearSquareForAnyShape) {
    struct Case {
        uint32_t w, h, cw, ch;
    };
    for (const Case& c : {Case{320, 180, 16, 9}, Case{180, 320, 9, 16}, Case{64, 36, 16, 9}, Case{15, 15, 15, 15},
                          Case{100, 1, 16, 1}, Case{1, 1, 1, 1}, Case{1000, 990, 16, 16}}) {
        const ColorThumbnail t = colorThumbnail(uniform(c.w, c.h, 10, 200, 255), c.w, c.h);
        EXPECT_EQ(t.width, c.cw) << c.w << "x" << c.h;
        EXPECT_EQ(t.height, c.ch) << c.w << "x" << c.h;
        ASSERT_EQ(t.rgb.size(), size_t(3) * c.cw * c.ch);
        for (size_t i = 0; i < t.rgb.size(); i += 3) ASSERT_TRUE(t.rgb[i] == 10 && t.rgb[i + 1] == 200 && t.rgb[i + 2] == 255);
    }
}

// A shadow's edge moved by a few pixels moves one cell's mean: the RMSE over the
// cells is that cell's change, spread over all of them.
TEST(ColorThumbnail, ACellsMeanMovesWithWhatItCovers) {
    const uint32_t w = 64, h = 36;  // 16 x 9 cells of 4 x 4 pixels
    std::vector<uint8_t> lit = uniform(w, h, 200, 200, 200), shadowed = lit;
    for (uint32_t y = 0; y < 4; ++y)
        for (uint32_t x = 0; x < 2; ++x)
            for (int c = 0; c < 3; ++c) shadowed[3 * (y * w + x) + c] = 100;  // half of the first cell
    const ColorThumbnail a = colorThumbnail(lit, w, h), b = colorThumbnail(shadowed, w, h);
    EXPECT_EQ(b.rgb[0], 150);
    EXPECT_EQ(b.rgb[3], 200);
    EXPECT_NEAR(thumbnailRmse(a, b), std::sqrt(3.0 * 50.0 * 50.0 / (16 * 9 * 3)) / 255.0, 1e-12);
    EXPECT_EQ(thumbnailRmse(a, a), 0.0);
    EXPECT_TRUE(std::isnan(thumbnailRmse(a, colorThumbnail(lit, h, w)))) << "grids of other shapes do not compare";
}

TEST(ColorThumbnail, HexRoundTripsAndRefusesNonsense) {
    const std::vector<uint8_t> bytes = {0, 1, 15, 16, 127, 128, 254, 255};
    EXPECT_EQ(toHex(bytes), "00010f107f80feff");
    EXPECT_EQ(fromHex(toHex(bytes)), bytes);
    EXPECT_EQ(fromHex("0A0b"), (std::vector<uint8_t>{10, 11}));
    for (const char* bad : {"0", "0g", "zz", "1 2 "}) EXPECT_FALSE(fromHex(bad).has_value()) << bad;
}

}  // namespace
}  // namespace grotto
