#version 460
// The device's memory floor: a plain copy, 16 bytes a thread, read and written
// once (engine/lab/device_floors.h). Thread (x, y) copies word y * width + x.

layout(local_size_x = 8, local_size_y = 8) in;
layout(push_constant) uniform Copy {
    uint count;
    uint width;
} copy;
layout(set = 0, binding = 0, std430) readonly buffer Source { uvec4 source[]; };
layout(set = 0, binding = 1, std430) writeonly buffer Target { uvec4 target[]; };

void main() {
    uint i = gl_GlobalInvocationID.y * copy.width + gl_GlobalInvocationID.x;
    if (gl_GlobalInvocationID.x >= copy.width || i >= copy.count) return;
    target[i] = source[i];
}
