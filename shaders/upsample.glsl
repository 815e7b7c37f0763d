// Depth-aware upsample of half-res AO, shared by the composite (which shades with
// it directly, so full-res AO is never stored on the way) and upsample.comp (which
// writes it for the AO AOV). Of the four half-res samples around a pixel, only
// those on the same surface contribute, bilinearly weighted: same face direction
// and on the pixel's plane (voxel faces are planes, so this holds on grazing
// floors too, where depths differ a lot). If none qualifies, the one nearest in
// depth is taken. AO never crosses a discontinuity.
//
// One invocation per AO pixel resolves its whole scale x scale block of full-res
// pixels, so the four samples, their planes and normals are read once per block
// rather than once per pixel (lavapipe pays per fetch and per instruction).
//
// The includer declares `gtao` (GtaoConstants), `aoHalf` (readonly rgba32f: AO,
// edges or history, view depth, face + 1), `depthBuffer` (full-res D32, reverse-Z)
// and includes shared/gtao_kernel.h first.

// One AO sample: its visibility, view depth, surface key (face + 1 and object,
// shared/objects.h; 0 = sky) and the offset of its face's plane along that face's normal.
struct AoSample {
    float ao, depth, plane;
    uint face;
};

AoSample loadAoSample(ivec2 s) {
    vec4 v = imageLoad(aoHalf, s);
    AoSample r;
    r.ao = v.x;
    r.depth = v.z;
    r.face = uint(v.w);
    r.plane = dot(gtaoViewPosition(vec2(s), v.z), vec3(gtao.viewNormals[max(r.face, 1u) - 1u]));
    return r;
}

// The samples at AO pixel h and its right, lower and lower-right neighbours; the
// last three only at half resolution (at full resolution each pixel is its own).
struct AoBlock {
    AoSample s[4];
};

AoBlock loadAoBlock(ivec2 h) {
    AoBlock b;
    b.s[0] = loadAoSample(h);
    if (gtao.scale == 1u) return b;
    ivec2 last = ivec2(gtao.halfSize) - 1;
    b.s[1] = loadAoSample(min(h + ivec2(1, 0), last));
    b.s[2] = loadAoSample(min(h + ivec2(0, 1), last));
    b.s[3] = loadAoSample(min(h + ivec2(1, 1), last));
    return b;
}

// The visibility of full-res pixel h * scale + offset (offset within the block) on
// the surface with key `face` (not sky). The block's own pixel (offset 0) is the AO
// pixel's exactly (its depth, face and plane are that pixel's), so it takes it
// unchanged; the others blend the samples on their plane with bilinear weights.
float upsampledAo(AoBlock b, ivec2 h, ivec2 offset, uint face) {
    if (offset == ivec2(0)) return b.s[0].ao;
    ivec2 q = h * int(gtao.scale) + offset;
    float z = gtao.depthB / (texelFetch(depthBuffer, q, 0).r + gtao.depthA);
    float plane = dot(gtaoViewPosition(vec2(q) / float(gtao.scale), z), vec3(gtao.viewNormals[face - 1u]));
    vec4 w = offset == ivec2(1, 0) ? vec4(0.5, 0.5, 0.0, 0.0)
           : offset == ivec2(0, 1) ? vec4(0.5, 0.0, 0.5, 0.0) : vec4(0.25);
    float sum = 0.0, weight = 0.0, nearestAo = 1.0, nearestDz = 1e30;
    for (int i = 0; i < 4; ++i) {
        float dz = abs(b.s[i].depth - z);
        if (dz < nearestDz) {
            nearestDz = dz;
            nearestAo = b.s[i].ao;
        }
        if (w[i] > 0.0 && b.s[i].face == face && abs(b.s[i].plane - plane) <= 1e-3 * z) {
            sum += w[i] * b.s[i].ao;
            weight += w[i];
        }
    }
    return weight > 1e-4 ? clamp(sum / weight, 0.0, 1.0) : nearestAo;  // rounding may pass 1
}
