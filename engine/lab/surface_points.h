#pragma once
// The G-buffer's surface points in double precision, for the reference AO: the
// same points and normals the screen-space method sees, snapped onto the voxel
// face planes they lie on so that float depth never puts a point inside a voxel.
#include "engine/camera.h"
#include "engine/frame/frame_images.h"
#include "voxel/reference_ao.h"

#include <cstdint>
#include <vector>

namespace grotto {

struct SurfacePoints {
    std::vector<glm::dvec3> points, normals;  // world units; normals axis-aligned, unit
    std::vector<uint32_t> pixels;             // y * width + x of each point; sky pixels have none
    std::vector<uint32_t> owners;             // 0: the world's voxels; k: the frame's object k (objects[k - 1])
};

// Needs a readback with AOVs. voxelSize and origin (voxel corner 0,0,0) place the
// face planes: each point's coordinate along its normal is set to the nearest one.
SurfacePoints surfacePoints(const FrameImages& frame, const Camera& camera, double voxelSize, glm::dvec3 origin);
// With objects (the frame's, at its poses; object k of the surface ids is objects[k - 1]):
// an object pixel's point is snapped onto its face plane in the object's own grid.
SurfacePoints surfacePoints(const FrameImages& frame, const Camera& camera, const voxel::World& world,
                            std::span<const voxel::PosedWorld> objects);

}  // namespace grotto
