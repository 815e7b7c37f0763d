#include "app/options.h"

#include "common/error.h"

#include <cstdio>

namespace grotto::app {

Size parseSize(const std::string& text, const std::string& option) {
    unsigned w = 0, h = 0;
    char extra = 0;
    if (std::sscanf(text.c_str(), "%ux%u%c", &w, &h, &extra) != 2 || w < 1 || h < 1 || w > 16384 || h > 16384)
        throw Error(option, "'" + text + "' is not a valid size", "expected WxH with both in 1..16384, e.g. 1280x720");
    return {w, h};
}

void requireNoValidationMessages(const vk::Context& ctx) {
    if (ctx.validationMessages() > 0)
        throw Error::internal("vulkan", std::to_string(ctx.validationMessages()) +
                                            " validation message(s) reported (printed above)");
}

}  // namespace grotto::app
