// Lets one header declare a struct that both C++ and GLSL read. In C++ the GLSL vector and matrix
// types map onto glm and every shared struct lives in namespace lll::gpu; GLSL sees plain structs.
// Use only 16-byte-aligned members in order (vec4, uvec4, mat4, or four scalars), so std140,
// std430 and C++ agree on every offset; the C++ side static_asserts the size of each struct.
#ifndef LLL_SHARED_H
#define LLL_SHARED_H

#ifdef __cplusplus
#include <cstdint>
#include <glm/glm.hpp>
#define LLL_NAMESPACE_BEGIN \
  namespace lll::gpu {      \
  using vec2 = glm::vec2;   \
  using uvec2 = glm::uvec2; \
  using vec4 = glm::vec4;   \
  using uvec4 = glm::uvec4; \
  using ivec4 = glm::ivec4; \
  using mat4 = glm::mat4;   \
  using uint = uint32_t;    \
  using vec3 = glm::vec3;   \
  using glm::ceil;          \
  using glm::clamp;         \
  using glm::log;           \
  using glm::pow;           \
  using glm::dot;           \
  using glm::max;           \
  using glm::min;
#define LLL_NAMESPACE_END }
// Functions shared by C++ and GLSL are written in the common subset of both languages.
#define LLL_FUNCTION inline
#define LLL_CONST(type, name, value) inline constexpr type name = value
#define LLL_CHECK_SIZE(T, bytes) static_assert(sizeof(T) == (bytes), #T " must match its GLSL layout")
#else
#define LLL_NAMESPACE_BEGIN
#define LLL_NAMESPACE_END
#define LLL_CONST(type, name, value) const type name = value
#define LLL_CHECK_SIZE(T, bytes)
#define LLL_FUNCTION
#endif

#endif
