#pragma once
// In AddressSanitizer builds only: keeps every shared library loaded so far (the
// Vulkan driver, the LLVM it compiles shaders with, the validation layer) loaded
// until the process exits. vkDestroyInstance would otherwise unload them, and the
// leak check at exit would then report the memory they still hold as leaks from
// "<unknown module>", with no way to tell them from ours. Elsewhere it does nothing.

namespace grotto::vk {

void pinLoadedLibraries();

}  // namespace grotto::vk
