#pragma once
// An EXR against the PNG of the same frame: the PNG must be the EXR's scene-linear
// colour made display-referred as docs/lighting.md says (the tone map, then sRGB
// encoding to 8 bits), and the EXR must say what it holds.
#include "shaders/shared/tone_map.h"

#include <OpenImageIO/imageio.h>
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
    auto e = OIIO::ImageInput::open(exr.string());
    auto p = OIIO::ImageInput::open(png.string());
    if (!e || !p || e->spec().width != p->spec().width || e->spec().height != p->spec().height) return r;
    const OIIO::ImageSpec& spec = e->spec();
    r.colorSpace = spec.get_string_attribute("oiio:ColorSpace");
    if (const OIIO::ParamValue* c = spec.find_attribute("chromaticities", OIIO::TypeDesc(OIIO::TypeDesc::FLOAT, 8)))
        r.chromaticities.assign(static_cast<const float*>(c->data()), static_cast<const float*>(c->data()) + 8);
    const size_t n = size_t(spec.width) * spec.height;
    std::vector<float> linear(3 * n);
    std::vector<uint8_t> bytes(3 * n);
    if (!e->read_image(0, 0, 0, 3, OIIO::TypeDesc::FLOAT, linear.data()) ||
        !p->read_image(0, 0, 0, 3, OIIO::TypeDesc::UINT8, bytes.data()))
        return r;
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
