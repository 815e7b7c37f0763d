#include "voxel/generators/noise.h"

#include <cmath>

namespace grotto::voxel {
namespace {

// Bit mixer with good avalanche: every input bit flips about half the output bits.
uint32_t mix(uint32_t h) {
    h ^= h >> 16;
    h *= 0x7feb352du;
    h ^= h >> 15;
    h *= 0x846ca68bu;
    h ^= h >> 16;
    return h;
}

// Quintic fade: continuous second derivative, so no creases at lattice faces.
float fade(float t) { return t * t * t * (t * (t * 6.0f - 15.0f) + 10.0f); }

float lerp(float a, float b, float t) { return a + (b - a) * t; }

// The 12 cube-edge directions (Perlin's improved noise): no axis is favoured.
constexpr float kGradients[12][3] = {{1, 1, 0}, {-1, 1, 0}, {1, -1, 0}, {-1, -1, 0},
                                     {1, 0, 1}, {-1, 0, 1}, {1, 0, -1}, {-1, 0, -1},
                                     {0, 1, 1}, {0, -1, 1}, {0, 1, -1}, {0, -1, -1}};

float gradDot(uint32_t h, float dx, float dy, float dz) {
    const float* g = kGradients[h % 12u];
    return g[0] * dx + g[1] * dy + g[2] * dz;
}

}  // namespace

uint32_t hashCoord(int32_t x, int32_t y, int32_t z, uint32_t seed) {
    uint32_t h = mix(seed ^ 0x9e3779b9u);
    h = mix(h ^ static_cast<uint32_t>(x));
    h = mix(h ^ static_cast<uint32_t>(y) * 0x85ebca6bu);
    h = mix(h ^ static_cast<uint32_t>(z) * 0xc2b2ae35u);
    return h;
}

float hashUnit(int32_t x, int32_t y, int32_t z, uint32_t seed) {
    // The top 24 bits fit a float mantissa exactly.
    return static_cast<float>(hashCoord(x, y, z, seed) >> 8) * (1.0f / 16777216.0f);
}

float gradientNoise(float x, float y, float z, uint32_t seed) {
    const float fx = std::floor(x), fy = std::floor(y), fz = std::floor(z);
    const auto ix = static_cast<int32_t>(fx), iy = static_cast<int32_t>(fy),
               iz = static_cast<int32_t>(fz);
    const float dx = x - fx, dy = y - fy, dz = z - fz;
    auto corner = [&](int cx, int cy, int cz) {
        return gradDot(hashCoord(ix + cx, iy + cy, iz + cz, seed), dx - float(cx), dy - float(cy),
                       dz - float(cz));
    };
    const float u = fade(dx), v = fade(dy), w = fade(dz);
    const float x00 = lerp(corner(0, 0, 0), corner(1, 0, 0), u);
    const float x10 = lerp(corner(0, 1, 0), corner(1, 1, 0), u);
    const float x01 = lerp(corner(0, 0, 1), corner(1, 0, 1), u);
    const float x11 = lerp(corner(0, 1, 1), corner(1, 1, 1), u);
    return lerp(lerp(x00, x10, v), lerp(x01, x11, v), w);
}

float fbm(float x, float y, float z, uint32_t seed, int octaves) {
    float sum = 0.0f, amplitude = 1.0f, total = 0.0f, frequency = 1.0f;
    for (int i = 0; i < octaves; ++i) {
        sum += amplitude * gradientNoise(x * frequency, y * frequency, z * frequency,
                                         seed + 0x632be5abu * static_cast<uint32_t>(i + 1));
        total += amplitude;
        amplitude *= 0.5f;
        frequency *= 2.0f;
    }
    return total > 0.0f ? sum / total : 0.0f;
}

bool inWormTunnel(float x, float y, float z, uint32_t seed) {
    constexpr float kTunnel = 0.006f;  // squared radius of tunnels in noise units
    const float a = fbm(x / 48.0f, y / 32.0f, z / 48.0f, seed + 2u, 2);
    const float b = fbm(x / 48.0f, y / 32.0f, z / 48.0f, seed + 3u, 2);
    return a * a + b * b < kTunnel;
}

}  // namespace grotto::voxel
