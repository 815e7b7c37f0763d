// The face cache's levels (shared/face_trace.h), 2 bits a face, at
// GROTTO_FACE_LEVELS_BINDING, which the includer defines (GpuFaceCache::withLevelsBinding).
layout(set = 0, binding = GROTTO_FACE_LEVELS_BINDING, std430) readonly buffer FaceLevels { uint faceLevels[]; };

// Face `face`'s level: 0 until its texels are traced again (a new face, or one an
// edit reached), GROTTO_FACE_LEVEL_CONVERGED once they have all their rays.
uint faceLevel(int face) { return (faceLevels[uint(face) >> 4u] >> ((uint(face) & 15u) * 2u)) & 3u; }

#ifdef GROTTO_SHARED_FACE_CACHE_H  // where the cache's taps are read
// Taps `t` less those on faces at level 0: they drop out and the rest are
// reweighted, as at a missing neighbour, so no pixel shows a texel that was never
// traced (a new face beside the view's, read before anything asked for it) or an
// edit left stale. The face under a pixel was traced before the frame read it.
void dropUntraced(inout FaceCacheTaps t) {
    for (int c = 0; c < 4; ++c)
        if (t.weight[c] > 0.0 && faceLevel(t.face[c]) == 0u) t.weight[c] = 0.0;
}
#endif
