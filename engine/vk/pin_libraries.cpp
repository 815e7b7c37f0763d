#include "engine/vk/pin_libraries.h"

#include "common/sanitizers.h"

#if GROTTO_ASAN
#include <dlfcn.h>
#include <link.h>
#endif

namespace grotto::vk {

void pinLoadedLibraries() {
#if GROTTO_ASAN
    // RTLD_NOLOAD finds a library already loaded; RTLD_NODELETE then makes any
    // later dlclose of it (the Vulkan loader's) leave it in place.
    dl_iterate_phdr([](dl_phdr_info* info, size_t, void*) {
        if (info->dlpi_name && *info->dlpi_name) dlopen(info->dlpi_name, RTLD_LAZY | RTLD_NOLOAD | RTLD_NODELETE);
        return 0;
    }, nullptr);
#endif
}

}  // namespace grotto::vk
