// The per-pixel, per-frame noise of every stochastic pass (GTAO's slice angles,
// the voxel rays, the soft sun's directions), written once for GLSL and C++ (GLM;
// the C++ includer wraps it in `using namespace glm`).
#ifndef GROTTO_SHARED_NOISE_H
#define GROTTO_SHARED_NOISE_H

// Index of a pixel along a 64x64 Hilbert curve: neighbouring pixels get distant
// sequence indices, so the low-discrepancy noise below spreads evenly in space.
uint gtaoHilbertIndex(uint px, uint py) {
    uint x = px & 63u, y = py & 63u, index = 0u;
    for (uint level = 32u; level > 0u; level /= 2u) {
        uint rx = (x & level) > 0u ? 1u : 0u;
        uint ry = (y & level) > 0u ? 1u : 0u;
        index += level * level * ((3u * rx) ^ ry);
        if (ry == 0u) {  // rotate the quadrant so the curve stays continuous
            if (rx == 1u) {
                x = 63u - x;
                y = 63u - y;
            }
            uint t = x;
            x = y;
            y = t;
        }
    }
    return index;
}

// The R2 sequence (plastic-number lattice) in 32-bit fixed point, so GPU and CPU
// produce the same bits: 2^32 / 1.32471795724 and 2^32 / 1.32471795724^2, offset by 0.5.
vec2 gtaoNoise(uvec2 pixel, uint frameIndex) {
    uint index = gtaoHilbertIndex(pixel.x, pixel.y) + 288u * (frameIndex % 64u);
    uint a = index * 3242174889u + 2147483648u;
    uint b = index * 2447445414u + 2147483648u;
    return vec2(float(a >> 8u), float(b >> 8u)) * (1.0f / 16777216.0f);
}

#endif
