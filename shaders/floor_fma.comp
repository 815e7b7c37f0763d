#version 460
// The device's arithmetic floor: each thread runs `rounds` rounds of 8
// independent vec4 multiply-adds (32 lanes' worth a round) and writes one vec4,
// so the time is the arithmetic's (engine/lab/device_floors.h).

layout(local_size_x = 8, local_size_y = 8) in;
layout(push_constant) uniform Fma {
    uint rounds;
    uint width;
} fma;
layout(set = 0, binding = 0, std430) writeonly buffer Target { vec4 target[]; };

void main() {
    uint i = gl_GlobalInvocationID.y * fma.width + gl_GlobalInvocationID.x;
    vec4 a[8];
    for (int k = 0; k < 8; ++k) a[k] = vec4(float(i & 255u) * 1e-3 + float(k));
    const vec4 m = vec4(0.9999), c = vec4(1e-4);
    for (uint r = 0u; r < fma.rounds; ++r)
        for (int k = 0; k < 8; ++k) a[k] = a[k] * m + c;
    vec4 sum = vec4(0.0);
    for (int k = 0; k < 8; ++k) sum += a[k];
    target[i] = sum;
}
