#pragma once
// SPIR-V of every shader under shaders/, compiled by glslc at build time and embedded in the binary
// (cmake/EmbedShaders.cmake), so lll runs from any directory without shader files beside it.
#include <cstddef>
#include <cstdint>
#include <span>
#include <string_view>

namespace lll {

struct EmbeddedShader {
  std::string_view path;  // relative to shaders/, e.g. "lighting/forward.frag"
  const uint32_t* words;
  size_t wordCount;
};

// Defined in the generated embedded_shaders.cpp.
std::span<const EmbeddedShader> embeddedShaders();

// The SPIR-V of one shader; throws std::logic_error for a path that was never compiled.
std::span<const uint32_t> shaderCode(std::string_view path);

}  // namespace lll
