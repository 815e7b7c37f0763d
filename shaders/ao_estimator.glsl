// What every AO estimator pass (gtao.comp and the ssao.comp / hbao.comp
// baselines) reads and writes, so they are interchangeable in the chain: the depth
// MIP atlas and surface ids in, RGBA32F (visibility, packed edges, view depth,
// surface key: face + 1 and object, shared/objects.h) out. The includer defines its specialization constants first.
layout(local_size_x = GROTTO_GTAO_GROUP, local_size_y = GROTTO_GTAO_GROUP) in;

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
#ifdef GROTTO_VBAO
layout(set = 0, binding = 4, r32f) uniform readonly image2D thicknessAtlas;  // the depth atlas's layout
float gtaoThickness(ivec2 texel, int mip) { return imageLoad(thicknessAtlas, (texel >> mip) + gtaoMipOffset(mip)).r; }
layout(set = 0, binding = 5, rgba16f) uniform writeonly image2D bentNormals;  // AO resolution, world space
void vbaoBentNormal(ivec2 texel, vec3 direction) { imageStore(bentNormals, texel, vec4(direction, 0.0)); }
#endif
uint gtaoSurface(ivec2 pixel) { return texelFetch(surfaceTex, pixel, 0).r; }

#include "shared/gtao_kernel.h"

// Depth and face ride along so the upsample needs one fetch per sample.
void aoStore(ivec2 p, vec2 visibilityEdges) {
    imageStore(aoEdges, p, vec4(visibilityEdges, gtaoDepth(p, 0), float(surfaceKey(gtaoSurface(p * int(gtao.scale))))));
}
