// Instanced drawing (issue 16): a mesh placed many times is drawn with one draw per primitive for
// all its visible instances, each instance's transform and normal matrix computed on the CPU.
// Checked against the same boxes baked into one mesh (the transforms applied by MeshBuilder, an
// independent path), for every technique's mesh passes; instances outside the view are culled;
// 100,000 instances render in seconds on lavapipe.
#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <glm/gtc/matrix_transform.hpp>
#include <vector>

#include "lighting/technique.h"
#include "scene/mesh_builder.h"
#include "test_support.h"

namespace lll {
namespace {

// A floor, lights and a camera looking at boxes around the origin; `place` adds the boxes.
Scene boxesScene(const std::vector<glm::mat4>& transforms, bool instanced, bool glass) {
  Scene scene;
  scene.name = instanced ? "instanced" : "baked";
  Material white;
  white.metallic = 0.0f;
  white.roughness = 0.6f;
  scene.materials.push_back(white);
  Material pane = white;
  pane.baseColorFactor = glm::vec4(0.3f, 0.6f, 1.0f, 0.4f);
  pane.alphaMode = AlphaMode::Blend;
  scene.materials.push_back(pane);
  MeshBuilder floor("floor");
  floor.addQuad(glm::mat4(1.0f), glm::vec2(20.0f));
  addInstance(scene, floor.addTo(scene));
  MeshBuilder boxes("boxes");
  boxes.setMaterial(glass ? 1 : 0);
  if (instanced) {
    boxes.addBox(glm::mat4(1.0f), glm::vec3(0.5f));
    const uint32_t mesh = boxes.addTo(scene);
    for (const glm::mat4& t : transforms) addInstance(scene, mesh, t);
  } else {
    for (const glm::mat4& t : transforms) boxes.addBox(t, glm::vec3(0.5f));
    addInstance(scene, boxes.addTo(scene));
  }
  for (int i = 0; i < 3; ++i) {
    Light light;
    light.position = glm::vec3(-3.0f + 3.0f * float(i), 2.0f, 1.0f);
    light.color = glm::vec3(i == 0, i == 1, i == 2) * 0.7f + 0.3f;
    light.intensity = 6.0f;
    light.range = 8.0f;
    scene.lights.push_back(light);
  }
  Camera camera;
  camera.name = "view";
  camera.eye = glm::vec3(0.0f, 4.0f, 7.0f);
  camera.target = glm::vec3(0.0f, 0.0f, 0.0f);
  scene.cameras.push_back(camera);
  return scene;
}

// Rotated, non-uniformly scaled and translated boxes (normal matrices differ from the models).
std::vector<glm::mat4> scatteredBoxes() {
  std::vector<glm::mat4> transforms;
  for (int i = 0; i < 12; ++i) {
    glm::mat4 t =
        glm::translate(glm::mat4(1.0f), glm::vec3(-3.0f + 0.55f * float(i), 0.4f, float(i % 3) - 1.0f));
    t = glm::rotate(t, 0.4f * float(i), glm::normalize(glm::vec3(1.0f, 2.0f, 0.5f)));
    transforms.push_back(glm::scale(t, glm::vec3(1.0f + 0.1f * float(i % 4), 0.6f, 1.4f)));
  }
  return transforms;
}

RenderSettings smallSettings(const std::string& technique) {
  RenderSettings settings;
  settings.width = 96;
  settings.height = 54;
  settings.technique = technique;
  return settings;
}

TEST(Instancing, MatchesTheSameBoxesBakedIntoOneMesh) {
  for (bool glass : {false, true}) {
    const Scene instanced = boxesScene(scatteredBoxes(), true, glass);
    const Scene baked = boxesScene(scatteredBoxes(), false, glass);
    for (const TechniqueInfo& technique : techniques()) {
      const test::Rendered a = test::render(instanced, smallSettings(technique.name));
      const test::Rendered b = test::render(baked, smallSettings(technique.name));
      // The same triangles, transformed in the vertex shader instead of on the CPU: positions
      // and normals differ in the last bits only.
      EXPECT_GT(test::psnr(a.ldr, b.ldr), 45.0) << technique.name << (glass ? " glass" : " opaque");
    }
  }
}

// Boxes behind the camera are culled (not drawn), and the image is the one without them.
TEST(Instancing, InstancesOutsideTheViewAreCulled) {
  std::vector<glm::mat4> transforms = scatteredBoxes();
  const Scene visibleOnly = boxesScene(transforms, true, false);
  for (int i = 0; i < 50; ++i)
    transforms.push_back(
        glm::translate(glm::mat4(1.0f), glm::vec3(float(i % 10) - 5.0f, 0.5f, 12.0f + float(i / 10))));
  const Scene withHidden = boxesScene(transforms, true, false);
  Renderer renderer(test::gpuContext(), withHidden, smallSettings("forward"));
  renderer.renderFrame(true);
  EXPECT_EQ(renderer.gpuScene().visibleInstances(), 1u + 12u);  // the floor and the scattered boxes
  const test::Rendered reference = test::render(visibleOnly, smallSettings("forward"));
  EXPECT_TRUE(std::isinf(test::psnr(renderer.ldrImage(), reference.ldr)));
}

// 100,000 instances of one box: one draw per pass, whatever the count, and seconds on lavapipe
// (before instancing each instance was a draw of its own).
TEST(Instancing, HundredThousandInstancesInOneDraw) {
  std::vector<glm::mat4> transforms;
  for (int i = 0; i < 100000; ++i) {
    const float x = float(i % 400) * 0.05f - 10.0f, z = float(i / 400) * 0.05f - 10.0f;
    transforms.push_back(
        glm::scale(glm::translate(glm::mat4(1.0f), glm::vec3(x, 0.1f, z)), glm::vec3(0.06f)));
  }
  const Scene scene = boxesScene(transforms, true, false);
  RenderSettings settings = smallSettings("lll");
  settings.width = 64;
  settings.height = 36;
  const auto start = std::chrono::steady_clock::now();
  Renderer renderer(test::gpuContext(), scene, settings);
  renderer.renderFrame(true);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  EXPECT_EQ(renderer.gpuScene().drawCount(DrawFilter::OpaqueOnly), 2u);  // the floor's draw and the boxes'
  EXPECT_GT(renderer.gpuScene().visibleInstances(), 50000u);
  std::printf("100,000 instances: %u visible, %.2f s for the renderer and one lll frame at 64x36\n",
              renderer.gpuScene().visibleInstances(), seconds);
  EXPECT_LT(seconds, 60.0);
}

}  // namespace
}  // namespace lll
