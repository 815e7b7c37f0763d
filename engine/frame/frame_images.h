#pragma once
// A frame read back to host memory: what image files, metrics and the reference
// consume, without depending on the renderer that made it.
#include "shaders/shared/tone_map.h"

#include <cstdint>
#include <vector>

namespace grotto {

// A frame read back to host memory; pixel (x, y) at index y * width + x, row 0 on top.
// Half-resolution AOVs are stored at full size, each pixel taking its half-res
// pixel (x / 2, y / 2).
struct FrameImages {
    uint32_t width = 0, height = 0;
    std::vector<float> color;      // scene-linear RGBA: radiance x exposure, no tone map (values above 1 are normal)
    uint32_t toneMap = GROTTO_TONE_MAP_FILMIC;  // the curve that makes `color` display values (shared/tone_map.h)
    std::vector<float> depth;      // view-axis distance in world units; +inf for sky
    std::vector<float> normal;     // world-space xyz; 0 for sky
    std::vector<float> bentNormal; // VBAO: the mean open direction, world-space xyz (half res); 0 for sky;
                                   // empty with other methods
    std::vector<float> albedo;     // linear rgb; 0 for sky
    std::vector<float> ao;         // final visibility, full res (1 without AO)
    std::vector<float> aoRaw;      // the estimator's output (half res)
    std::vector<float> aoSpatial;  // after the spatial denoiser (half res)
    std::vector<float> aoTemporal; // after the temporal pass (half res; the spatial AO without one)
    std::vector<float> aoHistory;  // frames of history behind each temporal pixel (half res; 1 without)
    std::vector<float> edges;      // smallest of the four edge weights (half res)
    std::vector<float> depthBuffer;       // raw reverse-Z values, as the GPU stored them
    std::vector<uint16_t> surfaceIds;     // raw G-buffer surface ids
    std::vector<float> aoRawHalf;         // the estimator's output at half res: visibility, packed edges
    std::vector<float> motion;            // where objects move: xy previous minus current pixel, z previous
                                          // view depth, 0 for sky (4 floats a pixel); empty otherwise
    std::vector<float> shadow;            // 1 where the sun reaches a surface, 0 where it does not (full res;
                                          // 1 everywhere without sun shadows)
    std::vector<float> light;             // the face cache's light at each pixel, irradiance over pi, linear
                                          // rgb before exposure (the full light, or the sky's); 0 where it has
                                          // none; empty without a face cache
};

}  // namespace grotto
