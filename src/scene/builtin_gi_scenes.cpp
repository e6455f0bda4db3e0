#include "scene/builtin_gi_scenes.h"

#include <glm/gtc/constants.hpp>

#include "scene/mesh_builder.h"

namespace lll::builtin {
namespace {

Material lambertian(const char* name, const glm::vec3& albedo) {
  Material m;
  m.name = name;
  m.baseColorFactor = glm::vec4(albedo, 1.0f);
  m.metallic = 0.0f;
  m.roughness = 1.0f;
  return m;
}

}  // namespace

Scene makeCornell() {
  Scene scene;
  scene.name = "cornell";
  scene.materials = {lambertian("white", glm::vec3(0.75f)), lambertian("red", {0.75f, 0.08f, 0.06f}),
                     lambertian("green", {0.10f, 0.60f, 0.10f})};
  constexpr float kSide = 5.5f, kWall = 0.1f, kSealedEnd = 8.0f;
  MeshBuilder room("cornell");
  room.setMaterial(0);
  room.addBoxBetween({-kWall, -kWall, -kWall}, {kSealedEnd + kWall, 0.0f, kSide + kWall});          // floor
  room.addBoxBetween({-kWall, kSide, -kWall}, {kSealedEnd + kWall, kSide + kWall, kSide + kWall});  // ceiling
  room.addBoxBetween({0.0f, 0.0f, -kWall}, {kSealedEnd, kSide, 0.0f});                              // back
  room.addBoxBetween({0.0f, 0.0f, kSide}, {kSealedEnd, kSide, kSide + kWall});                      // front
  room.addBoxBetween({kSealedEnd, 0.0f, 0.0f}, {kSealedEnd + kWall, kSide, kSide});  // sealed end
  room.setMaterial(1);
  room.addBoxBetween({-kWall, 0.0f, 0.0f}, {0.0f, kSide, kSide});
  room.setMaterial(2);
  room.addBoxBetween({kSide, 0.0f, 0.0f}, {kSide + kWall, kSide, kSide});
  addInstance(scene, room.addTo(scene));

  Light spot;
  spot.type = LightType::Spot;
  spot.position = glm::vec3(4.5f, 5.0f, 2.75f);
  spot.direction = glm::normalize(glm::vec3(0.0f, 3.0f, 2.75f) - spot.position);
  spot.intensity = 60.0f;
  spot.range = 12.0f;
  spot.innerConeAngle = glm::radians(12.0f);
  spot.outerConeAngle = glm::radians(15.0f);
  scene.lights.push_back(spot);

  scene.cameras.push_back(
      Camera{"room", {2.75f, 2.75f, 5.4f}, {2.75f, 2.4f, 0.0f}, {0, 1, 0}, glm::radians(70.0f)});
  scene.cameras.push_back(
      Camera{"sealed", {6.8f, 4.5f, 5.4f}, {6.8f, 0.0f, 1.0f}, {0, 1, 0}, glm::radians(70.0f)});
  return scene;
}

Scene makeSphereRoom() {
  Scene scene;
  scene.name = "sphere-room";
  Material grey = lambertian("grey", glm::vec3(kSphereRoomAlbedo));
  grey.doubleSided = true;
  scene.materials.push_back(grey);
  MeshBuilder sphere("sphere");
  sphere.addSphere(glm::mat4(1.0f), kSphereRoomRadius, 96, 48);
  addInstance(scene, sphere.addTo(scene));
  Light light;
  light.position = glm::vec3(0.0f);
  light.intensity = kSphereRoomIntensity;
  light.range = 1000.0f;  // the window is 1 - 1e-10 at the wall: plain inverse square
  scene.lights.push_back(light);
  scene.cameras.push_back(
      Camera{"inside", {0.0f, 0.0f, 2.0f}, {0.0f, 0.0f, -3.0f}, {0, 1, 0}, glm::radians(60.0f)});
  return scene;
}

}  // namespace lll::builtin
