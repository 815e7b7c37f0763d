#include "engine/vk/cpu_device_heap.h"

#include "common/sanitizers.h"

#if defined(__GLIBC__) && !GROTTO_ASAN
#include <malloc.h>
#endif

namespace grotto::vk {

void keepHeapForCpuDevice() {
#if defined(__GLIBC__) && !GROTTO_ASAN
    mallopt(M_MMAP_THRESHOLD, 32 << 20);  // glibc's own most, which it grows to by itself
    mallopt(M_TRIM_THRESHOLD, 256 << 20);
#endif
}

}  // namespace grotto::vk
