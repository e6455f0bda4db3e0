#include "scene/builtin_textures.h"

#include <cmath>
#include <functional>
#include <glm/gtc/constants.hpp>

#include "scene/hash.h"
#include "scene/srgb.h"

namespace lll::builtin {

namespace {

constexpr uint32_t kSize = 256;

uint32_t hash(uint32_t x, uint32_t y, uint32_t seed) {
  return lowbias32(x * 0x8da6b343u ^ y * 0xd8163841u ^ seed * 0xcb1ab31fu);
}

float hash01(uint32_t x, uint32_t y, uint32_t seed) {
  return float(hash(x, y, seed) & 0xffffffu) / 16777216.0f;
}

// Value noise on a lattice of periodX x periodY cells over the unit square; it wraps at the edges,
// so every texture made from it tiles.
float noise(float x, float y, uint32_t periodX, uint32_t periodY, uint32_t seed) {
  const float fx = x * float(periodX), fy = y * float(periodY);
  const float ix = std::floor(fx), iy = std::floor(fy);
  const float tx = glm::smoothstep(0.0f, 1.0f, fx - ix), ty = glm::smoothstep(0.0f, 1.0f, fy - iy);
  auto at = [&](float cx, float cy) {
    const auto wx = uint32_t(int64_t(cx) % periodX + periodX) % periodX;
    const auto wy = uint32_t(int64_t(cy) % periodY + periodY) % periodY;
    return hash01(wx, wy, seed);
  };
  const float top = glm::mix(at(ix, iy), at(ix + 1, iy), tx);
  const float bottom = glm::mix(at(ix, iy + 1), at(ix + 1, iy + 1), tx);
  return glm::mix(top, bottom, ty);
}

// Fractal sum of `octaves` noises from a base period, normalised to [0, 1].
float fbm(float x, float y, uint32_t period, int octaves, uint32_t seed) {
  float sum = 0.0f, amplitude = 0.5f, total = 0.0f;
  for (int o = 0; o < octaves; ++o) {
    sum += amplitude * noise(x, y, period << o, period << o, seed + uint32_t(o));
    total += amplitude;
    amplitude *= 0.5f;
  }
  return sum / total;
}

uint8_t toSrgb8(float linear) {
  const float c = glm::clamp(linear, 0.0f, 1.0f);
  return uint8_t(std::lround(srgbEncode(c) * 255.0f));
}

// A colour texture whose texel (x, y) is `shade(x, y)` in linear RGB.
Texture makeTexture(const char* name, const std::function<glm::vec3(uint32_t, uint32_t)>& shade) {
  Texture texture;
  texture.name = name;
  texture.width = texture.height = kSize;
  texture.srgb = true;
  texture.rgba.resize(size_t(kSize) * kSize * 4);
  for (uint32_t y = 0; y < kSize; ++y) {
    for (uint32_t x = 0; x < kSize; ++x) {
      const glm::vec3 c = shade(x, y);
      uint8_t* texel = &texture.rgba[(size_t(y) * kSize + x) * 4];
      texel[0] = toSrgb8(c.r);
      texel[1] = toSrgb8(c.g);
      texel[2] = toSrgb8(c.b);
      texel[3] = 255;
    }
  }
  return texture;
}

// Distance in texels from (x, y) to the nearest edge of its cell in a grid of cellW x cellH.
float distanceToCellEdge(uint32_t x, uint32_t y, uint32_t cellW, uint32_t cellH) {
  const float dx = std::min(float(x % cellW) + 0.5f, float(cellW - x % cellW) - 0.5f);
  const float dy = std::min(float(y % cellH) + 0.5f, float(cellH - y % cellH) - 0.5f);
  return std::min(dx, dy);
}

glm::vec2 unit(uint32_t x, uint32_t y) {
  return glm::vec2(float(x), float(y)) / float(kSize);
}

}  // namespace

Texture makeFloorTilesTexture() {
  return makeTexture("builtin floor tiles", [](uint32_t x, uint32_t y) {
    constexpr uint32_t kTile = kSize / 4;
    const uint32_t tx = x / kTile, ty = y / kTile;
    const bool dark = (tx + ty) % 2 == 1;
    glm::vec3 stone = dark ? glm::vec3(0.30f, 0.17f, 0.12f) : glm::vec3(0.56f, 0.49f, 0.39f);
    stone *= 0.88f + 0.24f * hash01(tx, ty, 11);
    const glm::vec2 p = unit(x, y);
    stone *= 0.8f + 0.35f * fbm(p.x, p.y, 8, 5, dark ? 21u : 31u);
    const float edge = distanceToCellEdge(x, y, kTile, kTile);
    if (edge < 1.5f) return glm::vec3(0.12f, 0.11f, 0.10f);
    return edge < 4.0f ? stone * 0.85f : stone;
  });
}

Texture makeAshlarTexture() {
  return makeTexture("builtin ashlar", [](uint32_t x, uint32_t y) {
    constexpr uint32_t kBlockW = kSize / 2, kBlockH = kSize / 4;
    const uint32_t row = y / kBlockH;
    const uint32_t shifted = (x + (row % 2) * kBlockW / 2) % kSize;
    const glm::vec2 p = unit(x, y);
    glm::vec3 stone = glm::vec3(0.52f, 0.42f, 0.30f) * (0.85f + 0.25f * hash01(shifted / kBlockW, row, 41));
    stone *= 0.78f + 0.35f * fbm(p.x, p.y, 8, 5, 43);
    const float edge = distanceToCellEdge(shifted, y, kBlockW, kBlockH);
    if (edge < 1.5f) return glm::vec3(0.26f, 0.23f, 0.19f);
    return edge < 3.5f ? stone * 0.9f : stone;
  });
}

Texture makePlasterTexture() {
  return makeTexture("builtin plaster", [](uint32_t x, uint32_t y) {
    const glm::vec2 p = unit(x, y);
    const float blotches = fbm(p.x, p.y, 4, 6, 51);
    return glm::vec3(0.70f, 0.60f, 0.47f) * (0.78f + 0.35f * blotches);
  });
}

Texture makeWoodTexture() {
  return makeTexture("builtin wood", [](uint32_t x, uint32_t y) {
    constexpr uint32_t kPlank = kSize / 8;
    const uint32_t plank = x / kPlank;
    const glm::vec2 p = unit(x, y);
    // Grain: noise stretched along the plank, a few octaves of it.
    const float grain = 0.6f * noise(p.x, p.y, 64, 4, 61) + 0.4f * noise(p.x, p.y, 128, 8, 62);
    glm::vec3 wood = glm::vec3(0.30f, 0.15f, 0.06f) * (0.7f + 0.6f * grain);
    wood *= 0.8f + 0.4f * hash01(plank, 0, 63);
    const uint32_t joint = hash(plank, 1, 64) % kSize;
    if (x % kPlank == 0 || y == joint) return wood * 0.45f;
    return wood;
  });
}

Texture makeMarbleTexture() {
  return makeTexture("builtin marble", [](uint32_t x, uint32_t y) {
    const glm::vec2 p = unit(x, y);
    const float turbulence = fbm(p.x, p.y, 4, 6, 71);
    const float wave = std::sin(2.0f * glm::pi<float>() * (2.0f * p.x + p.y) + 9.0f * turbulence);
    const float vein = std::pow(1.0f - std::abs(wave), 10.0f);
    const glm::vec3 white = glm::vec3(0.80f, 0.77f, 0.72f) * (0.92f + 0.1f * fbm(p.x, p.y, 16, 3, 72));
    return glm::mix(white, glm::vec3(0.32f, 0.31f, 0.33f), 0.8f * vein);
  });
}

Texture makeBannerTexture() {
  return makeTexture("builtin banner", [](uint32_t x, uint32_t y) {
    const glm::vec2 p = unit(x, y);
    const float weave = ((x / 2 + y / 2) % 2 == 0) ? 1.0f : 0.93f;
    float value = 0.72f * weave * (0.9f + 0.15f * fbm(p.x, p.y, 8, 3, 81));
    // A banner is about three times as long as it is wide: measure the emblem in metres-like units.
    const glm::vec2 d(p.x - 0.5f, 3.0f * (p.y - 0.3f));
    const float radius = glm::length(d);
    const bool ring = radius > 0.26f && radius < 0.32f;
    const bool diamond = std::abs(d.x) + std::abs(d.y) < 0.18f;
    const bool border = p.x < 0.08f || p.x > 0.92f || p.y < 0.04f || (p.y > 0.66f && p.y < 0.70f);
    const bool trim = (p.x > 0.1f && p.x < 0.12f) || (p.x > 0.88f && p.x < 0.9f);
    if (ring || diamond || trim) value = 1.0f;
    if (border) value = 0.25f;
    return glm::vec3(value);
  });
}

}  // namespace lll::builtin
