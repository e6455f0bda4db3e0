#pragma once
// A scene that exercises light lists at their edges, shared by the lll and light-grid tests.
#include <glm/glm.hpp>
#include <random>

#include "scene/builtin_scenes.h"
#include "scene/lights.h"

namespace lll::test {

// The plane under a camera 8 m above it, with point, spot and box lights of every awkward kind: one
// around the camera, some below the floor (hidden), some off-screen, spots pointing every way,
// boxes turned every way (one around the camera, one under the floor).
inline Scene awkwardLightsScene(uint32_t extraPoints) {
  Scene scene = *makeBuiltinScene("plane");
  scene.lights.clear();
  std::mt19937 rng(7);
  auto uniform = [&](float lo, float hi) { return lo + (hi - lo) * float(rng() >> 8) / 16777216.0f; };
  for (uint32_t i = 0; i < extraPoints; ++i) {
    Light l;
    l.position = {uniform(-12, 12), uniform(-1.5f, 6), uniform(-12, 12)};
    l.range = uniform(0.4f, 4.0f);
    l.intensity = l.range * l.range;
    l.color = {uniform(0.2f, 1), uniform(0.2f, 1), uniform(0.2f, 1)};
    scene.lights.push_back(l);
  }
  Light aroundCamera;
  aroundCamera.position = {0.3f, 7.5f, 0.2f};
  aroundCamera.range = 9.0f;
  aroundCamera.intensity = 20.0f;
  scene.lights.push_back(aroundCamera);
  Light hidden;
  hidden.position = {1.0f, -2.0f, 1.0f};
  hidden.range = 1.5f;
  scene.lights.push_back(hidden);
  Light offscreen;
  offscreen.position = {40.0f, 1.0f, 0.0f};
  offscreen.range = 3.0f;
  scene.lights.push_back(offscreen);
  for (int i = 0; i < 8; ++i) {
    Light spot;
    spot.type = LightType::Spot;
    spot.position = {uniform(-6, 6), uniform(0.5f, 5), uniform(-6, 6)};
    spot.direction = glm::normalize(glm::vec3(uniform(-1, 1), uniform(-1, -0.2f), uniform(-1, 1)));
    spot.range = uniform(3, 9);
    spot.intensity = 30.0f;
    spot.outerConeAngle = uniform(0.2f, 1.3f);  // some wider than 60 degrees: filled as spheres
    spot.innerConeAngle = spot.outerConeAngle * 0.7f;
    scene.lights.push_back(spot);
  }
  for (int i = 0; i < 8; ++i) {
    const glm::vec3 x(uniform(-1, 1), uniform(-1, 1), uniform(-1, 1)),
        y(uniform(-1, 1), uniform(-1, 1), uniform(-1, 1));
    scene.lights.push_back(makeBoxLight({uniform(-8, 8), uniform(-0.5f, 3), uniform(-8, 8)}, x, y,
                                        {uniform(0.3f, 4), uniform(0.3f, 2), uniform(0.3f, 1.5f)},
                                        {uniform(0.2f, 1), uniform(0.2f, 1), uniform(0.2f, 1)}, 6.0f));
  }
  scene.lights.push_back(
      makeBoxLight({0.0f, 7.0f, 0.5f}, {1, 0, 0}, {0, 1, 1}, {3, 2, 2}, glm::vec3(1.0f), 8.0f));
  scene.lights.push_back(
      makeBoxLight({2.0f, -1.5f, 0.0f}, {1, 0, 0}, {0, 1, 0}, {2, 1, 2}, glm::vec3(1.0f), 8.0f));
  return scene;
}

}  // namespace lll::test
