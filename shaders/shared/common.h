// Lets one header declare structs and small functions for both C++ and GLSL.
#ifndef GROTTO_SHARED_COMMON_H
#define GROTTO_SHARED_COMMON_H

#ifdef __cplusplus
#include <cstdint>
#include <glm/glm.hpp>
#define GROTTO_NAMESPACE_BEGIN namespace grotto::gpu { using uint = uint32_t; using glm::vec2; \
    using glm::vec3; using glm::vec4; using glm::mat4; using glm::uvec2; using glm::uvec4; using glm::ivec2; using glm::ivec4;
#define GROTTO_NAMESPACE_END }
#define GROTTO_INLINE inline constexpr
#define GROTTO_FUNCTION inline  // not constexpr: it calls GLM
#define GROTTO_STATIC_ASSERT(x) static_assert(x, #x)
#else
#define GROTTO_NAMESPACE_BEGIN
#define GROTTO_NAMESPACE_END
#define GROTTO_INLINE
#define GROTTO_FUNCTION
#define GROTTO_STATIC_ASSERT(x)
#endif

#endif
