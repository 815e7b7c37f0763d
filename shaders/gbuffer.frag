#version 460
// The surface id; built a second time as gbuffer_atlas.frag (GROTTO_FACE_ATLAS)
// with the quad's atlas record beside it (gbuffer.vert), and as
// gbuffer_object_atlas.frag (GROTTO_NO_RECORD) for objects, which have none.
layout(location = 0) flat in uint inSurface;
layout(location = 0) out uint outSurface;
#ifdef GROTTO_FACE_ATLAS
#ifndef GROTTO_NO_RECORD
layout(location = 1) flat in uvec2 inAtlasRecord;
#endif
layout(location = 1) out uvec2 outAtlasRecord;
#endif

void main() {
    outSurface = inSurface;
#ifdef GROTTO_FACE_ATLAS
#ifdef GROTTO_NO_RECORD
    outAtlasRecord = uvec2(0u);
#else
    outAtlasRecord = inAtlasRecord;
#endif
#endif
}
