// The techniques "deferred" (Infinity) and "prepass" (Resistance 2 light pre-pass) against the
// forward reference: whole scenes, the light-volume corner cases (camera inside a point light or a
// spot cone, lights cut by the near plane, lights behind the camera), translucents and edge AA.
#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <string>

#include "scene/builtin_scenes.h"
#include "scene/mesh_builder.h"
#include "scene/scene_source.h"
#include "test_support.h"

namespace lll {
namespace {

// Small frames: lavapipe shades on the CPU. 1,024 lights at this size still take well under a second.
constexpr uint32_t kWidth = 160;
constexpr uint32_t kHeight = 90;
// deferred evaluates the same BRDF from a G-buffer: the same image; the light pre-pass
// approximates the colour of Fresnel-weighted highlights (shaders/lighting/prepass_combine.frag):
// its own bound, test::kPrepassBound.
const test::ImageBound kDeferredBound = test::kSameImage;

const Scene& loadedScene(const std::string& name, uint32_t extraLights) {
  static std::map<std::pair<std::string, uint32_t>, Scene> cache;
  const auto key = std::make_pair(name, extraLights);
  auto it = cache.find(key);
  if (it == cache.end()) it = cache.emplace(key, loadScene(SceneRequest{name, extraLights, 1})).first;
  return it->second;
}

// The scene without its alpha-blended primitives (glass, smoke): the opaque-only comparisons.
Scene withoutBlended(const Scene& scene) {
  Scene opaque = scene;
  for (Mesh& mesh : opaque.meshes) {
    std::erase_if(mesh.primitives, [&](const Primitive& p) {
      return scene.materials[p.material].alphaMode == AlphaMode::Blend;
    });
  }
  return opaque;
}

RenderSettings settingsFor(const std::string& technique) {
  RenderSettings settings;
  settings.width = kWidth;
  settings.height = kHeight;
  settings.technique = technique;
  return settings;
}

struct Comparison {
  test::Rendered reference;
  test::Rendered candidate;
};

const test::ImageBound& boundFor(const RenderSettings& settings) {
  return settings.technique == "prepass" ? test::kPrepassBound : kDeferredBound;
}

Comparison renderWithForward(const Scene& scene, RenderSettings settings) {
  Comparison c;
  c.candidate = test::render(scene, settings);
  c.reference = test::render(scene, test::reference(settings));
  return c;
}

// Renders `settings` and forward, and expects the candidate within its technique's bound.
Comparison compareWithForward(const Scene& scene, const RenderSettings& settings, const std::string& label) {
  Comparison c = renderWithForward(scene, settings);
  test::expectWithinBound(c.candidate.ldr, c.reference.ldr, boundFor(settings), label);
  return c;
}

// A closed 12 x 5 x 14 m room (double-sided walls seen from inside) with a rough box, a smooth
// metal sphere and a glossy dielectric pillar: every pixel has a surface, silhouettes and creases
// exist, and the specular lobes are sharp enough to show a light drawn twice.
Scene roomScene() {
  Scene scene;
  scene.name = "volume-test-room";
  auto material = [&](const char* name, glm::vec3 color, float metallic, float roughness, bool doubleSided) {
    Material m;
    m.name = name;
    m.baseColorFactor = glm::vec4(color, 1.0f);
    m.metallic = metallic;
    m.roughness = roughness;
    m.doubleSided = doubleSided;
    scene.materials.push_back(m);
  };
  material("walls", {0.7f, 0.7f, 0.65f}, 0.0f, 0.8f, true);
  material("rough box", {0.8f, 0.3f, 0.2f}, 0.0f, 1.0f, false);
  material("metal", {0.9f, 0.8f, 0.5f}, 1.0f, 0.35f, false);
  material("glossy", {0.2f, 0.4f, 0.8f}, 0.0f, 0.25f, false);
  MeshBuilder builder("room");
  builder.setMaterial(0);
  builder.addBoxBetween({-6.0f, 0.0f, -9.0f}, {6.0f, 5.0f, 5.0f});
  builder.setMaterial(1);
  builder.addBoxBetween({-3.0f, 0.0f, -5.0f}, {-1.0f, 1.5f, -3.0f});
  builder.setMaterial(2);
  builder.addSphere(glm::translate(glm::mat4(1.0f), glm::vec3(1.5f, 1.0f, -4.0f)), 1.0f, 24, 16);
  builder.setMaterial(3);
  builder.addCylinder(glm::translate(glm::mat4(1.0f), glm::vec3(3.5f, 0.0f, -6.0f)), 0.6f, 4.0f, 24);
  addInstance(scene, builder.addTo(scene));
  scene.cameras.push_back(
      Camera{"room", {0.0f, 1.6f, 3.0f}, {0.0f, 1.2f, -5.0f}, {0.0f, 1.0f, 0.0f}, glm::radians(70.0f)});
  return scene;
}

Light pointLight(const glm::vec3& position, float range, const glm::vec3& color, float intensity) {
  Light light;
  light.position = position;
  light.range = range;
  light.color = color;
  light.intensity = intensity;
  return light;
}

Light spotLight(const glm::vec3& position, const glm::vec3& target, float range, float outerDegrees) {
  Light light = pointLight(position, range, {1.0f, 0.9f, 0.7f}, 40.0f);
  light.type = LightType::Spot;
  light.direction = glm::normalize(target - position);
  light.outerConeAngle = glm::radians(outerDegrees);
  light.innerConeAngle = 0.7f * light.outerConeAngle;
  return light;
}

// ---------------------------------------------------------------------------------------------
// deferred

TEST(DeferredMatchesForward, DefaultSceneOpaque) {
  const Scene scene = withoutBlended(loadedScene("", 0));
  const Comparison c = compareWithForward(scene, settingsFor("deferred"), "deferred atrium opaque");
  EXPECT_EQ(test::stat(c.candidate, "gbuffer-bytes-per-pixel"), 12.0);
  EXPECT_GT(test::stat(c.candidate, "lights-drawn"), 0.0);
  EXPECT_LE(test::stat(c.candidate, "lights-drawn"), double(scene.lights.size()));
}

TEST(DeferredMatchesForward, DefaultSceneWithGlassLitByForwardPass) {
  RenderSettings settings = settingsFor("deferred");
  settings.deferredTranslucent = TranslucentLighting::Forward;
  compareWithForward(loadedScene("", 0), settings, "deferred atrium glass forward");
}

// Figure 1.1 of the seeds: a deferred renderer's glass gets no dynamic light. The glass pixels are
// where forward differs with and without the blended primitives.
TEST(DeferredTranslucent, UnlitGlassIsDarkerThanForward) {
  const Scene& full = loadedScene("", 0);
  const Scene opaque = withoutBlended(full);
  RenderSettings settings = settingsFor("deferred");
  settings.deferredTranslucent = TranslucentLighting::Unlit;
  const Comparison c = renderWithForward(full, settings);
  const test::Rendered opaqueForward = test::render(opaque, settingsFor("forward"));
  double glassForward = 0.0, glassUnlit = 0.0;
  int glassPixels = 0;
  for (uint32_t y = 0; y < kHeight; ++y) {
    for (uint32_t x = 0; x < kWidth; ++x) {
      const glm::vec3 withGlass(c.reference.hdr.at(x, y)), withoutGlass(opaqueForward.hdr.at(x, y));
      if (glm::length(withGlass - withoutGlass) < 0.02f * (glm::length(withoutGlass) + 0.05f)) continue;
      ++glassPixels;
      glassForward += glm::dot(withGlass, glm::vec3(0.2126f, 0.7152f, 0.0722f));
      glassUnlit += glm::dot(glm::vec3(c.candidate.hdr.at(x, y)), glm::vec3(0.2126f, 0.7152f, 0.0722f));
    }
  }
  std::printf("[ glass    ] %d pixels, mean luminance forward %.4f, deferred unlit %.4f\n", glassPixels,
              glassForward / std::max(glassPixels, 1), glassUnlit / std::max(glassPixels, 1));
  ASSERT_GT(glassPixels, 50);
  EXPECT_LT(glassUnlit, 0.9 * glassForward);
}

struct AssetCase {
  const char* scene;
  uint32_t lights;
};

class DeferredAssets : public ::testing::TestWithParam<AssetCase> {};

const Scene& assetScene(const std::string& name, uint32_t lights) {
  return loadedScene(std::string(LLL_ASSETS_DIR) + "/" + name + "/" + name + ".gltf", lights);
}

// Pixels the lights change visibly (by more than 2 of 255 in any channel) in the forward
// reference: comparisons on frames the lights barely touch would prove little.
int pixelsLitByLights(const Scene& scene, const Comparison& c, const RenderSettings& settings) {
  Scene unlit = scene;
  unlit.lights.clear();
  const test::Rendered dark = test::render(unlit, test::reference(settings));
  int lit = 0;
  for (size_t i = 0; i < dark.ldr.rgba.size(); i += 4) {
    for (size_t k = i; k < i + 3; ++k) {
      if (std::abs(int(dark.ldr.rgba[k]) - int(c.reference.ldr.rgba[k])) > 2) {
        ++lit;
        break;
      }
    }
  }
  return lit;
}

// Looking at the centre of the scene from above one corner of its bounds, where the scattered
// random lights are: the files' own cameras frame close-ups that 64 of them hardly reach.
RenderSettings overviewSettings(const Scene& scene, const std::string& technique) {
  RenderSettings settings = settingsFor(technique);
  const Bounds b = scene.worldBounds();
  const glm::vec3 eye = b.center() + b.extent() * glm::vec3(0.3f, 0.25f, 0.3f), target = b.center();
  char camera[256];
  std::snprintf(camera, sizeof(camera), "%g,%g,%g,%g,%g,%g", eye.x, eye.y, eye.z, target.x, target.y,
                target.z);
  settings.camera = camera;
  return settings;
}

TEST_P(DeferredAssets, MatchesForwardOpaque) {
  const AssetCase& p = GetParam();
  const Scene scene = withoutBlended(assetScene(p.scene, p.lights));
  const RenderSettings settings = overviewSettings(scene, "deferred");
  const Comparison c = compareWithForward(
      scene, settings, std::string("deferred ") + p.scene + " " + std::to_string(p.lights));
  const int lit = pixelsLitByLights(scene, c, settings);
  std::printf("[ lit      ] %d of %u pixels\n", lit, kWidth * kHeight);
  EXPECT_GT(lit, int(kWidth * kHeight) / 50);
}

INSTANTIATE_TEST_SUITE_P(DeferredScenes, DeferredAssets,
                         ::testing::Values(AssetCase{"camp", 64}, AssetCase{"camp", 1024},
                                           AssetCase{"cave", 64}, AssetCase{"cave", 1024},
                                           AssetCase{"garage", 64}, AssetCase{"garage", 1024},
                                           AssetCase{"space", 64}, AssetCase{"space", 1024}),
                         [](const auto& info) {
                           return std::string(info.param.scene) + std::to_string(info.param.lights);
                         });

// ---------------------------------------------------------------------------------------------
// light volumes at the camera: deferred flips to back faces, prepass to z-fail stencil

const Camera& roomCamera() {
  static const Camera camera = roomScene().cameras[0];
  return camera;
}

glm::vec3 roomForward() {
  return glm::normalize(roomCamera().target - roomCamera().eye);
}

// The renderer's near plane for the room (renderer.cpp: 1e-4 of the far plane, at least 1 mm).
float roomNear() {
  const Bounds b = roomScene().worldBounds();
  float far = 0.0f;
  for (int i = 0; i < 8; ++i) {
    const glm::vec3 corner(i & 1 ? b.max.x : b.min.x, i & 2 ? b.max.y : b.min.y, i & 4 ? b.max.z : b.min.z);
    far = std::max(far, glm::length(corner - roomCamera().eye) * 1.01f);
  }
  return std::clamp(far * 1e-4f, 1e-3f, 0.05f);
}

// The eye inside a point light (and a second light well away from it).
Scene roomWithCameraInsidePointLight() {
  Scene scene = roomScene();
  scene.lights = {
      pointLight(roomCamera().eye + glm::vec3(0.4f, 0.3f, -0.5f), 9.0f, {1.0f, 0.8f, 0.6f}, 12.0f),
      pointLight({-3.0f, 3.0f, -6.0f}, 5.0f, {0.3f, 0.5f, 1.0f}, 20.0f)};
  return scene;
}

// The eye inside a spot's cone: a spot high behind the camera shining down the room.
Scene roomWithCameraInsideSpotCone() {
  Scene scene = roomScene();
  scene.lights = {spotLight({0.0f, 4.8f, 4.8f}, {0.0f, 0.0f, -6.0f}, 20.0f, 50.0f)};
  const Light& spot = scene.lights[0];
  const float cosToEye = glm::dot(spot.direction, glm::normalize(roomCamera().eye - spot.position));
  EXPECT_GT(cosToEye, std::cos(spot.outerConeAngle)) << "the test needs the eye inside the cone";
  return scene;
}

// Lights whose volumes the near plane cuts while the eye stays outside them: spheres just in
// front of the eye (nearest point between the eye and the near plane, or a little beyond it) and
// a spot whose apex sits between the eye and the near plane.
Scene roomWithLightsCrossingTheNearPlane() {
  Scene scene = roomScene();
  const glm::vec3 eye = roomCamera().eye, forward = roomForward();
  const glm::vec3 right = glm::normalize(glm::cross(forward, glm::vec3(0, 1, 0)));
  const float near = roomNear(), range = 2.5f;
  const glm::vec3 colors[] = {{1, 0.2f, 0.2f}, {0.2f, 1, 0.2f}, {0.2f, 0.2f, 1}, {1, 1, 0.2f}};
  const float gaps[] = {0.3f * near, 0.9f * near, 1.5f * near, 3.0f * near};
  for (int i = 0; i < 4; ++i) {
    const glm::vec3 direction = glm::normalize(forward + right * (0.15f * float(i) - 0.2f));
    scene.lights.push_back(pointLight(eye + direction * (range + gaps[i]), range, colors[i], 6.0f));
  }
  Light spot = spotLight(eye + forward * (0.5f * near), eye + forward, 12.0f, 30.0f);
  scene.lights.push_back(spot);
  return scene;
}

// Lights behind the camera: three that cannot reach the view (culled, never drawn) and two
// whose range reaches past the eye into it (drawn, from inside).
Scene roomWithLightsBehindTheCamera(uint32_t* reaching) {
  Scene scene = roomScene();
  const glm::vec3 eye = roomCamera().eye, back = -roomForward();
  for (float x : {-1.0f, 0.0f, 1.0f})
    scene.lights.push_back(pointLight(eye + back * 3.0f + glm::vec3(x, 0.0f, 0.0f), 2.0f, {1, 1, 1}, 30.0f));
  scene.lights.push_back(pointLight(eye + back * 1.0f + glm::vec3(1, 0, 0), 7.0f, {1.0f, 0.4f, 0.1f}, 10.0f));
  scene.lights.push_back(pointLight(eye + back * 1.5f - glm::vec3(1, 0, 0), 8.0f, {0.1f, 0.5f, 1.0f}, 10.0f));
  *reaching = 2;
  return scene;
}

Comparison expectMatchesForward(const std::string& technique, const Scene& scene, const std::string& label,
                                int minLitPixels) {
  const RenderSettings settings = settingsFor(technique);
  Comparison c = compareWithForward(scene, settings, technique + " " + label);
  EXPECT_GT(pixelsLitByLights(scene, c, settings), minLitPixels);
  return c;
}

TEST(DeferredLightVolumes, CameraInsidePointLight) {
  const Scene scene = roomWithCameraInsidePointLight();
  const Comparison c =
      expectMatchesForward("deferred", scene, "camera inside point light", int(kWidth * kHeight) / 2);
  EXPECT_EQ(test::stat(c.candidate, "lights-drawn-camera-inside"), 1.0);
}

TEST(DeferredLightVolumes, CameraInsideSpotCone) {
  const Scene scene = roomWithCameraInsideSpotCone();
  const Comparison c =
      expectMatchesForward("deferred", scene, "camera inside spot cone", int(kWidth * kHeight) / 4);
  EXPECT_EQ(test::stat(c.candidate, "lights-drawn-camera-inside"), 1.0);
  EXPECT_EQ(test::stat(c.candidate, "lights-drawn-as-cones"), 1.0);
}

TEST(DeferredLightVolumes, LightsCrossingTheNearPlane) {
  const Scene scene = roomWithLightsCrossingTheNearPlane();
  const Comparison c =
      expectMatchesForward("deferred", scene, "lights crossing the near plane", int(kWidth * kHeight) / 10);
  // All five come within the near-plane margin, so all are drawn from inside.
  EXPECT_EQ(test::stat(c.candidate, "lights-drawn-camera-inside"), 5.0);
}

TEST(DeferredLightVolumes, LightsBehindTheCamera) {
  uint32_t reaching = 0;
  const Scene scene = roomWithLightsBehindTheCamera(&reaching);
  const Comparison c =
      expectMatchesForward("deferred", scene, "lights behind the camera", int(kWidth * kHeight) / 4);
  EXPECT_EQ(test::stat(c.candidate, "lights-drawn"), double(reaching));
  EXPECT_EQ(test::stat(c.candidate, "lights-drawn-camera-inside"), double(reaching));
}

// Box lights are drawn as their bounding spheres; the shader's box window does the rest.
TEST(DeferredLightVolumes, BoxLights) {
  const Scene scene = *makeBuiltinScene("box-plane");
  for (const char* technique : {"deferred", "prepass"})
    expectMatchesForward(technique, scene, std::string("box lights, ") + technique,
                         int(kWidth * kHeight) / 20);
}

// ---------------------------------------------------------------------------------------------
// edge anti-aliasing

int changedPixels(const LdrImage& a, const LdrImage& b) {
  int changed = 0;
  for (size_t i = 0; i < a.rgba.size(); i += 4) {
    for (size_t k = i; k < i + 3; ++k) {
      if (a.rgba[k] != b.rgba[k]) {
        ++changed;
        break;
      }
    }
  }
  return changed;
}

TEST(DeferredEdgeAa, BlendsSilhouettesAndCreasesOnly) {
  Scene scene = roomScene();
  scene.lights = {pointLight({0.0f, 3.5f, -2.0f}, 12.0f, {1, 1, 1}, 30.0f)};
  RenderSettings settings = settingsFor("deferred");
  const test::Rendered plain = test::render(scene, settings);
  settings.antiAliasing = AntiAliasing::Edge;
  const test::Rendered smoothed = test::render(scene, settings);
  const int changed = changedPixels(plain.ldr, smoothed.ldr);
  std::printf("[ edge aa  ] %d of %u pixels changed, %.2f dB from no AA\n", changed, kWidth * kHeight,
              test::psnr(plain.ldr, smoothed.ldr));
  // The room's silhouettes and wall creases are a few percent of the frame, the rest is flat.
  EXPECT_GT(changed, int(kWidth * kHeight) / 100);
  EXPECT_LT(changed, int(kWidth * kHeight) / 4);
  EXPECT_EQ(test::stat(smoothed, "gbuffer-bytes-per-pixel"), 12.0);
}

TEST(DeferredEdgeAa, LeavesAFlatPlaneUntouched) {
  const Scene& scene = loadedScene("plane", 0);
  RenderSettings settings = settingsFor("deferred");
  const test::Rendered plain = test::render(scene, settings);
  settings.antiAliasing = AntiAliasing::Edge;
  const test::Rendered smoothed = test::render(scene, settings);
  EXPECT_EQ(changedPixels(plain.ldr, smoothed.ldr), 0);
  EXPECT_GT(pixelsLitByLights(scene, Comparison{plain, plain}, settings), int(kWidth * kHeight) / 10);
}

// ---------------------------------------------------------------------------------------------
// prepass

TEST(PrepassMatchesForward, DefaultScene) {
  const Comparison c = compareWithForward(loadedScene("", 0), settingsFor("prepass"), "prepass atrium");
  EXPECT_EQ(test::stat(c.candidate, "gbuffer-bytes-per-pixel"), 8.0);
  EXPECT_EQ(test::stat(c.candidate, "light-buffer-bytes-per-pixel"),
            32.0);  // two RGBA32F buffers: diffuse, specular
  EXPECT_GT(test::stat(c.candidate, "lights-stencil-marked"), 0.0);
}

class PrepassAssets : public ::testing::TestWithParam<AssetCase> {};

TEST_P(PrepassAssets, MatchesForwardOpaque) {
  const AssetCase& p = GetParam();
  const Scene scene = withoutBlended(assetScene(p.scene, p.lights));
  const Comparison c = compareWithForward(scene, overviewSettings(scene, "prepass"),
                                          std::string("prepass ") + p.scene + " " + std::to_string(p.lights));
  const double drawn = test::stat(c.candidate, "lights-drawn");
  EXPECT_EQ(
      test::stat(c.candidate, "lights-stencil-marked") + test::stat(c.candidate, "lights-small-unstenciled"),
      drawn);
}

INSTANTIATE_TEST_SUITE_P(PrepassScenes, PrepassAssets,
                         ::testing::Values(AssetCase{"camp", 64}, AssetCase{"camp", 1024},
                                           AssetCase{"cave", 64}, AssetCase{"cave", 1024},
                                           AssetCase{"garage", 64}, AssetCase{"garage", 1024},
                                           AssetCase{"space", 64}, AssetCase{"space", 1024}),
                         [](const auto& info) {
                           return std::string(info.param.scene) + std::to_string(info.param.lights);
                         });

// Stencil volumes: z-fail where the camera may be inside (the same rooms as for deferred), z-pass
// for large lights in front of it, no stencil for small ones.
TEST(PrepassStencilVolumes, CameraInsidePointLight) {
  const Comparison c = expectMatchesForward("prepass", roomWithCameraInsidePointLight(),
                                            "camera inside point light", int(kWidth * kHeight) / 2);
  EXPECT_EQ(test::stat(c.candidate, "lights-stencil-marked-z-fail"), 1.0);
}

TEST(PrepassStencilVolumes, CameraInsideSpotCone) {
  const Comparison c = expectMatchesForward("prepass", roomWithCameraInsideSpotCone(),
                                            "camera inside spot cone", int(kWidth * kHeight) / 4);
  EXPECT_EQ(test::stat(c.candidate, "lights-stencil-marked-z-fail"), 1.0);
}

TEST(PrepassStencilVolumes, LightsCrossingTheNearPlane) {
  const Comparison c = expectMatchesForward("prepass", roomWithLightsCrossingTheNearPlane(),
                                            "lights crossing the near plane", int(kWidth * kHeight) / 10);
  EXPECT_EQ(test::stat(c.candidate, "lights-stencil-marked-z-fail"), 5.0);
}

TEST(PrepassStencilVolumes, LightsBehindTheCamera) {
  uint32_t reaching = 0;
  const Comparison c = expectMatchesForward("prepass", roomWithLightsBehindTheCamera(&reaching),
                                            "lights behind the camera", int(kWidth * kHeight) / 4);
  EXPECT_EQ(test::stat(c.candidate, "lights-drawn"), double(reaching));
  EXPECT_EQ(test::stat(c.candidate, "lights-stencil-marked-z-fail"), double(reaching));
}

// Lights in front of the camera, large on screen and partly hidden behind the box, sphere and
// pillar: marked with z-pass; and far small ones drawn without stencil.
TEST(PrepassStencilVolumes, ZPassAndSmallLights) {
  Scene scene = roomScene();
  scene.lights = {pointLight({-2.0f, 1.0f, -6.5f}, 4.0f, {1.0f, 0.5f, 0.2f}, 20.0f),
                  pointLight({2.5f, 2.0f, -7.5f}, 4.0f, {0.2f, 0.6f, 1.0f}, 20.0f),
                  spotLight({-4.0f, 4.5f, -3.0f}, {2.0f, 0.0f, -6.0f}, 12.0f, 35.0f)};
  for (int i = 0; i < 6; ++i)
    scene.lights.push_back(pointLight({-5.0f + 2.0f * float(i), 0.3f, -8.6f}, 0.6f, {1, 1, 1}, 2.0f));
  const Comparison c =
      expectMatchesForward("prepass", scene, "z-pass and small lights", int(kWidth * kHeight) / 6);
  EXPECT_EQ(test::stat(c.candidate, "lights-stencil-marked"), 3.0);
  EXPECT_EQ(test::stat(c.candidate, "lights-stencil-marked-z-fail"), 0.0);
  EXPECT_EQ(test::stat(c.candidate, "lights-small-unstenciled"), 6.0);
}

}  // namespace
}  // namespace lll
