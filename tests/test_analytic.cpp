// Analytic checks of the shading, through every shading path (forward, lll on the geometry and in
// compute over the G-buffer, deferred, the light pre-pass): lights over a plane seen from above,
// read back as HDR and compared per pixel with the glTF 2.0 BRDF (Appendix B) and
// KHR_lights_punctual evaluated on the CPU, written here from the specification, not from the
// shaders. Normal maps, in the file's tangent frame and in the one built from derivatives, and
// partly metallic materials are checked the same way.
#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <optional>

#include "scene/lights.h"
#include "shadows/local_shadows.h"
#include "test_support.h"

namespace lll {
namespace {

using test::kPi;

// The plane's material and, optionally, a constant normal map and the file's tangents.
struct PlaneMaterial {
  glm::vec3 baseColor{0.8f};
  float metallic = 0.0f;
  float roughness = 1.0f;
  std::optional<glm::u8vec3> normalTexel;  // one texel, linear: the tangent-space normal * 127.5 + 127.5
  std::optional<glm::vec4> tangent;        // TANGENT of every vertex (glTF: xyz, w handedness)
};

// A 40 m square plane at y = 0 facing up, u along +x and v along +z, seen from 8 m above.
Scene planeScene(const PlaneMaterial& pm = {}) {
  Scene scene;
  scene.name = "analytic-plane";
  const float h = 20.0f;
  scene.vertices = {{{-h, 0, -h}, {0, 1, 0}, {0, 0}},
                    {{-h, 0, h}, {0, 1, 0}, {0, 1}},
                    {{h, 0, h}, {0, 1, 0}, {1, 1}},
                    {{h, 0, -h}, {0, 1, 0}, {1, 0}}};
  if (pm.tangent)
    for (Vertex& v : scene.vertices) v.tangent = *pm.tangent;
  scene.indices = {0, 1, 2, 0, 2, 3};
  Material m;
  m.name = "plane";
  m.baseColorFactor = glm::vec4(pm.baseColor, 1.0f);
  m.metallic = pm.metallic;
  m.roughness = pm.roughness;
  if (pm.normalTexel) {
    scene.textures.push_back(
        Texture{"normal", 1, 1, {pm.normalTexel->x, pm.normalTexel->y, pm.normalTexel->z, 255}, false});
    m.normalTexture = 0;
  }
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

// The plane's shading normal: glTF's tangent frame (T the tangent, or +u = +x; B = cross(N, T) * w)
// applied to the decoded texel.
glm::vec3 shadingNormal(const PlaneMaterial& pm) {
  const glm::vec3 n(0, 1, 0);
  if (!pm.normalTexel) return n;
  const glm::vec3 t = pm.tangent ? glm::vec3(*pm.tangent) : glm::vec3(1, 0, 0);
  const float w = pm.tangent ? pm.tangent->w : 1.0f;
  const glm::vec3 b = glm::cross(n, t) * w;
  const glm::vec3 texel = glm::vec3(*pm.normalTexel) / 255.0f * 2.0f - 1.0f;
  return glm::normalize(texel.x * t + texel.y * b + texel.z * n);
}

// glTF 2.0 Appendix B: mix(dielectric_brdf, metal_brdf, metallic), where the dielectric is
// fresnel_mix(ior 1.5: f0 = 0.04, diffuse, specular) and the metal conductor_fresnel(base,
// specular); specular = D * V (GGX, height-correlated Smith), Fresnel by Schlick. Times n.l.
// `distributionAlpha` > 0 replaces the surface's alpha in the distribution D alone (a virtual point
// light's lobe, widened by the patch it stands for).
glm::vec3 brdfCosine(const PlaneMaterial& pm, glm::vec3 n, glm::vec3 v, glm::vec3 l,
                     float distributionAlpha = 0.0f) {
  const float nl = glm::dot(n, l);
  if (nl <= 0.0f) return glm::vec3(0.0f);
  const float nv = glm::max(glm::dot(n, v), 1e-4f);
  const glm::vec3 h = glm::normalize(l + v);
  const float nh = glm::max(glm::dot(n, h), 0.0f), vh = glm::clamp(glm::dot(v, h), 0.0f, 1.0f);
  const float a = glm::max(pm.roughness * pm.roughness, 1e-3f), a2 = a * a;
  const float ad = distributionAlpha > 0.0f ? distributionAlpha : a, ad2 = ad * ad;
  const float d = ad2 / (kPi * std::pow(nh * nh * (ad2 - 1.0f) + 1.0f, 2.0f));
  const float vis =
      0.5f / (nl * std::sqrt(nv * nv * (1 - a2) + a2) + nv * std::sqrt(nl * nl * (1 - a2) + a2));
  const float specular = d * vis;
  const float schlick = std::pow(1.0f - vh, 5.0f);
  const float dielectricF = 0.04f + 0.96f * schlick;
  const glm::vec3 dielectric = (1.0f - dielectricF) * pm.baseColor / kPi + dielectricF * specular;
  const glm::vec3 metal = (pm.baseColor + (1.0f - pm.baseColor) * schlick) * specular;
  return glm::mix(dielectric, metal, pm.metallic) * nl;
}

// KHR_lights_punctual: intensity / d^2 times the range window (or a box light's window), times the
// spot's smooth cone.
float attenuation(const Light& light, const glm::vec3& p) {
  const glm::vec3 toLight = light.position - p;
  const float d = glm::length(toLight);
  if (light.type == LightType::Box) {
    // Inverse square inside the box, (1 - x^4)^2 along each axis, x the offset over the half extent.
    const glm::vec3 axes[3] = {light.boxAxisX, light.boxAxisY, glm::cross(light.boxAxisX, light.boxAxisY)};
    float result = 1.0f / (d * d);
    for (int i = 0; i < 3; ++i) {
      const float x = glm::dot(p - light.position, axes[i]) / light.halfExtents[i];
      const float w = glm::clamp(1.0f - x * x * x * x, 0.0f, 1.0f);
      result *= w * w;
    }
    return result;
  }
  if (d >= light.range) return 0.0f;
  if (light.type == LightType::Vpl) {
    // Lambertian emitter: cosine about its normal; 1/d^2 and the window at max(d, near distance).
    const float dc = std::max(d, light.nearDistance);
    const float window = glm::clamp(1.0f - std::pow(dc / light.range, 4.0f), 0.0f, 1.0f);
    return window * window / (dc * dc) * std::max(glm::dot(light.direction, -toLight / d), 0.0f);
  }
  const float window = glm::clamp(1.0f - std::pow(d / light.range, 4.0f), 0.0f, 1.0f);
  float result = window * window / (d * d);
  if (light.type == LightType::Spot) {
    const float cd = glm::dot(light.direction, -toLight / d);
    const float cosOuter = std::cos(light.outerConeAngle), cosInner = std::cos(light.innerConeAngle);
    const float t = glm::clamp((cd - cosOuter) / (cosInner - cosOuter), 0.0f, 1.0f);
    result *= t * t;
  }
  return result;
}

glm::vec3 expectedRadiance(const Scene& scene, const PlaneMaterial& pm, const Light& light,
                           const glm::vec3& p) {
  const glm::vec3 v = glm::normalize(scene.cameras[0].eye - p);
  const glm::vec3 l = glm::normalize(light.position - p);
  float distributionAlpha = 0.0f;
  if (light.type == LightType::Vpl)  // the surface's alpha plus half the angle of the VPL's patch
    distributionAlpha = std::min(std::max(pm.roughness * pm.roughness, 1e-3f) +
                                     0.5f * light.nearDistance / glm::length(light.position - p),
                                 1.0f);
  return light.color * light.intensity * attenuation(light, p) *
         brdfCosine(pm, shadingNormal(pm), v, l, distributionAlpha);
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

// Every way lll shades an opaque surface: on the geometry (forward; lll's fragment shading, the
// chapter's), from the visibility buffer's rebuilt surfaces (forward and lll in compute, the
// default) and from screen-space buffers (lll's compute shading over the thin G-buffer; deferred;
// the light pre-pass).
struct ShadingPath {
  const char* name;
  const char* technique;
  LllShade lllShade;
  SurfaceSource surfaces;
};
constexpr ShadingPath kShadingPaths[] = {
    {"forward", "forward", LllShade::Compute, SurfaceSource::Gbuffer},
    {"forward-visibility", "forward", LllShade::Compute, SurfaceSource::Visibility},
    {"lll-fragment", "lll", LllShade::Fragment, SurfaceSource::Gbuffer},
    {"lll-visibility", "lll", LllShade::Compute, SurfaceSource::Visibility},
    {"lll-gbuffer", "lll", LllShade::Compute, SurfaceSource::Gbuffer},
    {"deferred", "deferred", LllShade::Compute, SurfaceSource::Visibility},
    {"prepass", "prepass", LllShade::Compute, SurfaceSource::Visibility}};

struct Counts {
  int lit = 0;
  int dark = 0;
};

// What a pixel should hold, from its ground point and the renderer that drew it (the shadow test
// reads the cascades it fitted); NaN in the red channel: not checked.
using Expectation = std::function<glm::vec3(const glm::vec3&, const Renderer&)>;

// Renders the plane with `light` through `path` and expects every pixel within 1% (+ 2e-4
// absolute, fp16 storage) of the formula.
Counts checkAgainstFormula(const Scene& scene, const Expectation& expectedAt, const ShadingPath& path,
                           LllFill fill = LllFill::Compute,
                           const std::function<void(RenderSettings&)>& configure = {}) {
  SCOPED_TRACE(std::string(path.name) + (fill == LllFill::Compute ? "" : fmt::format(" fill {}", fill)));
  RenderSettings settings;
  settings.width = 96;
  settings.height = 96;
  settings.ambient = 0.0f;
  settings.technique = path.technique;
  settings.lllShade = path.lllShade;
  settings.surfaces = path.surfaces;
  settings.lllFill = fill;
  if (configure) configure(settings);
  Context& context = test::gpuContext();
  const size_t before = context.validationMessages().size();
  Renderer renderer(context, scene, settings);
  renderer.renderFrame(true);
  const HdrImage hdr = renderer.hdrImage();
  Counts counts;
  int failures = 0;
  for (uint32_t y = 0; y < settings.height; ++y) {
    for (uint32_t x = 0; x < settings.width; ++x) {
      const glm::vec3 p = groundPoint(renderer, x, y, settings.width, settings.height);
      const glm::vec3 expected = expectedAt(p, renderer);
      if (std::isnan(expected.r)) continue;
      const glm::vec3 got = glm::vec3(hdr.at(x, y));
      for (int c = 0; c < 3; ++c) {
        // fp16 storage and a half-pixel position error near steep falloffs bound the tolerance.
        if (std::abs(got[c] - expected[c]) > 0.01f * expected[c] + 2e-4f && ++failures <= 5)
          ADD_FAILURE() << "pixel " << x << "," << y << " channel " << c << ": " << got[c] << ", expected "
                        << expected[c] << " at " << p.x << "," << p.z;
      }
      (expected.r > 1e-3f ? counts.lit : counts.dark) += 1;
    }
  }
  std::printf("[ analytic ] %s: %d lit, %d dark pixels\n", path.name, counts.lit, counts.dark);
  EXPECT_EQ(failures, 0) << "pixels off the formula";
  test::expectNoValidationMessagesSince(before);
  return counts;
}

Counts checkAgainstFormula(const Scene& scene, const std::function<glm::vec3(const glm::vec3&)>& expectedAt,
                           const ShadingPath& path, LllFill fill = LllFill::Compute) {
  return checkAgainstFormula(
      scene, [&](const glm::vec3& p, const Renderer&) { return expectedAt(p); }, path, fill);
}

Counts checkAgainstFormula(const Scene& scene, const PlaneMaterial& pm, const Light& light,
                           const ShadingPath& path, LllFill fill = LllFill::Compute) {
  return checkAgainstFormula(
      scene, [&](const glm::vec3& p) { return expectedRadiance(scene, pm, light, p); }, path, fill);
}

Light pointLight(glm::vec3 position, float intensity, float range) {
  Light light;
  light.position = position;
  light.intensity = intensity;
  light.range = range;
  return light;
}

class Analytic : public ::testing::TestWithParam<ShadingPath> {};

TEST_P(Analytic, PointLightOverLambertianPlane) {
  Scene scene = planeScene();
  const Light light = pointLight({0.0f, 2.0f, 0.0f}, 10.0f, 6.0f);
  scene.lights = {light};
  const Counts c = checkAgainstFormula(scene, {}, light, GetParam());
  // The range cut-off is inside the view: both lit pixels and pixels beyond the range were checked.
  EXPECT_GT(c.lit, 1800);
  EXPECT_GT(c.dark, 900);
}

TEST_P(Analytic, SpotLightConeAndRange) {
  Scene scene = planeScene();
  Light light = pointLight({0.0f, 3.0f, 0.0f}, 50.0f, 8.0f);
  light.type = LightType::Spot;
  light.direction = {0.0f, -1.0f, 0.0f};
  light.innerConeAngle = 20.0f * kPi / 180.0f;
  light.outerConeAngle = 30.0f * kPi / 180.0f;
  scene.lights = {light};
  const Counts c = checkAgainstFormula(scene, {}, light, GetParam());
  EXPECT_GT(c.lit, 225);
  EXPECT_GT(c.dark, 4500);  // outside the outer cone
}

// A box light standing in the plane, turned 30 degrees: lit inside the box's footprint (its faces
// fade the light to zero), dark outside it even within the bounding radius. Under lll every fill
// must give the formula's value.
TEST_P(Analytic, BoxLightFootprint) {
  Scene scene = planeScene();
  const float turn = 30.0f * kPi / 180.0f;
  const Light light = makeBoxLight({0.5f, 1.0f, 0.0f}, {std::cos(turn), 0.0f, std::sin(turn)},
                                   {0.0f, 1.0f, 0.0f}, {4.0f, 1.5f, 1.5f}, {1.0f, 0.9f, 0.8f}, 6.0f);
  scene.lights = {light};
  const bool lll = std::string(GetParam().technique) == "lll";
  for (const LllFill fill : {LllFill::Compute, LllFill::Ray, LllFill::Shells}) {
    const Counts c = checkAgainstFormula(scene, {}, light, GetParam(), fill);
    EXPECT_GT(c.lit, 540);
    EXPECT_GT(c.dark, 4500);
    if (!lll) break;  // fills are lll's alone
  }
}

// A virtual point light of instant radiosity (gi/photons.h) half a metre over the plane, its normal
// 60 degrees off straight down: the plane is lit only on the side its hemisphere faces, with the
// cosine falloff, and under it the 1/d^2 stops at its near distance (0.8 m, more than its height).
TEST_P(Analytic, VirtualPointLightHemisphereAndNearClamp) {
  Scene scene = planeScene();
  Light light = pointLight({0.0f, 0.5f, 0.0f}, 4.0f, 7.0f);
  light.type = LightType::Vpl;
  light.direction = glm::vec3(std::sin(kPi / 3.0f), -std::cos(kPi / 3.0f), 0.0f);
  light.nearDistance = 0.8f;
  scene.lights = {light};
  const Counts c = checkAgainstFormula(scene, {}, light, GetParam());
  EXPECT_GT(c.lit, 1200);
  EXPECT_GT(c.dark, 2500);  // behind its hemisphere (x < ~-0.29) and beyond its range
}

// A VPL over a glossy plane (roughness 0.3, alpha 0.09) stands for a patch of its near distance, 0.4
// m: its highlight is the lobe of alpha + 0.2 m / d (0.49 right under it, 1 m up), not a point
// light's glint, whose peak is 25 times higher. Straight down, 1.2 m off the camera's axis so the
// highlight sits off the plane's centre.
TEST_P(Analytic, VirtualPointLightHighlightIsItsPatchs) {
  PlaneMaterial pm;
  pm.roughness = 0.3f;
  Scene scene = planeScene(pm);
  Light light = pointLight({1.2f, 1.0f, 0.0f}, 8.0f, 6.0f);
  light.type = LightType::Vpl;
  light.direction = glm::vec3(0.0f, -1.0f, 0.0f);
  light.nearDistance = 0.4f;
  scene.lights = {light};
  const Counts c = checkAgainstFormula(scene, pm, light, GetParam());
  EXPECT_GT(c.lit, 2000);
}

// The sun (a directional light, in the frame's uniforms, never in a list): E lux from 50 degrees
// off the zenith, coloured; every pixel gets brdf x cos x E, the same on the whole plane but for
// the view direction.
TEST_P(Analytic, DirectionalLightLightsEveryPixel) {
  Scene scene = planeScene();
  scene.lights.clear();
  DirectionalLight sun;
  const float zenith = 50.0f * kPi / 180.0f;
  sun.direction = -glm::vec3(std::sin(zenith), std::cos(zenith), 0.0f);
  sun.color = {1.0f, 0.8f, 0.6f};
  sun.illuminance = 3.0f;
  scene.directionalLights = {sun};
  const PlaneMaterial pm;
  const Counts c = checkAgainstFormula(
      scene,
      [&](const glm::vec3& p) {
        const glm::vec3 v = glm::normalize(scene.cameras[0].eye - p);
        return sun.color * sun.illuminance * brdfCosine(pm, shadingNormal(pm), v, -sun.direction);
      },
      GetParam());
  EXPECT_EQ(c.dark, 0);
}

// A 2 m square 3 m over the plane (double-sided, facing up), centred over the origin, turned 20
// degrees about the vertical so that its shadow's edges cross the pixel grid at every offset.
constexpr float kOccluderTurn = 20.0f * kPi / 180.0f;
glm::vec2 occluderCorner(int i) {
  const glm::vec2 c(i == 0 || i == 1 ? -1.0f : 1.0f, i == 0 || i == 3 ? -1.0f : 1.0f);
  const float cs = std::cos(kOccluderTurn), sn = std::sin(kOccluderTurn);
  return {cs * c.x - sn * c.y, sn * c.x + cs * c.y};
}

// `doubleSided` false: a single-sided square whose front faces the sky (`facingUp`) or the plane.
void addSquareOccluder(Scene& scene, bool doubleSided = true, bool facingUp = true) {
  const uint32_t first = uint32_t(scene.vertices.size());
  for (int i = 0; i < 4; ++i)
    scene.vertices.push_back({{occluderCorner(i).x, 3.0f, occluderCorner(i).y}, {0, 1, 0}, {0, 0}});
  const uint32_t firstIndex = uint32_t(scene.indices.size());
  // Counter-clockwise seen from above: the front faces the sky.
  for (uint32_t i : {0u, 1u, 2u, 0u, 2u, 3u}) scene.indices.push_back(i);
  if (!facingUp) std::reverse(scene.indices.begin() + firstIndex, scene.indices.end());
  Material m = scene.materials[0];
  m.name = "occluder";
  m.doubleSided = doubleSided;
  scene.materials.push_back(m);
  scene.meshes.push_back(Mesh{"occluder", {Primitive{firstIndex, 6, first, 1}}});
  scene.instances.push_back(Instance{1, glm::mat4(1.0f)});
}

// Whether ground point `g` (x, z) lies inside the occluder's outline moved by `offset`, and its
// distance to that outline measured after scaling x by `xScale` (the sun's texels on the ground:
// square along z, stretched along x by 1 / cos(zenith)).
std::pair<bool, float> outlineDistance(glm::vec2 g, glm::vec2 offset, float xScale) {
  bool inside = true;
  float best = 1e30f;
  for (int i = 0; i < 4; ++i) {
    const glm::vec2 a = occluderCorner(i) + offset, b = occluderCorner((i + 1) % 4) + offset;
    const glm::vec2 edge = b - a;
    // Corners run clockwise seen from above (x right, z down the image): inside is on one side.
    if (edge.x * (g.y - a.y) - edge.y * (g.x - a.x) > 0.0f) inside = false;
    for (int k = 0; k <= 256; ++k) {
      const glm::vec2 d = a + edge * (float(k) / 256.0f) - g;
      best = std::min(best, std::hypot(d.x * xScale, d.y));
    }
  }
  return {inside, best};
}

// The sun's shadow of a square occluder (shadows/sun_shadows.h), the sun 45 degrees off the zenith
// along +x: the shadow is the square moved 3 tan(45) = 3 m towards -x. With one texel and no filter,
// every pixel more than 1.5 of the sun's texels from the shadow's edge must be exactly lit (brdf x
// cos x E) or exactly dark (no ambient); with PCF, every pixel 3 texels from it. Pixels that see
// the occluder itself are skipped; both sides of every edge are checked. On one path the casters
// are also drawn by the compute rasterizer (shadows/shadow_raster.h).
TEST_P(Analytic, SunShadowOfASquareOccluder) {
  Scene scene = planeScene();
  addSquareOccluder(scene);
  DirectionalLight sun;
  const float zenith = 45.0f * kPi / 180.0f;
  sun.direction = -glm::vec3(std::sin(zenith), std::cos(zenith), 0.0f);
  sun.color = {1.0f, 0.9f, 0.8f};
  sun.illuminance = 3.0f;
  scene.directionalLights = {sun};
  const PlaneMaterial pm;
  const glm::vec2 shift(-3.0f * std::tan(zenith), 0.0f);
  std::vector<std::pair<ShadowFilter, RasterChoice>> runs = {{ShadowFilter::None, RasterChoice::Hardware},
                                                             {ShadowFilter::Pcf, RasterChoice::Hardware}};
  if (std::string(GetParam().name) == "forward-visibility")
    runs.insert(runs.end(),
                {{ShadowFilter::None, RasterChoice::Compute}, {ShadowFilter::Pcf, RasterChoice::Compute}});
  for (const auto& [filter, raster] : runs) {
    SCOPED_TRACE(fmt::format("--shadow-filter {} --shadow-raster {}", filter, raster));
    const float edgeTexels = filter == ShadowFilter::None ? 1.5f : 3.0f;
    int nearEdge = 0;
    Counts c = checkAgainstFormula(
        scene,
        [&](const glm::vec3& p, const Renderer& renderer) {
          const glm::vec3 eye = scene.cameras[0].eye;
          // Seen through the occluder (with a margin): not the plane.
          const glm::vec3 q = eye + (p - eye) * ((eye.y - 3.0f) / eye.y);
          const auto [onOccluder, toOccluderEdge] = outlineDistance({q.x, q.z}, {0.0f, 0.0f}, 1.0f);
          if (onOccluder || toOccluderEdge < 0.05f) return glm::vec3(NAN);
          const gpu::SunShadow& cascades = renderer.shadows().cascades();
          uint32_t k = 0;  // straight down: every ground point at view depth eye.y
          while (k + 1 < cascades.config.x && eye.y > cascades.splits[k]) ++k;
          const auto [inside, toEdge] = outlineDistance({p.x, p.z}, shift, std::cos(zenith));
          if (toEdge < edgeTexels * cascades.texelWorld[k]) {
            ++nearEdge;
            return glm::vec3(NAN);
          }
          if (inside) return glm::vec3(0.0f);
          const glm::vec3 v = glm::normalize(eye - p);
          return sun.color * sun.illuminance * brdfCosine(pm, shadingNormal(pm), v, -sun.direction);
        },
        GetParam(), LllFill::Compute,
        [&](RenderSettings& s) {
          s.shadowFilter = filter;
          s.shadowRaster = raster;
          s.shadowResolution = 1024;
        });
    std::printf("[ analytic ] %d pixels near the shadow's edge skipped\n", nearEdge);
    EXPECT_GT(c.dark, 80) << "the shadow is in view";
    EXPECT_GT(c.lit, 5000);
    EXPECT_GT(nearEdge, 5) << "the edges cross pixel centres";
    EXPECT_LT(nearEdge, 400) << "the edge band is a few texels wide";
  }
}

// A local light's shadow of the square occluder (shadows/local_shadows.h), the light 6 m over the
// origin, the occluder halfway down: the shadow is the square scaled twice about the origin. A spot
// (one view) and a point light (a cube, the shadow in its -y face), PCF off and on, every shading
// path: every pixel more than 1.5 (PCF: 3) of the light's texels on the ground from the shadow's edge
// is exactly lit (the formula) or exactly dark; pixels that see the occluder itself are skipped. On
// one path the casters are drawn by the compute rasterizer too, at 500 texels a view.
TEST_P(Analytic, LocalLightShadowOfASquareOccluder) {
  for (const LightType type : {LightType::Spot, LightType::Point}) {
    Scene scene = planeScene();
    addSquareOccluder(scene);
    Light light = pointLight({0.0f, 6.0f, 0.0f}, 60.0f, 12.0f);
    light.type = type;
    light.direction = {0.0f, -1.0f, 0.0f};
    light.innerConeAngle = 40.0f * kPi / 180.0f;
    light.outerConeAngle = 45.0f * kPi / 180.0f;
    scene.lights = {light};
    const PlaneMaterial pm;
    std::vector<std::pair<ShadowFilter, RasterChoice>> runs = {{ShadowFilter::None, RasterChoice::Hardware},
                                                               {ShadowFilter::Pcf, RasterChoice::Hardware}};
    if (std::string(GetParam().name) == "forward-visibility")
      runs.insert(runs.end(),
                  {{ShadowFilter::None, RasterChoice::Compute}, {ShadowFilter::Pcf, RasterChoice::Compute}});
    for (const auto& [filter, raster] : runs) {
      SCOPED_TRACE(fmt::format("{} --shadow-filter {} --shadow-raster {}",
                               type == LightType::Spot ? "spot" : "point", filter, raster));
      const float edgeTexels = filter == ShadowFilter::None ? 1.5f : 3.0f;
      // The compute rasterizer at 500 texels: the cube faces' cells start off its 8-texel tiles
      // and 32-texel bins (the occluder is a large triangle, found through the bins).
      const uint32_t resolution = raster == RasterChoice::Compute ? 500 : 512;
      const float tanHalf = shadowViews(light, resolution)[0].tanHalf;
      int nearEdge = 0;
      Counts c = checkAgainstFormula(
          scene,
          [&](const glm::vec3& p, const Renderer&) {
            const glm::vec3 eye = scene.cameras[0].eye;
            const glm::vec3 q = eye + (p - eye) * ((eye.y - 3.0f) / eye.y);
            const auto [onOccluder, toOccluderEdge] = outlineDistance({q.x, q.z}, {0.0f, 0.0f}, 1.0f);
            if (onOccluder || toOccluderEdge < 0.05f) return glm::vec3(NAN);
            // The ground point seen from the light crosses the occluder's plane at half its offset.
            const auto [inside, toEdge] = outlineDistance({0.5f * p.x, 0.5f * p.z}, {0.0f, 0.0f}, 1.0f);
            // A texel on the ground: its size at this distance, stretched by the slant.
            const float d = glm::length(light.position - p);
            const float texel = d * 2.0f * tanHalf / float(resolution) * (d / light.position.y);
            if (2.0f * toEdge < edgeTexels * texel) {
              ++nearEdge;
              return glm::vec3(NAN);
            }
            return inside ? glm::vec3(0.0f) : expectedRadiance(scene, pm, light, p);
          },
          GetParam(), LllFill::Compute,
          [&](RenderSettings& s) {
            s.shadows = ShadowMode::All;
            s.shadowLights = 1;
            s.shadowFilter = filter;
            s.shadowRaster = raster;
            s.shadowLightResolution = resolution;
          });
      std::printf("[ analytic ] %d pixels near the shadow's edge skipped\n", nearEdge);
      EXPECT_GT(c.dark, 300) << "the shadow is in view";
      EXPECT_GT(c.lit, 2000);
      EXPECT_GT(nearEdge, 5) << "the edges cross pixel centres";
      EXPECT_LT(nearEdge, 500) << "the edge band is a few texels wide";
    }
  }
}

// A single-sided caster casts from its front faces only (glTF draws no back faces): the square
// facing the sky shadows the plane, the same square facing the plane lets the sun through.
TEST(AnalyticShadow, SingleSidedCastersCastFromTheirFrontFaces) {
  for (const bool facingUp : {true, false}) {
    SCOPED_TRACE(facingUp ? "front towards the sun" : "back towards the sun");
    Scene scene = planeScene();
    addSquareOccluder(scene, false, facingUp);
    DirectionalLight sun;
    sun.direction = -glm::normalize(glm::vec3(1.0f, 1.0f, 0.0f));
    sun.illuminance = 3.0f;
    scene.directionalLights = {sun};
    RenderSettings settings;
    settings.width = 96;
    settings.height = 96;
    settings.ambient = 0.0f;
    settings.shadowFilter = ShadowFilter::None;
    const test::Rendered out = test::render(scene, settings);
    // The shadow's middle, 3 m towards -x (pixel 29, 47): dark only when it casts.
    const float middle = out.hdr.at(29, 47).r;
    if (facingUp)
      EXPECT_EQ(middle, 0.0f);
    else
      EXPECT_GT(middle, 0.3f);
  }
}

// A light low over the plane (light arriving at up to ~85 degrees): a shading normal tilted by
// even a fraction of a degree moves the far pixels by several percent.
Light grazingLight() {
  return pointLight({1.0f, 0.6f, -0.5f}, 12.0f, 30.0f);
}

// Texture coordinates but no normal map: the geometric normal, exactly. (The neutral 1x1 normal
// texel (128, 128, 255) decodes to a 0.32 degree tilt.)
TEST_P(Analytic, UvMappedPlaneWithoutNormalMapKeepsItsNormal) {
  Scene scene = planeScene();
  const Light light = grazingLight();
  scene.lights = {light};
  const Counts c = checkAgainstFormula(scene, {}, light, GetParam());
  EXPECT_GT(c.lit, 8000);
}

// A normal map tilting 30 degrees towards +u, -u, +v or -v in tangent space (glTF: +x right along
// +u, +y up the image, i.e. along -v), in the frame built from derivatives (no TANGENT) and in the
// file's frame (TANGENT along +v, w = 1 and -1, so it differs from what derivatives give).
TEST_P(Analytic, NormalMapTiltsTheWayTheTangentFrameSays) {
  const glm::u8vec3 tilts[] = {{191, 128, 238}, {64, 128, 238}, {128, 191, 238}, {128, 64, 238}};
  const char* tiltNames[] = {"+x", "-x", "+y", "-y"};
  const std::optional<glm::vec4> tangents[] = {std::nullopt, glm::vec4(0, 0, 1, 1), glm::vec4(0, 0, 1, -1)};
  const char* tangentNames[] = {"derivative frame", "TANGENT +v w=1", "TANGENT +v w=-1"};
  const Light light = pointLight({0.0f, 1.0f, 0.0f}, 10.0f, 12.0f);
  for (int t = 0; t < 3; ++t) {
    for (int i = 0; i < 4; ++i) {
      SCOPED_TRACE(std::string(tangentNames[t]) + ", tilt " + tiltNames[i]);
      PlaneMaterial pm;
      pm.normalTexel = tilts[i];
      pm.tangent = tangents[t];
      Scene scene = planeScene(pm);
      scene.lights = {light};
      const Counts c = checkAgainstFormula(scene, pm, light, GetParam());
      EXPECT_GT(c.lit, 2700);
    }
  }
}

// glTF mixes a dielectric and a metal BRDF by `metallic`: the dielectric's diffuse is weighted by
// its own Fresnel term. A half-metallic, coloured, glossy patch under a white light.
TEST_P(Analytic, HalfMetallicPatchFollowsTheSpecificationsMix) {
  PlaneMaterial pm;
  pm.baseColor = {0.9f, 0.6f, 0.3f};
  pm.metallic = 0.5f;
  pm.roughness = 0.5f;
  Scene scene = planeScene(pm);
  const Light light = pointLight({0.5f, 1.5f, 0.0f}, 10.0f, 12.0f);
  scene.lights = {light};
  const Counts c = checkAgainstFormula(scene, pm, light, GetParam());
  EXPECT_GT(c.lit, 4500);
}

// A sharp highlight under a strong light: 600 cd 1 m over a roughness-0.1 plane peaks near 19,000,
// within fp16's 65,504 in the HDR target; a technique's own buffers must not overflow first (the
// pre-pass once summed unweighted lobes, 25x larger, and read 18% dark here).
TEST_P(Analytic, SharpHighlightUnderAStrongLight) {
  PlaneMaterial pm;
  pm.roughness = 0.1f;
  Scene scene = planeScene(pm);
  const Light light = pointLight({0.0f, 1.0f, 0.0f}, 600.0f, 30.0f);
  scene.lights = {light};
  const Counts c = checkAgainstFormula(scene, pm, light, GetParam());
  EXPECT_GT(c.lit, 8000);
}

// Past fp16's range: the plane right under a 10^6 cd light reflects ~2.4 x 10^5. Vulkan lets a
// device store that in the RGBA16F target as infinity or as 65504 (lavapipe clamps); either way
// the display shows the brightest white. The filmic curve of infinity would be Inf / Inf, a NaN,
// and a black pixel.
TEST(AnalyticDisplay, OverflowedRadianceShowsWhite) {
  Scene scene = planeScene();
  scene.lights = {pointLight({0.0f, 1.0f, 0.0f}, 1e6f, 30.0f)};
  RenderSettings settings;
  settings.width = 96;
  settings.height = 96;
  const test::Rendered out = test::render(scene, settings);
  size_t overflowed = 0;
  for (size_t i = 0; i < out.hdr.rgba.size(); i += 4) {
    if (!(out.hdr.rgba[i] >= 65504.0f)) continue;  // infinity or the largest finite half
    ++overflowed;
    EXPECT_EQ(out.ldr.rgba[i], 255) << "pixel " << i / 4;
  }
  EXPECT_GT(overflowed, 0u) << "nothing reached fp16's limit: the test checks nothing";
}

INSTANTIATE_TEST_SUITE_P(ShadingPaths, Analytic, ::testing::ValuesIn(kShadingPaths),
                         [](const ::testing::TestParamInfo<ShadingPath>& info) {
                           std::string name = info.param.name;
                           std::replace(name.begin(), name.end(), '-', '_');
                           return name;
                         });

TEST(AnalyticLights, UnboundedRangeFollowsCutoff) {
  const float range = rangeForUnboundedLight(4.0f, glm::vec3(0.5f, 1.0f, 0.25f));
  EXPECT_NEAR(4.0f * 1.0f / (range * range), kUnboundedLightCutoff, 1e-6f);
}

}  // namespace
}  // namespace lll
