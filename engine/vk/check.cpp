#include "engine/vk/check.h"

#include <string>

namespace grotto::vk {

const char* resultName(VkResult r) {
    switch (r) {
#define GROTTO_RESULT(x) case x: return #x;
        GROTTO_RESULT(VK_SUCCESS)
        GROTTO_RESULT(VK_NOT_READY)
        GROTTO_RESULT(VK_TIMEOUT)
        GROTTO_RESULT(VK_INCOMPLETE)
        GROTTO_RESULT(VK_ERROR_OUT_OF_HOST_MEMORY)
        GROTTO_RESULT(VK_ERROR_OUT_OF_DEVICE_MEMORY)
        GROTTO_RESULT(VK_ERROR_INITIALIZATION_FAILED)
        GROTTO_RESULT(VK_ERROR_DEVICE_LOST)
        GROTTO_RESULT(VK_ERROR_MEMORY_MAP_FAILED)
        GROTTO_RESULT(VK_ERROR_LAYER_NOT_PRESENT)
        GROTTO_RESULT(VK_ERROR_EXTENSION_NOT_PRESENT)
        GROTTO_RESULT(VK_ERROR_FEATURE_NOT_PRESENT)
        GROTTO_RESULT(VK_ERROR_INCOMPATIBLE_DRIVER)
        GROTTO_RESULT(VK_ERROR_TOO_MANY_OBJECTS)
        GROTTO_RESULT(VK_ERROR_FORMAT_NOT_SUPPORTED)
        GROTTO_RESULT(VK_ERROR_FRAGMENTED_POOL)
        GROTTO_RESULT(VK_ERROR_OUT_OF_POOL_MEMORY)
#undef GROTTO_RESULT
        default: return "VkResult(unknown)";
    }
}

void failCall(const char* call, VkResult r, const char* file, int line) {
    throw Error::internal(std::string(file) + ":" + std::to_string(line),
                          std::string(call) + " failed with " + resultName(r) + " (" +
                              std::to_string(int(r)) + ")");
}

}  // namespace grotto::vk
