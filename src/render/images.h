#pragma once
// A rendered frame read back to the CPU: linear radiance (HDR) and the display image (LDR).
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include <algorithm>
#include <cstdint>
#include <vector>

namespace lll {

struct HdrImage {
  uint32_t width = 0;
  uint32_t height = 0;
  std::vector<float> rgba;  // linear radiance, row 0 at the top
  glm::vec4 at(uint32_t x, uint32_t y) const {
    const float* p = &rgba[(size_t(y) * width + x) * 4];
    return {p[0], p[1], p[2], p[3]};
  }
  // From linear RGB, alpha 1: radiance made on the CPU (the path-traced reference).
  static HdrImage fromRgb(uint32_t width, uint32_t height, const std::vector<glm::vec3>& rgb) {
    HdrImage image{width, height, std::vector<float>(rgb.size() * 4, 1.0f)};
    for (size_t i = 0; i < rgb.size(); ++i) std::copy_n(&rgb[i].x, 3, &image.rgba[i * 4]);
    return image;
  }
};

struct LdrImage {
  uint32_t width = 0;
  uint32_t height = 0;
  std::vector<uint8_t> rgba;  // sRGB-encoded, row 0 at the top
};

}  // namespace lll
