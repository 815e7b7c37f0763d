#pragma once
// The SPIR-V of every shader, compiled at build time and built into the library
// (cmake/EmbedShaders.cmake writes the definition), so an installed or embedded
// renderer needs no shader files beside it.
#include <cstddef>
#include <span>

namespace grotto::vk {

struct EmbeddedShader {
    const char* name;             // the source's file name, e.g. "gtao.comp"
    const unsigned char* bytes;   // SPIR-V, 4-byte aligned
    std::size_t size;
};

std::span<const EmbeddedShader> embeddedShaders();

}  // namespace grotto::vk
