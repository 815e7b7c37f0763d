#pragma once
// Error of an AO image against the reference (docs/metrics.md):
// over the pixels the mask marks (non-sky), MAE, RMSE, PSNR with peak 1.0 and the
// mean signed bias (method - reference). Plain arithmetic, no Vulkan: the tradeoff
// and stability commands and the tests all use it.
#include <cstddef>
#include <cstdint>
#include <span>

namespace grotto {

struct AoError {
    double mae = 0.0, rmse = 0.0;
    double psnr = 0.0;  // dB, 10 log10(1 / MSE); +inf when the images agree exactly
    double bias = 0.0;  // mean of (ao - reference): negative = too dark
    size_t pixels = 0;  // pixels compared; all figures are 0 (psnr +inf) when none
};

// `mask` is non-zero where a pixel counts; the three spans must be the same size
// (throws grotto::Error, internal, otherwise).
AoError aoError(std::span<const float> ao, std::span<const float> reference, std::span<const uint8_t> mask);

}  // namespace grotto
