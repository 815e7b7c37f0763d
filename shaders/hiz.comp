#version 460
#extension GL_GOOGLE_include_directive : require
// The farthest depth in each tile of the depth buffer (reverse-Z: the smallest
// value; 0 where any pixel is sky), for occlusion culling on the CPU: a box whose
// nearest point lies behind every tile it covers is hidden.
#include "shared/common.h"

layout(local_size_x = 8, local_size_y = 8) in;
layout(set = 0, binding = 0) uniform sampler2D depthBuffer;  // full-res D32, reverse-Z
layout(set = 0, binding = 1, std430) writeonly buffer Tiles { float farthest[]; };
layout(push_constant) uniform Push { uvec2 size; uvec2 tiles; uint tileSize; };

void main() {
    uvec2 tile = gl_GlobalInvocationID.xy;
    if (any(greaterThanEqual(tile, tiles))) return;
    uvec2 lo = tile * tileSize, hi = min(lo + tileSize, size);
    float d = 1.0;
    for (uint y = lo.y; y < hi.y; ++y)
        for (uint x = lo.x; x < hi.x; ++x) d = min(d, texelFetch(depthBuffer, ivec2(x, y), 0).r);
    farthest[tile.y * tiles.x + tile.x] = d;
}
