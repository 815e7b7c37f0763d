#pragma once
// Small pieces the subcommands share: image sizes and the checks that end a run.
#include "engine/vk/context.h"

#include <cstdint>
#include <string>

namespace grotto::app {

struct Size {
    uint32_t width = 0, height = 0;
};

// "WxH" with both in 1..16384; throws grotto::Error (input) naming the option.
Size parseSize(const std::string& text, const std::string& option = "--size");

// Fails the run (exit 1) when the validation layer reported anything.
void requireNoValidationMessages(const vk::Context& ctx);

}  // namespace grotto::app
