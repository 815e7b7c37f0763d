#pragma once
// An EXR against the PNG of the same frame: the PNG must be the EXR's scene-linear
// colour made display-referred as docs/lighting.md says (the tone map, then sRGB
// encoding to 8 bits), and the EXR must say what it holds.
#include "engine/image_input.h"
#include "shaders/shared/tone_map.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace grotto::test {

// The sRGB transfer function to 8 bits, straight from its definition.
inline int srgbByte(float v) {
    const double x = std::clamp(double(v), 0.0, 1.0);
    return int(std::lround(255.0 * (x <= 0.0031308 ? 12.92 * x : 1.055 * std::pow(x, 1.0 / 2.4) - 0.055)));
}

struct ExrAgainstPng {
    bool read = false;        // both files read, of one size
    int worst = 256;          // largest |PNG byte - encode(toneMap(EXR))| over R, G, B
    float brightest = 0.0f;   // the EXR's largest R, G or B
    std::string colorSpace;   // its "oiio:ColorSpace"
    std::vector<float> chromaticities;  // its "chromaticities" (red, green, blue, white xy), if any
};

inline ExrAgainstPng compareExrWithPng(const std::filesystem::path& exr, const std::filesystem::path& png,
                                       uint32_t curve = GROTTO_TONE_MAP_FILMIC) {
    ExrAgainstPng r;
    const std::optional<ImageFile> e = readImage(exr), p = readImage(png, ReadAs::UInt8);
    if (!e || !p || e->width != p->width || e->height != p->height || e->channels() < 3 || p->channels() < 3) return r;
    r.colorSpace = e->colorSpace;
    r.chromaticities = e->chromaticities;
    const size_t n = size_t(e->width) * e->height;
    // R, G and B of each pixel, as the first three channels of both.
    std::vector<float> linear(3 * n);
    std::vector<uint8_t> bytes(3 * n);
    for (size_t i = 0; i < n; ++i)
        for (size_t c = 0; c < 3; ++c) {
            linear[3 * i + c] = e->floats[size_t(e->channels()) * i + c];
            bytes[3 * i + c] = p->bytes[size_t(p->channels()) * i + c];
        }
    r.read = true;
    r.worst = 0;
    for (size_t k = 0; k < 3 * n; ++k) {
        r.brightest = std::max(r.brightest, linear[k]);
        r.worst = std::max(r.worst, std::abs(int(bytes[k]) - srgbByte(gpu::toneMap(linear[k], curve))));
    }
    return r;
}

// Rec. 709 primaries and the D65 white, as OpenEXR's chromaticities list them.
inline const std::vector<float> kRec709Chromaticities = {0.64f, 0.33f, 0.30f, 0.60f, 0.15f, 0.06f, 0.3127f, 0.3290f};

// A world over the CLI fixture's floor (good.vdb) under a sun four times the
// default, unscaled, so sunlit faces are well above 1; camera "c" and a one-second
// path "p" look at it. `toneMap`: "filmic" or "linear".
inline std::string brightWorld(const std::string& toneMap) {
    return R"({"grid": {"file": "good.vdb"},
        "lighting": {"sun": {"intensity": 4}, "exposure": 1, "tone_map": ")" + toneMap + R"("},
        "cameras": {"c": {"position": [8, 10, 30], "target": [8, 0, 8]}},
        "paths": {"p": {"keys": [{"time": 0, "position": [8, 10, 30], "target": [8, 0, 8]},
                                 {"time": 1, "position": [20, 8, 24], "target": [8, 0, 8]}]}}})";
}

// What every EXR of a brightWorld frame and its PNG must show.
inline void expectSceneLinear(const ExrAgainstPng& r, const std::string& what) {
    ASSERT_TRUE(r.read) << what;
    EXPECT_LE(r.worst, 1) << what << ": the PNG is not the EXR through the tone map";
    EXPECT_GT(r.brightest, 1.5f) << what << ": a sunlit face under 4x the default sun must exceed 1";
    EXPECT_EQ(r.colorSpace, "Linear") << what;
    EXPECT_EQ(r.chromaticities, kRec709Chromaticities) << what;
}

}  // namespace grotto::test
