#pragma once
// A frame's light against the path-traced light of the same view
// (engine/lab/light_reference.h), over the surface pixels: how far the final
// image is from the light transport it approximates (docs/metrics.md, "Light").
#include "engine/lab/light_reference.h"
#include "voxel/luminance.h"

#include <glm/vec3.hpp>

#include <cstddef>
#include <vector>

namespace grotto {

struct LightError {
    size_t pixels = 0;        // surface pixels compared
    double psnr = 0.0;        // dB over RGB of the tone-mapped images as 8-bit sRGB PNGs hold them (peak 1)
    double relativeRmse = 0.0;  // RMSE of linear radiance (RGB) / the reference's mean radiance
    double bias = 0.0;        // mean(image - reference) / mean(reference), luminance
    // Per-pixel relative error of the luminance |a - r| / r where the reference is
    // at least 1% of open ground's (`dim` pixels): median and 95th percentile.
    size_t dimPixels = 0;
    double medianRelative = 0.0, p95Relative = 0.0;
    size_t blackWhereLit = 0;  // of those, pixels the image leaves black (luminance below 1e-6 of the threshold)
};

// `image`: the frame's radiance per pixel (its scene-linear colour over the
// exposure). `openGround`: the luminance white open ground shows under the
// world's lights (openGroundLuminance). `exposure` and `toneMap` make both
// images display values for the PSNR.
LightError lightError(const std::vector<glm::vec3>& image, const LightReference& reference, double openGround,
                      float exposure, unsigned toneMap);

// The luminance a white, flat, unshadowed floor sends back under `lights`: the sun
// at its height plus the sky's light on a face looking up.
double openGroundLuminance(const voxel::LightSources& lights);

using voxel::luminance;  // Rec. 709

}  // namespace grotto
