// The default scene's lights. Intensities follow from the ranges: a light of range r and
// intensity ~r^2 * k cd gives a surface at half its range an irradiance of about 3.5 k, which
// after a stone albedo and the filmic curve reads as well lit without blowing out.
#include <glm/gtc/constants.hpp>
#include <glm/gtx/color_space.hpp>

#include "scene/builtin_atrium.h"

namespace lll::builtin {

using namespace atrium;

namespace {

// Saturated colours that step around the hue circle by the golden angle, so that neighbouring
// lights always differ.
class Palette {
 public:
  glm::vec3 next() {
    const float hue = glm::fract(0.07f + 0.618034f * float(count_++));
    return glm::rgbColor(glm::vec3(360.0f * hue, 0.85f, 1.0f));
  }

 private:
  uint32_t count_ = 0;
};

void addPoint(Scene& scene, const glm::vec3& position, const glm::vec3& color, float range, float intensity) {
  Light light;
  light.type = LightType::Point;
  light.position = position;
  light.color = color;
  light.range = range;
  light.intensity = intensity;
  scene.lights.push_back(light);
}

// One light under every bay of both aisles, halfway between the arcade and the outer wall.
void addAisleLights(Scene& scene, Palette& palette) {
  const float aisleMiddle = 0.5f * (0.5f * kArcadeThickness + kAisleWidth);
  for (float height : {3.3f, kGalleryFloor + 2.5f}) {
    for (const ArcadeRow& row : arcadeRows()) {
      for (int k = 0; k < row.bays; ++k) {
        const glm::vec3 p = row.bayCentre(k) - aisleMiddle * row.towardsCourtyard() + glm::vec3(0, height, 0);
        addPoint(scene, p, palette.next(), 4.5f, 10.0f);
      }
    }
  }
}

// Low lights at the foot of the columns, and lights floating in three rows over the courtyard.
void addCourtyardLights(Scene& scene, Palette& palette) {
  for (const ArcadeRow& row : arcadeRows()) {
    for (int k = 1; k < row.bays; ++k) {
      const bool isLong = row.bays == kLongBays;
      if (!isLong && k != row.bays / 2) continue;
      const glm::vec3 p = row.column(k) + 0.9f * row.towardsCourtyard() + glm::vec3(0, 0.6f, 0);
      addPoint(scene, p, palette.next(), 2.5f, 2.0f);
    }
  }
  for (int lane = 0; lane < 3; ++lane) {
    for (int i = 0; i < 8; ++i) {
      const float height = 2.5f + 2.0f * (0.5f + 0.5f * std::sin(1.3f * float(i) + 2.0f * float(lane)));
      const glm::vec3 p(-10.5f + 3.0f * float(i), height, -3.8f + 3.8f * float(lane));
      addPoint(scene, p, palette.next(), 5.5f, 9.0f);
    }
  }
}

// A light in front of every banner, and a few around the glass and metal on the plinths.
void addAccentLights(Scene& scene, Palette& palette) {
  for (const ArcadeRow& row : arcadeRows()) {
    for (int k = 0; k < row.bays; ++k) {
      const bool isLong = row.bays == kLongBays;
      if (isLong ? k % 2 == 0 : k != row.bays / 2) continue;
      const glm::vec3 p = row.column(k) + 2.0f * row.towardsCourtyard() + glm::vec3(0, 5.2f, 0);
      addPoint(scene, p, palette.next(), 3.5f, 9.0f);
    }
  }
  const glm::vec3 objects[] = {{-8.0f, 2.2f, -2.2f}, {-8.0f, 2.2f, 2.2f}, {-4.5f, 1.8f, -1.4f},
                               {-4.0f, 1.4f, 1.6f},  {8.0f, 2.2f, -2.2f}, {8.0f, 2.2f, 2.2f}};
  for (const glm::vec3& p : objects) addPoint(scene, p, palette.next(), 3.0f, 4.0f);
}

void addSpot(Scene& scene, const glm::vec3& position, const glm::vec3& target, const glm::vec3& color) {
  Light light;
  light.type = LightType::Spot;
  light.position = position;
  light.direction = glm::normalize(target - position);
  light.color = color;
  light.range = 15.0f;
  light.intensity = 200.0f;
  light.innerConeAngle = glm::radians(26.0f);
  light.outerConeAngle = glm::radians(34.0f);
  scene.lights.push_back(light);
}

// Spots on the upper galleries, just in front of the rail, shining down into the courtyard: the
// long sides light the floor and the plinths, the short ones the floor on either side of the
// medallion.
void addGallerySpots(Scene& scene) {
  const glm::vec3 warm(1.0f, 0.82f, 0.6f), cool(0.7f, 0.8f, 1.0f);
  const float y = kGalleryFloor + 2.7f, inFront = kCourtHalfZ - 0.55f;
  for (float x : {-5.625f, 5.625f}) {
    addSpot(scene, {x, y, inFront}, {0.8f * x, 0.0f, 1.0f}, warm);
    addSpot(scene, {-x, y, -inFront}, {-0.8f * x, 0.0f, -1.0f}, warm);
  }
  for (float side : {-1.0f, 1.0f}) {
    addSpot(scene, {side * (kCourtHalfX - 0.55f), y, 0.0f}, {side * 6.0f, 0.0f, 0.0f}, cool);
  }
}

}  // namespace

void addAtriumLights(Scene& scene) {
  Palette palette;
  addAisleLights(scene, palette);
  addCourtyardLights(scene, palette);
  addAccentLights(scene, palette);
  addGallerySpots(scene);
}

}  // namespace lll::builtin
