#pragma once
// The sRGB transfer function (IEC 61966-2-1) on the CPU: colour textures are stored encoded, the
// renderer shades in linear light, and display images are encoded again.
#include <cmath>

namespace lll {

inline float srgbEncode(float linear) {
  return linear <= 0.0031308f ? 12.92f * linear : 1.055f * std::pow(linear, 1.0f / 2.4f) - 0.055f;
}

inline float srgbDecode(float encoded) {
  return encoded <= 0.04045f ? encoded / 12.92f : std::pow((encoded + 0.055f) / 1.055f, 2.4f);
}

}  // namespace lll
