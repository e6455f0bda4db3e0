// Analytic checks of the shading: a point and a spot light over a Lambertian-ish plane, read back
// as HDR and compared with the glTF BRDF and KHR_lights_punctual formulas evaluated on the CPU.
#include <glm/gtc/matrix_transform.hpp>

#include "scene/lights.h"
#include "test_support.h"

namespace lll {
namespace {

constexpr float kPi = 3.14159265358979f;

// A 40 m square plane at y = 0 facing up; base colour 0.8, roughness 1, dielectric.
Scene planeScene() {
  Scene scene;
  scene.name = "analytic-plane";
  const float h = 20.0f;
  scene.vertices = {{{-h, 0, -h}, {0, 1, 0}, {0, 0}},
                    {{-h, 0, h}, {0, 1, 0}, {0, 1}},
                    {{h, 0, h}, {0, 1, 0}, {1, 1}},
                    {{h, 0, -h}, {0, 1, 0}, {1, 0}}};
  scene.indices = {0, 1, 2, 0, 2, 3};
  Material m;
  m.name = "plane";
  m.baseColorFactor = glm::vec4(0.8f, 0.8f, 0.8f, 1.0f);
  m.metallic = 0.0f;
  m.roughness = 1.0f;
  scene.materials = {m};
  scene.meshes = {Mesh{"plane", {Primitive{0, 6, 0, 0}}}};
  scene.instances = {Instance{0, glm::mat4(1.0f)}};
  Camera top;
  top.name = "top";
  top.eye = {0.0f, 8.0f, 0.001f};
  top.target = {0.0f, 0.0f, 0.0f};
  top.up = {0.0f, 0.0f, -1.0f};
  top.yfov = kPi / 2.0f;
  scene.cameras = {top};
  return scene;
}

// The same BRDF as shaders/common/brdf.glsl, written independently from the glTF spec.
glm::vec3 expectedRadiance(const Scene& scene, const Light& light, const glm::vec3& p) {
  const glm::vec3 n(0, 1, 0);
  const glm::vec3 v = glm::normalize(scene.cameras[0].eye - p);
  const glm::vec3 toLight = light.position - p;
  const float d = glm::length(toLight);
  if (d >= light.range && light.type != LightType::Box) return glm::vec3(0.0f);
  const glm::vec3 l = toLight / d;
  const float nl = glm::max(glm::dot(n, l), 0.0f);
  const float nv = glm::max(glm::dot(n, v), 1e-4f);
  const glm::vec3 h = glm::normalize(l + v);
  const float nh = glm::max(glm::dot(n, h), 0.0f), vh = glm::max(glm::dot(v, h), 0.0f);
  const float base = 0.8f, a = 1.0f, a2 = a * a;
  const float f = 0.04f + 0.96f * std::pow(1.0f - vh, 5.0f);
  const float dTerm = a2 / (kPi * std::pow(nh * nh * (a2 - 1.0f) + 1.0f, 2.0f));
  const float vis =
      0.5f / (nl * std::sqrt(nv * nv * (1 - a2) + a2) + nv * std::sqrt(nl * nl * (1 - a2) + a2));
  const float brdf = (1.0f - f) * base / kPi + f * dTerm * vis;
  const float window = glm::clamp(1.0f - std::pow(d / light.range, 4.0f), 0.0f, 1.0f);
  float attenuation = window * window / (d * d);
  if (light.type == LightType::Box) {
    // Inverse square inside the box, (1 - x^4)^2 along each axis, x the offset over the half extent.
    const glm::vec3 axes[3] = {light.boxAxisX, light.boxAxisY, glm::cross(light.boxAxisX, light.boxAxisY)};
    attenuation = 1.0f / (d * d);
    for (int i = 0; i < 3; ++i) {
      const float x = glm::dot(p - light.position, axes[i]) / light.halfExtents[i];
      const float w = glm::clamp(1.0f - x * x * x * x, 0.0f, 1.0f);
      attenuation *= w * w;
    }
  }
  if (light.type == LightType::Spot) {
    const float cd = glm::dot(light.direction, -l);
    const float cosOuter = std::cos(light.outerConeAngle), cosInner = std::cos(light.innerConeAngle);
    const float t = glm::clamp((cd - cosOuter) / (cosInner - cosOuter), 0.0f, 1.0f);
    attenuation *= t * t;
  }
  return light.color * light.intensity * attenuation * brdf * nl;
}

// The world point seen at pixel (x, y) of the top camera: intersect the pixel's ray with y = 0.
glm::vec3 groundPoint(const Renderer& renderer, uint32_t x, uint32_t y, uint32_t w, uint32_t h) {
  const glm::mat4& inv = renderer.uniforms().invViewProj;
  const glm::vec2 ndc((x + 0.5f) / w * 2.0f - 1.0f, (y + 0.5f) / h * 2.0f - 1.0f);
  glm::vec4 nearPoint = inv * glm::vec4(ndc, 1.0f, 1.0f);
  glm::vec4 farPoint = inv * glm::vec4(ndc, 0.5f, 1.0f);
  const glm::vec3 a = glm::vec3(nearPoint) / nearPoint.w, b = glm::vec3(farPoint) / farPoint.w;
  const float t = a.y / (a.y - b.y);
  return a + t * (b - a);
}

void checkAgainstFormula(const Scene& scene, const Light& light, int* litPixels, int* darkPixels,
                         const RenderSettings& base = {}) {
  RenderSettings settings = base;
  settings.width = 96;
  settings.height = 96;
  settings.ambient = 0.0f;
  Context& context = test::gpuContext();
  Renderer renderer(context, scene, settings);
  renderer.renderFrame(true);
  const HdrImage hdr = renderer.hdrImage();
  for (uint32_t y = 2; y < settings.height; y += 3) {
    for (uint32_t x = 2; x < settings.width; x += 3) {
      const glm::vec3 p = groundPoint(renderer, x, y, settings.width, settings.height);
      const glm::vec3 expected = expectedRadiance(scene, light, p);
      const glm::vec3 got = glm::vec3(hdr.at(x, y));
      // fp16 storage and a half-pixel position error near steep falloffs bound the tolerance.
      EXPECT_NEAR(got.r, expected.r, 0.01f * expected.r + 2e-4f) << "pixel " << x << "," << y;
      EXPECT_NEAR(got.g, expected.g, 0.01f * expected.g + 2e-4f) << "pixel " << x << "," << y;
      (expected.r > 1e-3f ? *litPixels : *darkPixels) += 1;
    }
  }
  EXPECT_TRUE(context.validationMessages().empty());
}

TEST(Analytic, PointLightOverLambertianPlane) {
  Scene scene = planeScene();
  Light light;
  light.position = {0.0f, 2.0f, 0.0f};
  light.intensity = 10.0f;
  light.range = 6.0f;
  scene.lights = {light};
  int lit = 0, dark = 0;
  checkAgainstFormula(scene, light, &lit, &dark);
  // The range cut-off is inside the view: both lit pixels and pixels beyond the range were checked.
  EXPECT_GT(lit, 200);
  EXPECT_GT(dark, 100);
}

TEST(Analytic, SpotLightConeAndRange) {
  Scene scene = planeScene();
  Light light;
  light.type = LightType::Spot;
  light.position = {0.0f, 3.0f, 0.0f};
  light.direction = {0.0f, -1.0f, 0.0f};
  light.intensity = 50.0f;
  light.range = 8.0f;
  light.innerConeAngle = 20.0f * kPi / 180.0f;
  light.outerConeAngle = 30.0f * kPi / 180.0f;
  scene.lights = {light};
  int lit = 0, dark = 0;
  checkAgainstFormula(scene, light, &lit, &dark);
  EXPECT_GT(lit, 25);
  EXPECT_GT(dark, 500);  // outside the outer cone
}

// A box light standing in the plane, turned 30 degrees: lit inside the box's footprint (its faces
// fade the light to zero), dark outside it even within the bounding radius. Forward and every lll
// fill (shading on the geometry) must give the formula's value.
TEST(Analytic, BoxLightFootprint) {
  Scene scene = planeScene();
  const float turn = 30.0f * kPi / 180.0f;
  const Light light = makeBoxLight({0.5f, 1.0f, 0.0f}, {std::cos(turn), 0.0f, std::sin(turn)},
                                   {0.0f, 1.0f, 0.0f}, {4.0f, 1.5f, 1.5f}, {1.0f, 0.9f, 0.8f}, 6.0f);
  scene.lights = {light};
  for (const char* fill : {"", "compute", "ray", "shells"}) {
    SCOPED_TRACE(*fill ? fill : "forward");
    RenderSettings settings;
    if (*fill) {
      settings.technique = "lll";
      settings.lllFill = fill;
      settings.lllShade = "fragment";
    }
    int lit = 0, dark = 0;
    checkAgainstFormula(scene, light, &lit, &dark, settings);
    EXPECT_GT(lit, 60);
    EXPECT_GT(dark, 500);
  }
}

TEST(Analytic, UnboundedRangeFollowsCutoff) {
  const float range = rangeForUnboundedLight(4.0f, glm::vec3(0.5f, 1.0f, 0.25f));
  EXPECT_NEAR(4.0f * 1.0f / (range * range), kUnboundedLightCutoff, 1e-6f);
}

}  // namespace
}  // namespace lll
