// A face cache texel's rays on the GPU, the same sequence voxel/face_bake.cpp
// traces on the CPU: the texel's 64-bit seed (splitmix64 of its face and place,
// in pairs of 32-bit words here), the R2 sequence shifted by it, cosine-weighted
// about the face's normal or uniform over the sun's disc.

// 64-bit words as (low, high).
uvec2 add64(uvec2 a, uvec2 b) {
    uint carry;
    uint lo = uaddCarry(a.x, b.x, carry);
    return uvec2(lo, a.y + b.y + carry);
}
uvec2 mul64(uvec2 a, uvec2 b) {
    uint hi, lo;
    umulExtended(a.x, b.x, hi, lo);
    return uvec2(lo, hi + a.x * b.y + a.y * b.x);
}
uvec2 shr64(uvec2 a, uint n) { return uvec2((a.x >> n) | (a.y << (32u - n)), a.y >> n); }  // 0 < n < 32

uvec2 splitmix64(uvec2 x) {
    x = add64(x, uvec2(0x7f4a7c15u, 0x9e3779b9u));
    x = mul64(x ^ shr64(x, 30u), uvec2(0x1ce4e5b9u, 0xbf58476du));
    x = mul64(x ^ shr64(x, 27u), uvec2(0x133111ebu, 0x94d049bbu));
    return x ^ shr64(x, 31u);
}

// The top 24 of the 53 bits the CPU's unitInterval keeps: all a float holds.
float unitInterval(uvec2 bits) { return float(bits.y >> 8u) * (1.0 / 16777216.0); }

// The seed of texel (i, j) of the face of `cell` looking `dir`.
uvec2 texelSeed(ivec3 cell, uint dir, uint i, uint j) {
    uvec2 h = splitmix64(uvec2(uint(cell.x), 0u));
    h = splitmix64(h ^ uvec2(uint(cell.y), 0u));
    h = splitmix64(h ^ uvec2(uint(cell.z), 0u));
    return splitmix64(h ^ uvec2((i << 16u) | j, dir));
}

const float kR2A = 1.0 / 1.32471795724474602596, kR2B = 1.0 / (1.32471795724474602596 * 1.32471795724474602596);
vec2 r2(uint n, vec2 shift) { return fract(vec2(0.5) + float(n) * vec2(kR2A, kR2B) + shift); }

// Where on a texel's square its sun ray n starts (voxel/ray_sampling.h's texelSpread).
vec2 texelSpread(uint n, vec2 shift) { return fract(vec2(0.5) + float(n) * vec2(0.41421356237309505, 0.7320508075688772) + shift); }

vec3 cosineDirection(vec2 u) {
    float r = sqrt(u.x), phi = 6.28318530717958648 * u.y;
    return vec3(r * cos(phi), r * sin(phi), sqrt(max(1.0 - u.x, 0.0)));
}
vec3 coneDirection(vec2 u, float cosHalf) {
    float z = 1.0 - u.x * (1.0 - cosHalf), r = sqrt(max(0.0, 1.0 - z * z)), phi = 6.28318530717958648 * u.y;
    return vec3(r * cos(phi), r * sin(phi), z);
}

// Two unit tangents completing the unit normal n (Duff et al. 2017), as the CPU's.
void texelTangents(vec3 n, out vec3 t1, out vec3 t2) {
    float s = n.z >= 0.0 ? 1.0 : -1.0, a = -1.0 / (s + n.z), b = n.x * n.y * a;
    t1 = vec3(1.0 + s * n.x * n.x * a, s * b, -s * n.x);
    t2 = vec3(b, s + n.y * n.y * a, -n.y);
}
