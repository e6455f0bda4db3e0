#include "render/tonemap.h"

#include <algorithm>
#include <cmath>
#include <glm/gtc/packing.hpp>

#include "scene/srgb.h"

namespace lll {
namespace {

constexpr float kHalfMax = 65504.0f;

// An RGBA16F target holds at most kHalfMax; a larger value is stored as infinity, which the shader
// reads back as kHalfMax (common/finite.glsl).
float throughHalfFloat(float x) {
  const float stored = glm::unpackHalf1x16(glm::packHalf1x16(x));
  return std::isinf(stored) ? std::copysign(kHalfMax, stored) : stored;
}

float filmic(float x) {
  x = std::min(x, kHalfMax);
  return std::clamp((x * (2.51f * x + 0.03f)) / (x * (2.43f * x + 0.59f) + 0.14f), 0.0f, 1.0f);
}

uint8_t toUnorm8(float c) {
  if (!(c > 0.0f)) return 0;
  return uint8_t(std::lround(std::min(c, 1.0f) * 255.0f));
}

}  // namespace

LdrImage tonemapFilmic(const HdrImage& hdr, float exposure) {
  LdrImage ldr{hdr.width, hdr.height, std::vector<uint8_t>(size_t(hdr.width) * hdr.height * 4)};
  for (size_t i = 0; i < size_t(hdr.width) * hdr.height; ++i) {
    for (size_t c = 0; c < 3; ++c) {
      const float radiance = std::max(throughHalfFloat(hdr.rgba[i * 4 + c]) * exposure, 0.0f);
      ldr.rgba[i * 4 + c] = toUnorm8(srgbEncode(filmic(radiance)));
    }
    ldr.rgba[i * 4 + 3] = 255;
  }
  return ldr;
}

}  // namespace lll
