#version 460
#extension GL_GOOGLE_include_directive : require
// For tests: whether each of a list of voxels is solid in the GPU occupancy
// (trace.glsl's voxelRayBlock), so they can compare it with the CPU's World::solid.
// The cells lie in a 2D grid of `width` columns; thread (x, y) answers cell
// y * width + x, the first `count` of them.

layout(local_size_x = 8, local_size_y = 8) in;
layout(push_constant) uniform Query {
    uint count;
    uint width;
} query;
layout(set = 0, binding = 0, std430) readonly buffer Cells { ivec4 cells[]; };  // xyz: voxel index
layout(set = 0, binding = 1, std430) writeonly buffer Solid { uint solid[]; };  // 1 solid, 0 empty
#define GROTTO_TRACE_BINDING 2
#include "trace.glsl"

void main() {
    uint i = gl_GlobalInvocationID.y * query.width + gl_GlobalInvocationID.x;
    if (gl_GlobalInvocationID.x >= query.width || i >= query.count) return;
    solid[i] = voxelRayBlock(cells[i].xyz) < 0 ? 1u : 0u;
}
