#include "scene/builtin_scenes.h"

#include "scene/lights.h"

#include <glm/gtc/constants.hpp>
#include <glm/gtx/color_space.hpp>

#include "scene/builtin_atrium.h"
#include "scene/builtin_gi_scenes.h"
#include "scene/mesh_builder.h"

namespace lll {

namespace {

// ThreeL's lights reach every point of the scene from anywhere in it (the atrium's diagonal is
// under 50 m), so every light touches every pixel: the worst case for any light culling.
constexpr float kThreeLRange = 1000.0f;
// What all of a ThreeL scene's lights give together, split evenly: at exposure 1 the courtyard
// floor then sits in the filmic curve's shoulder rather than past it, whatever the light count.
constexpr float kThreeLTotalIntensity = 200.0f;

Scene makeAtrium() {
  Scene scene = builtin::makeAtriumGeometry();
  scene.name = "atrium";
  builtin::addAtriumLights(scene);
  scene.smokeSource = glm::vec3(0.0f, 0.02f, 0.0f);  // on the floor medallion, in the middle
  return scene;
}

// The atrium with every light a spot: its point lights turned into downlights (each shining straight
// down, 35 to 50 degrees), beside its six gallery spots. The bench's scene for many shadowed spots
// (issue 14's measure: the sun and 64 shadowed spots), where each spot is one shadow view rather
// than a point light's six.
Scene makeAtriumSpots() {
  Scene scene = makeAtrium();
  scene.name = "atrium-spots";
  for (Light& light : scene.lights) {
    if (light.type != LightType::Point) continue;
    light.type = LightType::Spot;
    light.direction = glm::vec3(0.0f, -1.0f, 0.0f);
    light.innerConeAngle = glm::radians(35.0f);
    light.outerConeAngle = glm::radians(50.0f);
  }
  return scene;
}

// The i-th element of the van der Corput sequence in `base`: evenly spread, and the same
// everywhere, unlike a random generator's output.
float radicalInverse(uint32_t i, uint32_t base) {
  float result = 0.0f, scale = 1.0f / float(base);
  for (; i > 0; i /= base, scale /= float(base)) result += scale * float(i % base);
  return result;
}

Scene makeThreeL(uint32_t count) {
  Scene scene = builtin::makeAtriumGeometry();
  scene.name = "threel" + std::to_string(count);
  const Bounds volume = builtin::atriumCourtyardVolume();
  for (uint32_t i = 0; i < count; ++i) {
    const glm::vec3 t(radicalInverse(i + 1, 2), radicalInverse(i + 1, 3), radicalInverse(i + 1, 5));
    Light light;
    light.position = volume.min + t * volume.extent();
    light.color = glm::rgbColor(glm::vec3(360.0f * float(i) / float(count), 1.0f, 1.0f));
    light.intensity = kThreeLTotalIntensity / float(count);
    light.range = kThreeLRange;
    scene.lights.push_back(light);
  }
  return scene;
}

// The analytic test scenes: a 40 m grey Lambertian square at y = 0 seen from straight above.
Scene makePlane(const char* name) {
  Scene scene;
  scene.name = name;
  Material material;
  material.name = "lambertian grey";
  material.baseColorFactor = glm::vec4(0.8f, 0.8f, 0.8f, 1.0f);
  material.metallic = 0.0f;
  material.roughness = 1.0f;
  scene.materials.push_back(material);
  MeshBuilder plane("plane");
  plane.setMaterial(0);
  plane.addQuad(glm::mat4(1.0f), glm::vec2(40.0f), 1.0f);
  addInstance(scene, plane.addTo(scene));
  scene.cameras.push_back(
      Camera{"top", {0.0f, 8.0f, 0.001f}, {0.0f, 0.0f, 0.0f}, {0.0f, 0.0f, -1.0f}, glm::radians(90.0f)});
  return scene;
}

Scene makePointPlane() {
  Scene scene = makePlane("plane");
  Light light;
  light.position = glm::vec3(0.0f, 2.0f, 0.0f);
  light.intensity = 10.0f;
  light.range = 6.0f;
  scene.lights.push_back(light);
  return scene;
}

Scene makeSpotPlane() {
  Scene scene = makePlane("spot-plane");
  Light light;
  light.type = LightType::Spot;
  light.position = glm::vec3(0.0f, 3.0f, 0.0f);
  light.direction = glm::vec3(0.0f, -1.0f, 0.0f);
  light.intensity = 50.0f;
  light.range = 8.0f;
  light.innerConeAngle = glm::radians(20.0f);
  light.outerConeAngle = glm::radians(30.0f);
  scene.lights.push_back(light);
  return scene;
}

// Box lights (Bezrati's box-shaped volumes): a long one standing in the plane, turned 30 degrees,
// and three smaller ones of other orientations, to show their rectangular footprints.
Scene makeBoxPlane() {
  Scene scene = makePlane("box-plane");
  const float turn = glm::radians(30.0f);
  scene.lights.push_back(makeBoxLight({0.5f, 1.0f, 0.0f}, {std::cos(turn), 0.0f, std::sin(turn)},
                                      {0.0f, 1.0f, 0.0f}, {4.0f, 1.5f, 1.5f}, {1.0f, 0.9f, 0.8f}, 6.0f));
  scene.lights.push_back(makeBoxLight({-5.0f, 0.5f, -4.0f}, {1.0f, 0.0f, 1.0f}, {0.0f, 1.0f, 0.0f},
                                      {1.0f, 1.0f, 2.5f}, {1.0f, 0.2f, 0.1f}, 3.0f));
  scene.lights.push_back(makeBoxLight({5.0f, 0.8f, -5.0f}, {1.0f, 0.0f, 0.0f}, {0.0f, 1.0f, -1.0f},
                                      {2.0f, 1.0f, 1.0f}, {0.1f, 0.4f, 1.0f}, 3.0f));
  scene.lights.push_back(makeBoxLight({-4.0f, 0.3f, 5.0f}, {1.0f, 0.3f, -1.0f}, {0.0f, 1.0f, 0.3f},
                                      {3.0f, 0.6f, 0.6f}, {0.2f, 1.0f, 0.3f}, 2.0f));
  return scene;
}

struct BuiltinEntry {
  const char* name;
  const char* description;
  Scene (*make)();
};

const BuiltinEntry kBuiltinScenes[] = {
    {"atrium",
     "two-storey arcaded courtyard, 30 m x 14 m, with banners, glass and bronze; 104 coloured point lights "
     "and 6 spots (the default)",
     makeAtrium},
    {"atrium-spots",
     "the atrium with its 104 point lights turned into downlights: 110 spot lights (the shadowed-spots "
     "benchmark)",
     makeAtriumSpots},
    {"threel16", "ThreeL benchmark: the atrium lit by 16 coloured lights that each reach the whole scene",
     [] { return makeThreeL(16); }},
    {"threel256", "ThreeL benchmark: the atrium lit by 256 coloured lights that each reach the whole scene",
     [] { return makeThreeL(256); }},
    {"plane", "analytic test: a 40 m grey Lambertian plane under one point light 2 m above it",
     makePointPlane},
    {"spot-plane", "analytic test: the same plane under one spot light 3 m above it, pointing down",
     makeSpotPlane},
    {"box-plane",
     "the same plane with four box lights of different sizes and orientations (Bezrati's box volumes)",
     makeBoxPlane},
    {"cornell",
     "indirect-light test: a closed Cornell-like room (red and green walls) with a spot on the red wall, and "
     "a "
     "sealed second room (try --gi vpl)",
     builtin::makeCornell},
    {"sphere-room",
     "indirect-light test: the inside of a closed grey sphere with a point light at its centre (analytic "
     "bounces)",
     builtin::makeSphereRoom},
};

}  // namespace

std::vector<BuiltinSceneInfo> builtinScenes() {
  std::vector<BuiltinSceneInfo> scenes;
  for (const BuiltinEntry& entry : kBuiltinScenes) scenes.push_back({entry.name, entry.description});
  return scenes;
}

std::optional<Scene> makeBuiltinScene(const std::string& name) {
  for (const BuiltinEntry& entry : kBuiltinScenes) {
    if (name == entry.name) return entry.make();
  }
  return std::nullopt;
}

}  // namespace lll
