// Instanced drawing (issue 16): a mesh placed many times is drawn with one draw per primitive for
// all its visible instances, each instance's transform and normal matrix computed on the CPU.
// Checked against the same boxes baked into one mesh (the transforms applied by MeshBuilder, an
// independent path), for every technique's mesh passes; instances outside the view are culled;
// 100,000 instances render in seconds on lavapipe. glTF nodes that mirror keep their front faces.
#include <gtest/gtest.h>

#include <fmt/format.h>

#include <chrono>
#include <cmath>
#include <glm/gtc/matrix_transform.hpp>
#include <vector>

#include "gltf_test_support.h"
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

// A glTF of a closed box (single-sided: culling shows its inside where the winding is wrong), a
// double-sided quad and a floor. With `mirrored` the box's and the quad's nodes mirror them
// (scale -1 along one axis); otherwise the same mirror is baked into their meshes' data
// (positions and normals mirrored, triangles reversed) under the same nodes without it: both
// files describe the same surfaces (glTF: a negative determinant makes the fronts clockwise). The
// box has tangents (u, handedness 1), baked as the mirror of u with handedness -1: a mirroring node
// must turn the bitangent cross(n, t) * w, which the renderer does with the sign of the node's
// determinant (mesh.vert and the visibility rebuild) and the baked data with w.
std::filesystem::path mirrorScene(const std::filesystem::path& dir, bool mirrored, bool glassBox) {
  using namespace gltf_test;
  GltfBuilder b;
  // Faces of the unit box: corners centre -u -v, +u -v, +u +v, -u +v with cross(u, v) = n.
  std::vector<float> boxPositions, boxNormals, boxTangents;
  std::vector<uint32_t> boxIndices;
  for (int axis = 0; axis < 3; ++axis) {
    for (float sign : {1.0f, -1.0f}) {
      glm::vec3 n(0.0f), u(0.0f);
      n[axis] = sign;
      u[(axis + 1) % 3] = 1.0f;
      const glm::vec3 v = glm::cross(n, u);
      const uint32_t first = uint32_t(boxPositions.size() / 3);
      for (const glm::vec2 c : {glm::vec2(-1, -1), glm::vec2(1, -1), glm::vec2(1, 1), glm::vec2(-1, 1)}) {
        const glm::vec3 p = 0.5f * (n + c.x * u + c.y * v);
        boxPositions.insert(boxPositions.end(), {p.x, p.y, p.z});
        boxNormals.insert(boxNormals.end(), {n.x, n.y, n.z});
        boxTangents.insert(boxTangents.end(), {u.x, u.y, u.z, 1.0f});
      }
      boxIndices.insert(boxIndices.end(), {first, first + 1, first + 2, first, first + 2, first + 3});
    }
  }
  std::vector<float> quadPositions = {-0.5f, -0.5f, 0, 0.5f, -0.5f, 0, 0.5f, 0.5f, 0, -0.5f, 0.5f, 0};
  std::vector<float> quadNormals = {0, 0, 1, 0, 0, 1, 0, 0, 1, 0, 0, 1};
  std::vector<uint32_t> quadIndices = {0, 1, 2, 0, 2, 3};
  // The box mirrors along x, the quad along z (so its front turns to the back). Tangents, where a
  // mesh has them, mirror too and flip their handedness.
  const auto bake = [](std::vector<float>& positions, std::vector<float>& normals,
                       std::vector<uint32_t>& indices, int axis, std::vector<float>* tangents = nullptr) {
    for (size_t i = size_t(axis); i < positions.size(); i += 3) {
      positions[i] = -positions[i];
      normals[i] = -normals[i];
    }
    for (size_t i = 0; i < indices.size(); i += 3) std::swap(indices[i + 1], indices[i + 2]);
    if (tangents)
      for (size_t i = 0; i < tangents->size(); i += 4) {
        (*tangents)[i + size_t(axis)] = -(*tangents)[i + size_t(axis)];
        (*tangents)[i + 3] = -(*tangents)[i + 3];
      }
  };
  if (!mirrored) {
    bake(boxPositions, boxNormals, boxIndices, 0, &boxTangents);
    bake(quadPositions, quadNormals, quadIndices, 2);
  }
  const auto addMesh = [&](const std::vector<float>& positions, const std::vector<float>& normals,
                           const std::vector<uint32_t>& indices, int material,
                           const std::vector<float>& tangents = {}) {
    json attributes = {{"POSITION", b.addPositions(positions)},
                       {"NORMAL", b.addAccessor(normals, kFloat, "VEC3")}};
    if (!tangents.empty()) attributes["TANGENT"] = b.addAccessor(tangents, kFloat, "VEC4");
    return b.addMesh(json::array({{{"attributes", attributes},
                                   {"indices", b.addAccessor(indices, kUnsignedInt, "SCALAR")},
                                   {"material", material}}}));
  };
  b.doc["materials"] = json::array(
      {{{"pbrMetallicRoughness", {{"baseColorFactor", {0.8, 0.8, 0.8, 1.0}}, {"metallicFactor", 0.0}}}},
       {{"pbrMetallicRoughness",
         {{"baseColorFactor", {0.9, 0.5, 0.2, glassBox ? 0.5 : 1.0}},
          {"metallicFactor", 0.2},
          {"roughnessFactor", 0.4}}},
        {"alphaMode", glassBox ? "BLEND" : "OPAQUE"}},
       {{"pbrMetallicRoughness", {{"baseColorFactor", {0.3, 0.7, 0.9, 1.0}}, {"metallicFactor", 0.0}}},
        {"doubleSided", true}}});
  const int floor = addMesh({-6, 0, -6, -6, 0, 6, 6, 0, 6, 6, 0, -6}, {0, 1, 0, 0, 1, 0, 0, 1, 0, 0, 1, 0},
                            {0, 1, 2, 0, 2, 3}, 0);
  const int box = addMesh(boxPositions, boxNormals, boxIndices, 1, boxTangents);
  const int quad = addMesh(quadPositions, quadNormals, quadIndices, 2);
  const json mirrorX = {-1, 1, 1}, mirrorZ = {1, 1, -1};
  const std::vector<int> roots = {
      b.addNode({{"mesh", floor}}),
      b.addNode({{"translation", {-0.8, 0.7, 0.3}},
                 {"rotation", {0.1, 0.35, 0.05, 0.93}},
                 {"children",
                  {b.addNode(mirrored ? json{{"mesh", box}, {"scale", mirrorX}} : json{{"mesh", box}})}}}),
      b.addNode({{"translation", {1.2, 0.9, 0.5}},
                 {"rotation", {0.0, -0.2, 0.0, 0.98}},
                 {"scale", {1.4, 1.2, 1.0}},
                 {"children",
                  {b.addNode(mirrored ? json{{"mesh", quad}, {"scale", mirrorZ}} : json{{"mesh", quad}})}}})};
  b.setScene(roots);
  return b.writeGltf(dir, mirrored ? "mirrored" : "baked");
}

Scene litMirrorScene(const std::filesystem::path& file) {
  Scene scene = loadGltf(file);
  // The box's normals tilted along its bitangent (and a little along its tangent), so that a
  // bitangent turned the wrong way lights it differently.
  scene.textures.push_back(Texture{"tilt", 1, 1, {150, 40, 190, 255}, false});
  scene.materials.at(1).normalTexture = int(scene.textures.size() - 1);
  for (int i = 0; i < 3; ++i) {
    Light light;
    light.position = glm::vec3(-2.5f + 2.5f * float(i), 2.2f, 1.8f - 1.5f * float(i == 1));
    light.color = glm::vec3(i == 0, i == 1, i == 2) * 0.7f + 0.3f;
    light.intensity = 5.0f;
    light.range = 8.0f;
    scene.lights.push_back(light);
  }
  DirectionalLight sun;
  sun.direction = glm::normalize(glm::vec3(0.4f, -1.0f, -0.3f));
  sun.illuminance = 2.0f;
  scene.directionalLights.push_back(sun);  // its shadow: the casters' culling sees the winding too
  Camera camera;
  camera.name = "view";
  camera.eye = glm::vec3(0.5f, 2.6f, 4.2f);
  camera.target = glm::vec3(0.0f, 0.6f, 0.0f);
  scene.cameras.push_back(camera);
  return scene;
}

// Every technique, with surfaces from the visibility buffer (rasterized by hardware and in
// compute) and from the geometry passes, gives the mirrored nodes the image of the mirror baked in.
TEST(Instancing, MirroredGltfNodesKeepTheirFrontFaces) {
  const std::filesystem::path dir =
      std::filesystem::temp_directory_path() / ("lll-mirror-" + std::to_string(std::random_device{}()));
  std::filesystem::create_directories(dir);
  for (bool glassBox : {false, true}) {
    const Scene mirrored = litMirrorScene(mirrorScene(dir, true, glassBox));
    const Scene baked = litMirrorScene(mirrorScene(dir, false, glassBox));
    ASSERT_EQ(mirrored.triangleCount(), baked.triangleCount());
    for (const TechniqueInfo& technique : techniques()) {
      for (const char* path : {"visibility", "visibility-compute", "gbuffer"}) {
        RenderSettings settings = smallSettings(technique.name);
        settings.surfaces =
            path == std::string("gbuffer") ? SurfaceSource::Gbuffer : SurfaceSource::Visibility;
        settings.raster =
            path == std::string("visibility-compute") ? RasterChoice::Compute : RasterChoice::Hardware;
        settings.shadowRaster = settings.raster;
        // Techniques that draw opaque geometry again with an EQUAL depth test refuse the compute
        // rasterizer (test_compute_raster.cpp).
        if (settings.raster == RasterChoice::Compute && technique.redrawsOpaque &&
            technique.redrawsOpaque(settings))
          continue;
        const test::Rendered a = test::render(mirrored, settings);
        const test::Rendered b = test::render(baked, settings);
        const std::string label =
            fmt::format("{} {}{}", technique.name, path, glassBox ? " glass box" : " opaque box");
        // Not the same pixels by construction (the transforms round differently), and the compute
        // rasterizer may give an edge pixel to the other triangle.
        test::expectWithinBound(a.ldr, b.ldr, test::kRasterBound, label);
        EXPECT_GT(test::shareAboveBlack(b.ldr), 0.5) << label;
      }
    }
  }
  std::error_code ec;
  std::filesystem::remove_all(dir, ec);
}

}  // namespace
}  // namespace lll
