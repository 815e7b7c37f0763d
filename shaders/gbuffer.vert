#version 460
#extension GL_GOOGLE_include_directive : require
// Pulls quads from the chunk buffer: six vertices per quad, no vertex buffer.
#include "shared/frame.h"
#include "shared/quad.h"

layout(set = 0, binding = 0, std430) readonly buffer Frame { FrameUniforms frame; };
layout(set = 0, binding = 1, std430) readonly buffer Quads { PackedQuad quads[]; };
layout(set = 0, binding = 2, std430) readonly buffer Palette { vec4 albedo[]; };
layout(push_constant) uniform Push { ChunkPush chunk; };

layout(location = 0) flat out uint outFace;
layout(location = 1) flat out vec3 outAlbedo;

// Two CCW triangles over the quad's (u, v) unit square.
const uvec2 kCorners[6] = uvec2[](uvec2(0, 0), uvec2(1, 0), uvec2(1, 1),
                                  uvec2(0, 0), uvec2(1, 1), uvec2(0, 1));

void main() {
    PackedQuad q = quads[gl_VertexIndex / 6];
    uvec2 c = kCorners[gl_VertexIndex % 6];
    uint face = quadFace(q.bits);
    vec3 p = vec3(quadCoord(q.bits, 0u), quadCoord(q.bits, 1u), quadCoord(q.bits, 2u));
    if (facePositive(face)) p[faceAxis(face)] += 1.0;
    p[faceUAxis(face)] += float(c.x * quadWidth(q.bits));
    p[faceVAxis(face)] += float(c.y * quadHeight(q.bits));
    vec3 position = chunk.offsetAndVoxelSize.xyz + p * chunk.offsetAndVoxelSize.w;
    gl_Position = frame.viewProj * vec4(position, 1.0);
    outFace = face;
    outAlbedo = albedo[q.material - 1u].rgb;
}
