// A voxel face quad as the mesher writes it (8 bytes, chunk-relative), the 4-byte
// vertex the G-buffer pass draws it with, and the 16-bit G-buffer surface id.
// Included by C++ and GLSL.
#ifndef GROTTO_SHARED_QUAD_H
#define GROTTO_SHARED_QUAD_H
#include "common.h"

GROTTO_NAMESPACE_BEGIN

// Faces in the order +X, -X, +Y, -Y, +Z, -Z. A face's U and V axes are chosen so
// that cross(U, V) is its outward normal, which fixes the winding.
#define GROTTO_CHUNK_SIZE 32u

// bits: x 0-4, y 5-9, z 10-14 (minimum voxel of the quad within its chunk),
// w-1 15-19 along U, h-1 20-24 along V, face 25-27. material: palette id.
struct PackedQuad {
    uint bits;
    uint material;
};
GROTTO_STATIC_ASSERT(sizeof(PackedQuad) == 8);

GROTTO_INLINE uint packQuadBits(uint x, uint y, uint z, uint w, uint h, uint face) {
    return x | (y << 5) | (z << 10) | ((w - 1u) << 15) | ((h - 1u) << 20) | (face << 25);
}
GROTTO_INLINE uint quadFace(uint bits) { return (bits >> 25) & 7u; }
GROTTO_INLINE uint quadWidth(uint bits) { return ((bits >> 15) & 31u) + 1u; }
GROTTO_INLINE uint quadHeight(uint bits) { return ((bits >> 20) & 31u) + 1u; }
GROTTO_INLINE uint quadCoord(uint bits, uint axis) { return (bits >> (5u * axis)) & 31u; }
GROTTO_INLINE uint faceAxis(uint face) { return face >> 1; }
GROTTO_INLINE bool facePositive(uint face) { return (face & 1u) == 0u; }
// The face's outward unit normal.
GROTTO_FUNCTION vec3 faceAxisNormal(uint face) {
    vec3 n = vec3(0.0f);
    n[faceAxis(face)] = facePositive(face) ? 1.0f : -1.0f;
    return n;
}
// U axis per face: +X:Y -X:Z +Y:Z -Y:X +Z:X -Z:Y; V axis: +X:Z -X:Y +Y:X -Y:Z +Z:Y -Z:X.
GROTTO_INLINE uint faceUAxis(uint face) { return (0x100221u >> (4u * face)) & 15u; }
GROTTO_INLINE uint faceVAxis(uint face) { return (0x012012u >> (4u * face)) & 15u; }

// A quad corner: x 0-5, y 6-11, z 12-17 (0..32 within the chunk), face 18-20,
// material 21-28. Attribute fetch of one uint is far cheaper on lavapipe than
// pulling quads from a storage buffer.
GROTTO_INLINE uint packVertex(uint x, uint y, uint z, uint face, uint material) {
    return x | (y << 6) | (z << 12) | (face << 18) | (material << 21);
}
GROTTO_INLINE uint vertexCoord(uint v, uint axis) { return (v >> (6u * axis)) & 63u; }
GROTTO_INLINE uint vertexFace(uint v) { return (v >> 18) & 7u; }
GROTTO_INLINE uint vertexMaterial(uint v) { return (v >> 21) & 255u; }

// The G-buffer keeps a surface id instead of normal and albedo: voxel normals are
// one of six axes and albedo comes from the palette. 0 = sky. Bits 11-15 name the
// object the surface belongs to (shared/objects.h; 0 = the world).
GROTTO_INLINE uint packSurface(uint face, uint material) { return (face + 1u) | (material << 3); }
GROTTO_INLINE uint surfaceFace(uint id) { return (id & 7u) - 1u; }
GROTTO_INLINE uint surfaceMaterial(uint id) { return (id >> 3) & 255u; }

GROTTO_NAMESPACE_END
#endif
