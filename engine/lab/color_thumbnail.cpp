#include "engine/lab/color_thumbnail.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace grotto {

ColorThumbnail colorThumbnail(const std::vector<uint8_t>& srgb8, uint32_t width, uint32_t height) {
    ColorThumbnail t;
    const uint32_t longer = std::max(width, height), shorter = std::min(width, height);
    const uint32_t across = std::min(kThumbnailCells, longer);
    const uint32_t down = std::clamp(uint32_t(std::lround(double(across) * shorter / longer)), 1u, shorter);
    t.width = width >= height ? across : down;
    t.height = width >= height ? down : across;
    t.rgb.resize(size_t(3) * t.width * t.height);
    for (uint32_t cy = 0; cy < t.height; ++cy)
        for (uint32_t cx = 0; cx < t.width; ++cx) {
            // Cell (cx, cy) covers the pixels from cx * width / cells up to the next cell's first.
            const uint32_t x0 = uint32_t(uint64_t(cx) * width / t.width), x1 = uint32_t(uint64_t(cx + 1) * width / t.width);
            const uint32_t y0 = uint32_t(uint64_t(cy) * height / t.height), y1 = uint32_t(uint64_t(cy + 1) * height / t.height);
            uint64_t sum[3] = {0, 0, 0};
            for (uint32_t y = y0; y < y1; ++y)
                for (uint32_t x = x0; x < x1; ++x)
                    for (int c = 0; c < 3; ++c) sum[c] += srgb8[3 * (size_t(y) * width + x) + c];
            const double n = double(x1 - x0) * double(y1 - y0);
            for (int c = 0; c < 3; ++c) t.rgb[3 * (size_t(cy) * t.width + cx) + c] = uint8_t(std::lround(double(sum[c]) / n));
        }
    return t;
}

double thumbnailRmse(const ColorThumbnail& a, const ColorThumbnail& b) {
    if (a.width != b.width || a.height != b.height || a.rgb.size() != b.rgb.size() || a.rgb.empty())
        return std::numeric_limits<double>::quiet_NaN();
    double sum = 0.0;
    for (size_t i = 0; i < a.rgb.size(); ++i) {
        const double d = (double(a.rgb[i]) - double(b.rgb[i])) / 255.0;
        sum += d * d;
    }
    return std::sqrt(sum / double(a.rgb.size()));
}

std::string toHex(const std::vector<uint8_t>& bytes) {
    static constexpr char kDigits[] = "0123456789abcdef";
    std::string hex;
    hex.reserve(2 * bytes.size());
    for (uint8_t b : bytes) hex += kDigits[b >> 4], hex += kDigits[b & 15];
    return hex;
}

std::optional<std::vector<uint8_t>> fromHex(const std::string& hex) {
    auto digit = [](char c) {
        return c >= '0' && c <= '9' ? c - '0' : c >= 'a' && c <= 'f' ? c - 'a' + 10 : c >= 'A' && c <= 'F' ? c - 'A' + 10 : -1;
    };
    if (hex.size() % 2) return std::nullopt;
    std::vector<uint8_t> bytes(hex.size() / 2);
    for (size_t i = 0; i < bytes.size(); ++i) {
        const int hi = digit(hex[2 * i]), lo = digit(hex[2 * i + 1]);
        if (hi < 0 || lo < 0) return std::nullopt;
        bytes[i] = uint8_t(hi * 16 + lo);
    }
    return bytes;
}

}  // namespace grotto
