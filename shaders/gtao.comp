#version 460
#extension GL_GOOGLE_include_directive : require
// GTAO main pass at half resolution: visibility and packed depth edges per pixel.
#include "shared/gtao.h"
#include "shared/quad.h"

layout(local_size_x = GROTTO_GTAO_GROUP, local_size_y = GROTTO_GTAO_GROUP) in;
// The loop shape as specialization constants (see the kernel); GtaoPass sets them.
layout(constant_id = 0) const uint specSlices = 3u;
layout(constant_id = 1) const uint specSteps = 3u;
layout(constant_id = 2) const float specPower = 2.0;
#define kGtaoSlices specSlices
#define kGtaoSteps specSteps
#define kGtaoPower specPower

layout(set = 0, binding = 0, std140) uniform Constants { GtaoConstants gtao; };
layout(set = 0, binding = 1, r32f) uniform readonly image2D depthAtlas;  // all MIPs side by side
layout(set = 0, binding = 2) uniform usampler2D surfaceTex;  // full resolution
layout(set = 0, binding = 3, rgba32f) uniform writeonly image2D aoEdges;  // AO, edges, depth, face + 1

// Point sampling with explicit texel coordinates, so the CPU twin can reproduce
// every fetch exactly. One atlas image keeps this a single fetch (five images
// behind a switch cost lavapipe half the pass). The kernel passes AO pixels inside
// the image, so texel >> mip is inside the MIP: only its offset is needed.
ivec2 gtaoMipOffset(int mip);  // in the kernel below

float gtaoDepth(ivec2 texel, int mip) { return imageLoad(depthAtlas, (texel >> mip) + gtaoMipOffset(mip)).r; }
uint gtaoSurface(ivec2 pixel) { return texelFetch(surfaceTex, pixel, 0).r; }

#include "shared/gtao_kernel.h"

void main() {
    ivec2 p = ivec2(gl_GlobalInvocationID.xy);
    if (any(greaterThanEqual(uvec2(p), gtao.halfSize))) return;
    // Depth and face ride along so the upsample needs one fetch per sample.
    imageStore(aoEdges, p, vec4(gtaoPixel(p), gtaoDepth(p, 0), float(gtaoSurface(p * int(gtao.scale)) & 7u)));
}
