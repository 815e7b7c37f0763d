#version 460
#extension GL_GOOGLE_include_directive : require
// Quad corners from a 4-byte vertex; chunk corner and voxel size from push constants.
// The position depends on the corner's voxel index only (shared/frame.h: ChunkPush).
// Built a second time as gbuffer_atlas.vert (GROTTO_FACE_ATLAS): each quad's
// record in the face cache's atlas too, from a buffer parallel to the vertices
// (engine/scene/face_atlas.h), which the fragment shader writes for the composite.
#include "shared/frame.h"
#include "shared/quad.h"

layout(set = 0, binding = 0, std140) uniform Frame { FrameUniforms frame; };
layout(push_constant) uniform Push { ChunkPush chunk; };

layout(location = 0) in uint inVertex;
layout(location = 0) flat out uint outSurface;
#ifdef GROTTO_FACE_ATLAS
layout(set = 0, binding = 1, std430) readonly buffer AtlasRecords { uvec2 atlasRecords[]; };
layout(location = 1) flat out uvec2 outAtlasRecord;
#endif

void main() {
    ivec3 voxel = chunk.voxel.xyz + ivec3(vertexCoord(inVertex, 0u), vertexCoord(inVertex, 1u), vertexCoord(inVertex, 2u));
    vec3 position = (vec3(voxel) - chunk.cameraAndVoxelSize.xyz) * chunk.cameraAndVoxelSize.w;
    gl_Position = frame.viewProj * vec4(position, 1.0);
    outSurface = packSurface(vertexFace(inVertex), vertexMaterial(inVertex));
#ifdef GROTTO_FACE_ATLAS
    outAtlasRecord = atlasRecords[uint(gl_VertexIndex) >> 2u];  // 4 vertices a quad, from the draw's vertex offset
#endif
}
