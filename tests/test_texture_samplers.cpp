// glTF's samplers (scene.h's TextureSampler, GpuScene's Vulkan samplers, the ray tracer's
// sampleTexture): wrap modes outside [0, 1], nearest and linear magnification, minification with
// and without mip levels. An emissive quad facing the camera squarely (its texture coordinates
// run linearly across the screen) shows the texture alone, through a fragment path, the visibility
// buffer's compute rebuild and deferred's G-buffer; each check is of what the sampler defines.
#include <gtest/gtest.h>

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <set>
#include <string>

#include "gi/ray_scene.h"
#include "test_support.h"

namespace lll {
namespace sampler_test {

constexpr uint32_t kWidth = 160, kHeight = 90;

struct Path {
  const char* name;
  const char* technique;
  SurfaceSource surfaces;
};
constexpr Path kPaths[] = {{"forward fragment", "forward", SurfaceSource::Gbuffer},
                           {"lll visibility", "lll", SurfaceSource::Visibility},
                           {"deferred visibility", "deferred", SurfaceSource::Visibility}};

// One emissive quad, 2 wide and 1 high at distance 2, texture coordinates u from `u0` to `u1`
// left to right and v from 0 to `vSize` top to bottom, lit by nothing else.
Scene emissiveQuad(const Texture& texture, float u0, float u1, float vSize = 1.0f) {
  Scene scene;
  scene.name = "sampler";
  scene.textures.push_back(texture);
  Material m;
  m.baseColorFactor = glm::vec4(0.0f, 0.0f, 0.0f, 1.0f);
  m.metallic = 0.0f;
  m.emissiveFactor = glm::vec3(1.0f);
  m.emissiveTexture = 0;
  scene.materials.push_back(m);
  const glm::vec2 corners[] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  for (const glm::vec2 c : corners) {
    Vertex v;
    v.position = glm::vec3(-1.0f + 2.0f * c.x, 0.5f - c.y, 0.0f);
    v.normal = glm::vec3(0, 0, 1);
    v.uv = glm::vec2(u0 + (u1 - u0) * c.x, vSize * c.y);
    scene.vertices.push_back(v);
  }
  scene.indices = {0, 2, 1, 0, 3, 2};  // counter-clockwise seen from +z
  Mesh mesh;
  mesh.name = "quad";
  mesh.primitives.push_back({0, 6, 0, 0});
  scene.meshes.push_back(mesh);
  scene.instances.push_back({0, glm::mat4(1.0f)});
  Camera camera;
  camera.name = "front";
  camera.eye = glm::vec3(0, 0, 2);
  camera.target = glm::vec3(0, 0, 0);
  scene.cameras.push_back(camera);
  return scene;
}

// An 8 x 8 texture: red in its left half, blue in its right.
Texture halves(TextureWrap wrap) {
  Texture t;
  t.name = "halves";
  t.width = t.height = 8;
  t.srgb = true;
  for (uint32_t y = 0; y < 8; ++y)
    for (uint32_t x = 0; x < 8; ++x)
      t.rgba.insert(t.rgba.end(), {uint8_t(x < 4 ? 255 : 0), 0, uint8_t(x < 4 ? 0 : 255), 255});
  t.sampler.wrapU = t.sampler.wrapV = wrap;
  return t;
}

// A `size` x `size` black and white checker of single texels.
Texture checker(uint32_t size, const TextureSampler& sampler) {
  Texture t;
  t.name = "checker";
  t.width = t.height = size;
  t.srgb = true;
  for (uint32_t y = 0; y < size; ++y)
    for (uint32_t x = 0; x < size; ++x) {
      const uint8_t c = (x + y) % 2 ? 255 : 0;
      t.rgba.insert(t.rgba.end(), {c, c, c, 255});
    }
  t.sampler = sampler;
  return t;
}

test::Rendered renderPath(const Scene& scene, const Path& p) {
  RenderSettings settings;
  settings.width = kWidth;
  settings.height = kHeight;
  settings.technique = p.technique;
  settings.surfaces = p.surfaces;
  settings.ambient = 0.0f;
  return test::render(scene, settings);
}

const uint8_t* pixel(const LdrImage& image, uint32_t x, uint32_t y) {
  return &image.rgba[(size_t(y) * image.width + x) * 4];
}

// The middle row's columns the quad covers (not black), first and last.
std::pair<uint32_t, uint32_t> quadColumns(const LdrImage& image) {
  uint32_t first = image.width, last = 0;
  for (uint32_t x = 0; x < image.width; ++x) {
    const uint8_t* p = pixel(image, x, image.height / 2);
    if (p[0] + p[1] + p[2] > 0) first = std::min(first, x), last = std::max(last, x);
  }
  return {first, last};
}

// Clamp to edge, repeat and mirrored repeat, each where it differs from the others: across
// u = -1 .. 2, the quarter points u = -0.75, -0.25, 1.25 and 1.75 are red or blue as the wrap
// mode maps them into the texture (red for u in [0, 0.5), blue for [0.5, 1)).
TEST(TextureSamplers, WrapModesMapCoordinatesOutsideTheTexture) {
  struct Case {
    TextureWrap wrap;
    const char* name;
    const char* expected;  // r or b at u = -0.75, -0.25, 1.25, 1.75
  };
  for (const Case& c :
       {Case{TextureWrap::Repeat, "repeat", "rbrb"}, Case{TextureWrap::ClampToEdge, "clamp", "rrbb"},
        Case{TextureWrap::MirroredRepeat, "mirrored", "brbr"}}) {
    const Scene scene = emissiveQuad(halves(c.wrap), -1.0f, 2.0f);
    for (const Path& p : kPaths) {
      const LdrImage image = renderPath(scene, p).ldr;
      const auto [first, last] = quadColumns(image);
      ASSERT_GT(last, first + 60) << c.name << ", " << p.name;
      const float span = float(last + 1 - first);
      const float us[] = {-0.75f, -0.25f, 1.25f, 1.75f};
      for (int i = 0; i < 4; ++i) {
        const uint32_t x = first + uint32_t((us[i] + 1.0f) / 3.0f * span);
        const uint8_t* q = pixel(image, x, image.height / 2);
        const char seen = q[0] > 100 && q[2] < 10 ? 'r' : q[2] > 100 && q[0] < 10 ? 'b' : '?';
        EXPECT_EQ(seen, c.expected[i])
            << c.name << ", " << p.name << ": u = " << us[i] << " at x = " << x << " is (" << int(q[0])
            << ", " << int(q[1]) << ", " << int(q[2]) << ")";
      }
    }
  }
}

// A 2 x 2 checker magnified to about 60 pixels a texel: nearest filtering shows two values across
// the middle row, linear filtering a ramp between them.
TEST(TextureSamplers, MagnificationFilters) {
  for (const TextureFilter filter : {TextureFilter::Nearest, TextureFilter::Linear}) {
    TextureSampler sampler;
    sampler.magnify = filter;
    const Scene scene = emissiveQuad(checker(2, sampler), 0.0f, 1.0f);
    for (const Path& p : kPaths) {
      const LdrImage image = renderPath(scene, p).ldr;
      const auto [first, last] = quadColumns(image);
      std::set<int> values;
      // The checker's black texels are black: the quad's columns come from the row of its white
      // texel, where both texels are in view (the lower row: v > 0.5).
      const uint32_t y = image.height / 2 + 10;
      for (uint32_t x = 0; x < image.width; ++x) values.insert(pixel(image, x, y)[0]);
      const bool nearest = filter == TextureFilter::Nearest;
      if (nearest)
        EXPECT_LE(values.size(), 2u) << p.name;  // black (texel and background) and white
      else
        EXPECT_GT(values.size(), 20u) << p.name;
      EXPECT_GT(last, first) << p.name;
    }
  }
}

// A 64 x 64 single-texel checker shrunk to about 20 pixels: through its mip levels it averages to
// grey; minified with the base level only (glTF's NEAREST), each pixel is one texel, black or white.
TEST(TextureSamplers, MinificationWithAndWithoutMipLevels) {
  for (const MipFilter mip : {MipFilter::Linear, MipFilter::None}) {
    TextureSampler sampler;
    sampler.minify = TextureFilter::Nearest;
    sampler.mip = mip;
    const Scene scene = emissiveQuad(checker(64, sampler), 0.0f, 20.0f, 10.0f);
    for (const Path& p : kPaths) {
      const LdrImage image = renderPath(scene, p).ldr;
      const auto [first, last] = quadColumns(image);
      ASSERT_GT(last, first + 60) << p.name;
      double sum = 0.0, squares = 0.0;
      int count = 0;
      for (uint32_t y = image.height / 2 - 10; y < image.height / 2 + 10; ++y)
        for (uint32_t x = first + 4; x + 4 < last; ++x, ++count) {
          const double v = pixel(image, x, y)[0];
          sum += v, squares += v * v;
        }
      const double mean = sum / count, deviation = std::sqrt(std::max(0.0, squares / count - mean * mean));
      // Black and white texels, one a pixel (about half each), or their average everywhere.
      if (mip == MipFilter::None)
        EXPECT_GT(deviation, 0.35 * mean) << p.name << ", mean " << mean;
      else
        EXPECT_LT(deviation, 0.05 * mean) << p.name << ", mean " << mean;
      EXPECT_GT(mean, 20.0) << p.name;
    }
  }
}

// The CPU ray tracer's sampling (photons, the reference) addresses and filters as the GPU does.
TEST(TextureSamplers, RayTracerSamplesAsTheSamplerDefines) {
  const auto red = [](const glm::vec4& c) { return c.r > 0.99f && c.b < 0.01f; };
  const auto blue = [](const glm::vec4& c) { return c.b > 0.99f && c.r < 0.01f; };
  const float us[] = {-0.75f, -0.25f, 1.25f, 1.75f};
  const std::pair<TextureWrap, const char*> cases[] = {{TextureWrap::Repeat, "rbrb"},
                                                       {TextureWrap::ClampToEdge, "rrbb"},
                                                       {TextureWrap::MirroredRepeat, "brbr"}};
  for (const auto& [wrap, expected] : cases)
    for (int i = 0; i < 4; ++i) {
      const glm::vec4 c = gi::sampleTexture(halves(wrap), glm::vec2(us[i], 0.5f));
      EXPECT_TRUE(expected[i] == 'r' ? red(c) : blue(c)) << int(wrap) << " at " << us[i];
    }
  TextureSampler nearest;
  nearest.magnify = TextureFilter::Nearest;
  // Between a black and a white texel: bilinear blends them, nearest takes the closer one.
  EXPECT_NEAR(gi::sampleTexture(checker(2, {}), glm::vec2(0.5f, 0.25f)).r, 0.5f, 1e-6f);
  EXPECT_NEAR(gi::sampleTexture(checker(2, nearest), glm::vec2(0.45f, 0.25f)).r, 0.0f, 1e-6f);
  EXPECT_NEAR(gi::sampleTexture(checker(2, nearest), glm::vec2(0.55f, 0.25f)).r, 1.0f, 1e-6f);
}

}  // namespace sampler_test
}  // namespace lll
