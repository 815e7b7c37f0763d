#include "engine/lab/ao_metrics.h"

#include "grotto/error.h"

#include <cmath>
#include <limits>
#include <string>

namespace grotto {

AoError aoError(std::span<const float> ao, std::span<const float> reference, std::span<const uint8_t> mask) {
    if (ao.size() != reference.size() || ao.size() != mask.size())
        throw Error::internal("aoError", "image sizes differ: " + std::to_string(ao.size()) + ", " +
                                             std::to_string(reference.size()) + ", mask " + std::to_string(mask.size()));
    // Sums in double: 4K frames have 8 M pixels.
    double sumAbs = 0.0, sumSq = 0.0, sum = 0.0;
    AoError e;
    for (size_t i = 0; i < ao.size(); ++i) {
        if (!mask[i]) continue;
        const double d = double(ao[i]) - double(reference[i]);
        sum += d;
        sumAbs += std::abs(d);
        sumSq += d * d;
        ++e.pixels;
    }
    if (e.pixels == 0) {
        e.psnr = std::numeric_limits<double>::infinity();
        return e;
    }
    const double n = double(e.pixels), mse = sumSq / n;
    e.mae = sumAbs / n;
    e.rmse = std::sqrt(mse);
    e.bias = sum / n;
    e.psnr = mse > 0.0 ? -10.0 * std::log10(mse) : std::numeric_limits<double>::infinity();
    return e;
}

}  // namespace grotto
