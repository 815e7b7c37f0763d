#pragma once
// A CPU device (lavapipe) takes the memory of each frame's work (its binned
// triangles, its shaders' scratch) from this process's heap and frees it as the
// frame ends. glibc's malloc by default gives the heap's top back to the system on
// such a free and maps larger blocks afresh each time, so every frame faulted the
// same pages in again: a test drawing caves' paths spent more time in page faults
// than in its shaders (788,000 faults, 25 s, against 44,000 and 15 s kept). Called
// when Grotto makes its own CPU device: freed blocks up to 32 MiB stay in the heap,
// and up to 256 MiB of free heap top is kept for the next frame. Nothing elsewhere
// (another C library, the sanitizers' allocator, a device a host lends).

namespace grotto::vk {

void keepHeapForCpuDevice();

}  // namespace grotto::vk
