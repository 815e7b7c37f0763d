#pragma once
// The CPU twin of the GTAO and VBAO main passes: the same kernel source (shaders/
// shared/gtao_kernel.h), the same noise and the same depth MIP chain, run on a
// read-back G-buffer. Tests use it to pin the GPU result.
#include "shaders/shared/gtao.h"

#include <glm/glm.hpp>

#include <array>
#include <cstdint>
#include <vector>

namespace grotto {

class GtaoTwin {
public:
    // depthBuffer: full-res reverse-Z values as stored; surface: full-res ids;
    // vbao: the kernel as vbao.comp compiles it (each slice a sector bitmask).
    GtaoTwin(const gpu::GtaoConstants& constants, std::vector<float> depthBuffer, std::vector<uint16_t> surface,
             bool vbao = false);
    ~GtaoTwin();

    // Visibility and packed edges at a half-resolution pixel.
    glm::vec2 pixel(glm::ivec2 halfPixel) const;
    // VBAO's bent normal there (world space, unit length; zero for the sky).
    glm::vec3 bentNormal(glm::ivec2 halfPixel) const;

private:
    struct Kernel;
    Kernel* kernel_;
    bool vbao_;
};

}  // namespace grotto
