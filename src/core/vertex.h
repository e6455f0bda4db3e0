#pragma once
// The vertex every mesh is made of: what the scene's loaders write, the GPU layer describes to the
// rasterizer (gpu/pipeline.cpp) and the surface rebuild reads as bits
// (shaders/common/visibility_surface.glsl). In core/, below gpu/ and scene/, so that the GPU layer
// needs nothing of the scene.
#include <cstdint>
#include <glm/glm.hpp>
#include <glm/gtc/packing.hpp>

namespace lll {

struct Vertex {
  glm::vec3 position;
  glm::vec3 normal;
  glm::vec2 uv;
  // glTF's TANGENT: xyz the unit tangent (along +u), w the bitangent's handedness (+1 or -1);
  // w = 0 where the file gives none, and shaders build the frame from screen derivatives.
  glm::vec4 tangent{0.0f};
  glm::vec2 uv1{0.0f};  // glTF's TEXCOORD_1, for the textures whose texCoord is 1
  // glTF's COLOR_0 (linear RGBA, multiplying the base colour), four half floats; white where the
  // file gives none.
  glm::uvec2 color{kWhiteHalf2, kWhiteHalf2};

  static constexpr uint32_t kWhiteHalf2 = 0x3C003C00u;  // packHalf2x16(1, 1)
  void setColor(const glm::vec4& rgba) {
    color = glm::uvec2(glm::packHalf2x16(glm::vec2(rgba.r, rgba.g)),
                       glm::packHalf2x16(glm::vec2(rgba.b, rgba.a)));
  }
  glm::vec4 rgba() const { return glm::vec4(glm::unpackHalf2x16(color.x), glm::unpackHalf2x16(color.y)); }
};
static_assert(sizeof(Vertex) == 64);

}  // namespace lll
