#pragma once
// VK_CHECK stays on in release builds: a failing call throws grotto::Error naming
// the call and its VkResult.
#include "grotto/error.h"

#include <vulkan/vulkan.h>

namespace grotto::vk {

const char* resultName(VkResult r);

[[noreturn]] void failCall(const char* call, VkResult r, const char* file, int line);

}  // namespace grotto::vk

#define VK_CHECK(call)                                                                  \
    do {                                                                                \
        VkResult vkCheckResult_ = (call);                                               \
        if (vkCheckResult_ != VK_SUCCESS)                                               \
            ::grotto::vk::failCall(#call, vkCheckResult_, __FILE__, __LINE__);          \
    } while (0)
