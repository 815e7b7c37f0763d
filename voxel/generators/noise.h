#pragma once
// A small seeded gradient noise of our own. Lattice gradients come from integer
// hashing and the interpolation uses only + - * on floats, so the same inputs give
// the same bits on every machine and at every thread count.
#include <cstdint>

namespace grotto::voxel {

// 32-bit avalanche hash of a lattice point and a seed.
uint32_t hashCoord(int32_t x, int32_t y, int32_t z, uint32_t seed);

// Uniform in [0, 1), from hashCoord.
float hashUnit(int32_t x, int32_t y, int32_t z, uint32_t seed);

// Gradient (Perlin-style) noise at p, roughly in [-1, 1]; 0 at lattice points.
float gradientNoise(float x, float y, float z, uint32_t seed);

// Fractal sum of `octaves` gradient noises, each twice the frequency and half the
// amplitude of the last, each with its own seed; normalised to roughly [-1, 1].
float fbm(float x, float y, float z, uint32_t seed, int octaves);

// Worm-like tunnels (caves, mine): where two fractal noises, 48 voxels across and
// 32 up, are both near zero; their zero surfaces cross along winding curves.
bool inWormTunnel(float x, float y, float z, uint32_t seed);

}  // namespace grotto::voxel
