// The built-in scenes and the mesh builder they are made with: valid geometry (indices, normals,
// winding, materials), the lights, cameras and objects each scene promises, and determinism.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <glm/gtc/constants.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <map>
#include <set>

#include "scene/builtin_scenes.h"
#include "scene/mesh_builder.h"

namespace lll {
namespace {

// Scenes are built once per test binary: the atrium takes a while and every test only reads it.
const Scene& builtScene(const std::string& name) {
  static std::map<std::string, Scene> cache;
  auto it = cache.find(name);
  if (it == cache.end()) {
    std::optional<Scene> scene = makeBuiltinScene(name);
    if (!scene) throw std::runtime_error("no built-in scene " + name);
    it = cache.emplace(name, std::move(*scene)).first;
  }
  return it->second;
}

std::vector<std::string> builtinNames() {
  std::vector<std::string> names;
  for (const BuiltinSceneInfo& info : builtinScenes()) names.push_back(info.name);
  return names;
}

// The fraction of the scene's triangles whose counter-clockwise face normal points the same way
// (within 90 degrees) as the average of its vertex normals. Collapsed triangles count as agreeing.
double fractionWoundWithNormals(const Scene& scene) {
  uint64_t total = 0, agreeing = 0;
  for (const Mesh& mesh : scene.meshes) {
    for (const Primitive& p : mesh.primitives) {
      for (uint32_t i = 0; i + 2 < p.indexCount; i += 3) {
        const Vertex* v[3];
        for (int k = 0; k < 3; ++k)
          v[k] = &scene.vertices[p.vertexOffset + scene.indices[p.firstIndex + i + k]];
        const glm::vec3 face = glm::cross(v[1]->position - v[0]->position, v[2]->position - v[0]->position);
        ++total;
        if (glm::dot(face, v[0]->normal + v[1]->normal + v[2]->normal) >= 0.0f) ++agreeing;
      }
    }
  }
  return total == 0 ? 0.0 : double(agreeing) / double(total);
}

template <int N>
bool finite(const glm::vec<N, float>& v) {
  for (int i = 0; i < N; ++i) {
    if (!std::isfinite(v[i])) return false;
  }
  return true;
}

size_t countLights(const Scene& scene, LightType type) {
  return size_t(std::count_if(scene.lights.begin(), scene.lights.end(),
                              [&](const Light& l) { return l.type == type; }));
}

std::array<glm::vec3, 8> corners(const Bounds& b) {
  std::array<glm::vec3, 8> result;
  for (int i = 0; i < 8; ++i) {
    result[i] = glm::vec3(i & 1 ? b.max.x : b.min.x, i & 2 ? b.max.y : b.min.y, i & 4 ? b.max.z : b.min.z);
  }
  return result;
}

// Whether the segment from `from` to `to` passes through any opaque triangle of the scene.
bool occluded(const Scene& scene, const glm::vec3& from, const glm::vec3& to) {
  const glm::vec3 d = to - from;
  for (const Instance& instance : scene.instances) {
    for (const Primitive& p : scene.meshes[instance.mesh].primitives) {
      if (scene.materials[p.material].alphaMode == AlphaMode::Blend) continue;
      for (uint32_t i = 0; i + 2 < p.indexCount; i += 3) {
        glm::vec3 v[3];
        for (int k = 0; k < 3; ++k) {
          const glm::vec3 local =
              scene.vertices[p.vertexOffset + scene.indices[p.firstIndex + i + k]].position;
          v[k] = glm::vec3(instance.transform * glm::vec4(local, 1.0f));
        }
        const glm::vec3 e1 = v[1] - v[0], e2 = v[2] - v[0], pv = glm::cross(d, e2);
        const float det = glm::dot(e1, pv);
        if (std::abs(det) < 1e-12f) continue;
        const glm::vec3 tv = from - v[0];
        const float u = glm::dot(tv, pv) / det;
        const glm::vec3 qv = glm::cross(tv, e1);
        const float w = glm::dot(d, qv) / det, t = glm::dot(e2, qv) / det;
        if (u >= 0 && w >= 0 && u + w <= 1 && t > 1e-4f && t < 1.0f - 1e-4f) return true;
      }
    }
  }
  return false;
}

// ---- every built-in scene ----

class EveryBuiltinScene : public ::testing::TestWithParam<std::string> {};

TEST_P(EveryBuiltinScene, BuildsWithGeometryLightsAndACamera) {
  const Scene& scene = builtScene(GetParam());
  EXPECT_EQ(scene.name, GetParam());
  EXPECT_FALSE(scene.instances.empty());
  EXPECT_FALSE(scene.lights.empty());
  EXPECT_FALSE(scene.cameras.empty());
  EXPECT_GT(scene.triangleCount(), 0u);
  EXPECT_TRUE(scene.worldBounds().valid());
}

TEST_P(EveryBuiltinScene, IndicesStayInsideTheirArrays) {
  const Scene& scene = builtScene(GetParam());
  for (const Instance& instance : scene.instances) ASSERT_LT(instance.mesh, scene.meshes.size());
  for (const Mesh& mesh : scene.meshes) {
    ASSERT_FALSE(mesh.primitives.empty()) << mesh.name;
    for (const Primitive& p : mesh.primitives) {
      ASSERT_GT(p.indexCount, 0u) << mesh.name;
      ASSERT_EQ(p.indexCount % 3, 0u) << mesh.name;
      ASSERT_LE(uint64_t(p.firstIndex) + p.indexCount, scene.indices.size()) << mesh.name;
      for (uint32_t i = 0; i < p.indexCount; ++i) {
        ASSERT_LT(uint64_t(scene.indices[p.firstIndex + i]) + p.vertexOffset, scene.vertices.size())
            << mesh.name;
      }
    }
  }
}

TEST_P(EveryBuiltinScene, VerticesAreFiniteWithUnitNormals) {
  const Scene& scene = builtScene(GetParam());
  for (size_t i = 0; i < scene.vertices.size(); ++i) {
    const Vertex& v = scene.vertices[i];
    ASSERT_TRUE(finite(v.position) && finite(v.uv)) << "vertex " << i;
    ASSERT_TRUE(finite(v.normal)) << "vertex " << i;
    ASSERT_NEAR(glm::length(v.normal), 1.0f, 1e-3f) << "vertex " << i;
  }
}

TEST_P(EveryBuiltinScene, MaterialsAndTexturesAreValid) {
  const Scene& scene = builtScene(GetParam());
  for (const Mesh& mesh : scene.meshes) {
    for (const Primitive& p : mesh.primitives) ASSERT_LT(p.material, scene.materials.size()) << mesh.name;
  }
  for (const Material& m : scene.materials) {
    for (int texture : {m.baseColorTexture, m.metallicRoughnessTexture, m.normalTexture, m.emissiveTexture,
                        m.occlusionTexture}) {
      EXPECT_TRUE(texture >= -1 && texture < int(scene.textures.size())) << m.name;
    }
    EXPECT_TRUE(m.metallic >= 0.0f && m.metallic <= 1.0f && m.roughness >= 0.0f && m.roughness <= 1.0f)
        << m.name;
  }
  EXPECT_LE(scene.textures.size(), 8u);
  for (const Texture& t : scene.textures) {
    EXPECT_GT(t.width * t.height, 0u) << t.name;
    EXPECT_EQ(t.rgba.size(), size_t(t.width) * t.height * 4) << t.name;
  }
}

TEST_P(EveryBuiltinScene, TrianglesAreWoundCounterClockwiseAroundTheirNormals) {
  EXPECT_GE(fractionWoundWithNormals(builtScene(GetParam())), 0.99);
}

TEST_P(EveryBuiltinScene, LightsAreWellFormed) {
  for (const Light& l : builtScene(GetParam()).lights) {
    EXPECT_TRUE(finite(l.position));
    EXPECT_GT(l.intensity, 0.0f);
    EXPECT_GT(l.range, 0.0f);
    EXPECT_NEAR(glm::length(l.direction), 1.0f, 1e-4f);
    EXPECT_GT(glm::length(l.color), 0.0f);
    if (l.type == LightType::Spot) {
      EXPECT_LT(l.innerConeAngle, l.outerConeAngle);
      EXPECT_LT(l.outerConeAngle, 0.5f * glm::pi<float>());
    }
  }
}

TEST_P(EveryBuiltinScene, CamerasStandInsideTheSceneAndLookSomewhere) {
  const Scene& scene = builtScene(GetParam());
  // Slightly more than the geometry; an axis along which the scene is flat (the analytic planes)
  // gets room for a camera to stand back: half the scene's largest extent either side.
  Bounds bounds = scene.worldBounds();
  const glm::vec3 extent = bounds.extent();
  const float largest = std::max({extent.x, extent.y, extent.z});
  for (int axis = 0; axis < 3; ++axis) {
    const float margin = extent[axis] < 0.01f * largest ? 0.5f * largest : 0.05f * glm::length(extent);
    bounds.min[axis] -= margin;
    bounds.max[axis] += margin;
  }
  for (const Camera& c : scene.cameras) {
    EXPECT_TRUE(glm::all(glm::greaterThanEqual(c.eye, bounds.min)) &&
                glm::all(glm::lessThanEqual(c.eye, bounds.max)))
        << c.name;
    const glm::vec3 forward = c.target - c.eye;
    EXPECT_GT(glm::length(forward), 1e-3f) << c.name;
    EXPECT_GT(glm::length(glm::cross(glm::normalize(forward), glm::normalize(c.up))), 1e-3f) << c.name;
    EXPECT_TRUE(c.yfov > 0.1f && c.yfov < glm::pi<float>()) << c.name;
  }
}

TEST_P(EveryBuiltinScene, IsTheSameEveryTime) {
  const Scene& first = builtScene(GetParam());
  const Scene second = *makeBuiltinScene(GetParam());
  ASSERT_EQ(first.vertices.size(), second.vertices.size());
  EXPECT_EQ(
      0, std::memcmp(first.vertices.data(), second.vertices.data(), first.vertices.size() * sizeof(Vertex)));
  EXPECT_EQ(first.indices, second.indices);
  ASSERT_EQ(first.lights.size(), second.lights.size());
  for (size_t i = 0; i < first.lights.size(); ++i) {
    EXPECT_EQ(first.lights[i].position, second.lights[i].position);
    EXPECT_EQ(first.lights[i].color, second.lights[i].color);
  }
}

INSTANTIATE_TEST_SUITE_P(BuiltinScenes, EveryBuiltinScene, ::testing::ValuesIn(builtinNames()),
                         [](const ::testing::TestParamInfo<std::string>& info) {
                           std::string name = info.param;
                           std::replace(name.begin(), name.end(), '-', '_');
                           return name;
                         });

// ---- the list ----

TEST(BuiltinScenes, ListsTheDefaultFirstAndEveryNameOnce) {
  const std::vector<std::string> names = builtinNames();
  ASSERT_FALSE(names.empty());
  EXPECT_EQ(names.front(), kDefaultSceneName);
  EXPECT_EQ(std::set<std::string>(names.begin(), names.end()).size(), names.size());
  for (const char* expected : {"atrium", "threel16", "threel256", "plane", "spot-plane"}) {
    EXPECT_NE(std::find(names.begin(), names.end(), expected), names.end()) << expected;
  }
  for (const BuiltinSceneInfo& info : builtinScenes()) EXPECT_FALSE(info.description.empty()) << info.name;
}

// The shadowed-spots benchmark's scene: the atrium's lights where they were, every one a spot, the
// former point lights shining straight down with their colours, ranges and intensities.
TEST(BuiltinScenes, AtriumSpotsIsTheAtriumLitBySpotsOnly) {
  const Scene& atrium = builtScene("atrium");
  const Scene& spots = builtScene("atrium-spots");
  EXPECT_EQ(spots.vertices.size(), atrium.vertices.size());
  ASSERT_EQ(spots.lights.size(), atrium.lights.size());
  for (size_t i = 0; i < spots.lights.size(); ++i) {
    const Light& a = atrium.lights[i];
    const Light& s = spots.lights[i];
    ASSERT_EQ(s.type, LightType::Spot) << i;
    EXPECT_EQ(s.position, a.position) << i;
    EXPECT_EQ(s.color, a.color) << i;
    EXPECT_EQ(s.range, a.range) << i;
    EXPECT_EQ(s.intensity, a.intensity) << i;
    if (a.type == LightType::Point) {
      EXPECT_EQ(s.direction, glm::vec3(0.0f, -1.0f, 0.0f)) << i;
      EXPECT_LT(s.innerConeAngle, s.outerConeAngle) << i;
      EXPECT_LE(s.outerConeAngle, glm::radians(60.0f)) << i << ": one shadow view, not a cube";
    } else {
      EXPECT_EQ(s.direction, a.direction) << i;
    }
  }
}

TEST(BuiltinScenes, UnknownNamesGiveNothing) {
  EXPECT_FALSE(makeBuiltinScene("").has_value());
  EXPECT_FALSE(makeBuiltinScene("sponza").has_value());
  EXPECT_FALSE(makeBuiltinScene("Atrium").has_value());
  EXPECT_FALSE(makeBuiltinScene("threel17").has_value());
}

// ---- the atrium ----

TEST(Atrium, HasAboutAHundredColouredPointLightsAndGallerySpots) {
  const Scene& scene = builtScene("atrium");
  const size_t points = countLights(scene, LightType::Point), spots = countLights(scene, LightType::Spot);
  EXPECT_GE(points, 90u);
  EXPECT_LE(points, 120u);
  EXPECT_GE(spots, 4u);
  const Bounds bounds = scene.worldBounds();
  for (const Light& l : scene.lights) {
    EXPECT_TRUE(glm::all(glm::greaterThan(l.position, bounds.min)) &&
                glm::all(glm::lessThan(l.position, bounds.max)));
    // Saturated: the weakest channel well under the strongest.
    const float top = std::max({l.color.r, l.color.g, l.color.b});
    const float bottom = std::min({l.color.r, l.color.g, l.color.b});
    if (l.type == LightType::Point) {
      EXPECT_TRUE(l.range >= 2.0f && l.range <= 6.0f) << l.range;
      EXPECT_LT(bottom, 0.5f * top);
    } else {
      EXPECT_TRUE(l.range >= 10.0f && l.range <= 15.0f) << l.range;
      EXPECT_LT(l.direction.y, -0.3f);  // pointing down from the gallery
      EXPECT_TRUE(l.outerConeAngle >= glm::radians(30.0f) && l.outerConeAngle <= glm::radians(40.0f));
    }
  }
}

TEST(Atrium, HasGlassMetalAndClothMaterials) {
  const Scene& scene = builtScene("atrium");
  int glass = 0, metal = 0, cloth = 0;
  for (const Material& m : scene.materials) {
    if (m.alphaMode == AlphaMode::Blend) {
      ++glass;
      EXPECT_TRUE(m.baseColorFactor.a > 0.2f && m.baseColorFactor.a < 0.45f) << m.name;
      EXPECT_LE(m.roughness, 0.1f) << m.name;
    }
    if (m.metallic == 1.0f) ++metal;
    if (m.name.find("cloth") != std::string::npos) {
      ++cloth;
      EXPECT_NEAR(m.roughness, 0.8f, 0.1f) << m.name;
    }
  }
  EXPECT_GE(glass, 1);
  EXPECT_GE(metal, 1);
  EXPECT_GE(cloth, 3);
  // The glass is used by some primitive, not only declared.
  bool glassDrawn = false;
  for (const Instance& instance : scene.instances) {
    for (const Primitive& p : scene.meshes[instance.mesh].primitives) {
      glassDrawn |= scene.materials[p.material].alphaMode == AlphaMode::Blend;
    }
  }
  EXPECT_TRUE(glassDrawn);
}

TEST(Atrium, IsCourtyardSizedWithAModestTriangleCount) {
  const Scene& scene = builtScene("atrium");
  EXPECT_GE(scene.triangleCount(), 50000u);
  EXPECT_LE(scene.triangleCount(), 200000u);
  const glm::vec3 extent = scene.worldBounds().extent();
  EXPECT_GT(extent.x, 30.0f);
  EXPECT_GT(extent.z, 14.0f);
  EXPECT_TRUE(extent.y > 8.0f && extent.y < 20.0f) << extent.y;  // two storeys
  EXPECT_NEAR(scene.worldBounds().min.y, 0.0f, 1e-4f);           // standing on y = 0
}

TEST(Atrium, NamesItsCamerasOverviewFirst) {
  const Scene& scene = builtScene("atrium");
  std::vector<std::string> names;
  for (const Camera& c : scene.cameras) names.push_back(c.name);
  ASSERT_GE(names.size(), 4u);
  EXPECT_EQ(names[0], "overview");
  for (const char* expected : {"gallery", "floor", "top"}) {
    EXPECT_NE(std::find(names.begin(), names.end(), expected), names.end()) << expected;
  }
  for (const Camera& c : scene.cameras) {
    EXPECT_TRUE(c.yfov >= glm::radians(60.0f) && c.yfov <= glm::radians(70.0f)) << c.name;
  }
  const Camera& overview = scene.cameras[0];
  EXPECT_TRUE(overview.eye.y >= 1.7f && overview.eye.y <= 3.0f);
}

TEST(Atrium, SmokeSourceIsOnTheCourtyardFloorInViewOfTheOverview) {
  const Scene& scene = builtScene("atrium");
  ASSERT_TRUE(scene.smokeSource.has_value());
  const glm::vec3 smoke = *scene.smokeSource;
  EXPECT_LT(std::abs(smoke.x), 5.0f);
  EXPECT_LT(std::abs(smoke.z), 3.0f);
  EXPECT_TRUE(smoke.y >= 0.0f && smoke.y < 0.2f) << smoke.y;
  // Inside the overview's frustum (16:9, the widest aspect we render at is wider still) ...
  const Camera& c = scene.cameras[0];
  const glm::mat4 view = glm::lookAt(c.eye, c.target, c.up);
  const glm::vec3 p = glm::vec3(view * glm::vec4(smoke, 1.0f));
  ASSERT_LT(p.z, 0.0f);
  const float tanHalf = std::tan(0.5f * c.yfov);
  EXPECT_LT(std::abs(p.y / -p.z), tanHalf);
  EXPECT_LT(std::abs(p.x / -p.z), tanHalf * 16.0f / 9.0f);
  // ... and nothing opaque in between (the point sits 2 cm above the floor medallion).
  EXPECT_FALSE(occluded(scene, c.eye, smoke + glm::vec3(0, 0.01f, 0)));
}

// ---- ThreeL ----

void expectThreeL(const std::string& name, size_t count) {
  const Scene& scene = builtScene(name);
  ASSERT_EQ(scene.lights.size(), count);
  EXPECT_FALSE(scene.smokeSource.has_value());
  const Scene& atrium = builtScene("atrium");
  EXPECT_EQ(scene.triangleCount(), atrium.triangleCount());  // the same geometry
  const Bounds bounds = scene.worldBounds();
  std::set<std::tuple<float, float, float>> colours;
  float total = 0.0f;
  for (size_t i = 0; i < count; ++i) {
    const Light& l = scene.lights[i];
    EXPECT_EQ(l.type, LightType::Point);
    for (const glm::vec3& corner : corners(bounds)) {
      ASSERT_GT(l.range, glm::distance(l.position, corner)) << "light " << i;
    }
    // Inside the courtyard: between the column lines, above the floor, below the roof.
    EXPECT_TRUE(std::abs(l.position.x) < 15.0f && std::abs(l.position.z) < 7.0f) << "light " << i;
    EXPECT_TRUE(l.position.y > 0.5f && l.position.y < 12.0f) << "light " << i;
    // Hue i / count at full saturation and value: the channels span exactly 0..1.
    EXPECT_NEAR(std::max({l.color.r, l.color.g, l.color.b}), 1.0f, 1e-4f);
    EXPECT_NEAR(std::min({l.color.r, l.color.g, l.color.b}), 0.0f, 1e-4f);
    colours.insert({l.color.r, l.color.g, l.color.b});
    total += l.intensity;
  }
  EXPECT_EQ(colours.size(), count);
  EXPECT_EQ(scene.lights[0].color, glm::vec3(1.0f, 0.0f, 0.0f));  // hue 0 is red
  // The sum does not grow with the count: every ThreeL variant is as bright as the others.
  EXPECT_TRUE(total > 50.0f && total < 400.0f) << total;
}

TEST(ThreeL, SixteenLightsReachEveryCorner) {
  expectThreeL("threel16", 16);
}
TEST(ThreeL, TwoHundredFiftySixLightsReachEveryCorner) {
  expectThreeL("threel256", 256);
}

// ---- the analytic planes ----

void expectPlane(const Scene& scene) {
  ASSERT_EQ(scene.triangleCount(), 2u);
  ASSERT_EQ(scene.materials.size(), 1u);
  const Material& m = scene.materials[0];
  EXPECT_EQ(m.baseColorFactor, glm::vec4(0.8f, 0.8f, 0.8f, 1.0f));
  EXPECT_EQ(m.metallic, 0.0f);
  EXPECT_EQ(m.roughness, 1.0f);
  EXPECT_EQ(m.alphaMode, AlphaMode::Opaque);
  EXPECT_EQ(m.baseColorTexture, -1);
  const Bounds b = scene.worldBounds();
  EXPECT_EQ(b.min, glm::vec3(-20.0f, 0.0f, -20.0f));
  EXPECT_EQ(b.max, glm::vec3(20.0f, 0.0f, 20.0f));
  for (const Vertex& v : scene.vertices) EXPECT_EQ(v.normal, glm::vec3(0.0f, 1.0f, 0.0f));
  ASSERT_EQ(scene.cameras.size(), 1u);
  const Camera& c = scene.cameras[0];
  EXPECT_EQ(c.name, "top");
  EXPECT_EQ(c.eye, glm::vec3(0.0f, 8.0f, 0.001f));
  EXPECT_EQ(c.target, glm::vec3(0.0f));
  EXPECT_EQ(c.up, glm::vec3(0.0f, 0.0f, -1.0f));
  EXPECT_NEAR(c.yfov, glm::radians(90.0f), 1e-6f);
  ASSERT_EQ(scene.lights.size(), 1u);
}

TEST(AnalyticPlanes, PointLightTwoMetresAbove) {
  const Scene& scene = builtScene("plane");
  expectPlane(scene);
  const Light& l = scene.lights[0];
  EXPECT_EQ(l.type, LightType::Point);
  EXPECT_EQ(l.position, glm::vec3(0.0f, 2.0f, 0.0f));
  EXPECT_EQ(l.color, glm::vec3(1.0f));
  EXPECT_EQ(l.intensity, 10.0f);
  EXPECT_EQ(l.range, 6.0f);
}

TEST(AnalyticPlanes, SpotLightPointingStraightDown) {
  const Scene& scene = builtScene("spot-plane");
  expectPlane(scene);
  const Light& l = scene.lights[0];
  EXPECT_EQ(l.type, LightType::Spot);
  EXPECT_EQ(l.position, glm::vec3(0.0f, 3.0f, 0.0f));
  EXPECT_EQ(l.direction, glm::vec3(0.0f, -1.0f, 0.0f));
  EXPECT_EQ(l.intensity, 50.0f);
  EXPECT_EQ(l.range, 8.0f);
  EXPECT_NEAR(l.innerConeAngle, glm::radians(20.0f), 1e-6f);
  EXPECT_NEAR(l.outerConeAngle, glm::radians(30.0f), 1e-6f);
}

// ---- the mesh builder ----

// Builds one shape into a scene of its own with material `material`.
template <typename AddShape>
Scene shapeScene(AddShape addShape, uint32_t materials = 1) {
  Scene scene;
  scene.materials.resize(materials);
  MeshBuilder builder("shape");
  addShape(builder);
  addInstance(scene, builder.addTo(scene));
  return scene;
}

// For a convex solid around `centre`: every face normal points away from it.
void expectOutwardFaces(const Scene& scene, const glm::vec3& centre) {
  ASSERT_GT(scene.indices.size(), 0u);
  EXPECT_GE(fractionWoundWithNormals(scene), 1.0);
  const Primitive& p = scene.meshes[0].primitives[0];
  for (uint32_t i = 0; i < p.indexCount; i += 3) {
    const glm::vec3 a = scene.vertices[p.vertexOffset + scene.indices[p.firstIndex + i]].position;
    const glm::vec3 b = scene.vertices[p.vertexOffset + scene.indices[p.firstIndex + i + 1]].position;
    const glm::vec3 c = scene.vertices[p.vertexOffset + scene.indices[p.firstIndex + i + 2]].position;
    ASSERT_GT(glm::dot(glm::cross(b - a, c - a), (a + b + c) / 3.0f - centre), 0.0f) << "triangle " << i / 3;
  }
}

TEST(MeshBuilder, BoxHasTwelveOutwardTriangles) {
  const glm::mat4 t = glm::translate(glm::mat4(1.0f), glm::vec3(1, 2, 3));
  const Scene scene = shapeScene([&](MeshBuilder& b) { b.addBox(t, glm::vec3(2, 1, 0.5f)); });
  EXPECT_EQ(scene.triangleCount(), 12u);
  expectOutwardFaces(scene, glm::vec3(1, 2, 3));
  EXPECT_EQ(scene.worldBounds().min, glm::vec3(0.0f, 1.5f, 2.75f));
  EXPECT_EQ(scene.worldBounds().max, glm::vec3(2.0f, 2.5f, 3.25f));
}

TEST(MeshBuilder, MirroredBoxStaysOutward) {
  const glm::mat4 mirror = glm::scale(glm::mat4(1.0f), glm::vec3(-1, 1, 1));
  const Scene scene = shapeScene([&](MeshBuilder& b) { b.addBox(mirror, glm::vec3(1)); });
  expectOutwardFaces(scene, glm::vec3(0));
}

TEST(MeshBuilder, SphereAndCylinderAreClosedAndOutward) {
  const Scene sphere = shapeScene([](MeshBuilder& b) { b.addSphere(glm::mat4(1.0f), 0.5f, 16, 8); });
  expectOutwardFaces(sphere, glm::vec3(0));
  for (const Vertex& v : sphere.vertices) EXPECT_NEAR(glm::length(v.position), 0.5f, 1e-5f);
  const Scene cylinder = shapeScene([](MeshBuilder& b) { b.addCylinder(glm::mat4(1.0f), 0.5f, 2.0f, 16); });
  expectOutwardFaces(cylinder, glm::vec3(0, 1, 0));
  EXPECT_EQ(cylinder.triangleCount(), 16u * 2 + 16u * 2);  // the side and two caps
}

TEST(MeshBuilder, FlippedWindingIsCaught) {
  Scene scene = shapeScene([](MeshBuilder& b) { b.addSphere(glm::mat4(1.0f), 1.0f, 12, 6); });
  for (size_t i = 0; i + 2 < scene.indices.size(); i += 3)
    std::swap(scene.indices[i + 1], scene.indices[i + 2]);
  EXPECT_LT(fractionWoundWithNormals(scene), 0.01);
}

TEST(MeshBuilder, OnePrimitivePerMaterialWithLocalIndices) {
  Scene scene;
  scene.materials.resize(3);
  scene.vertices.resize(5);  // geometry already there: the new primitives must start after it
  MeshBuilder b("parts");
  b.setMaterial(2);
  b.addBox(glm::mat4(1.0f), glm::vec3(1));
  b.setMaterial(0);
  b.addQuad(glm::mat4(1.0f), glm::vec2(1));
  b.setMaterial(2);
  b.addBox(glm::translate(glm::mat4(1.0f), glm::vec3(3, 0, 0)), glm::vec3(1));
  const uint32_t mesh = b.addTo(scene);
  EXPECT_TRUE(b.empty());
  ASSERT_EQ(scene.meshes[mesh].primitives.size(), 2u);
  for (const Primitive& p : scene.meshes[mesh].primitives) {
    EXPECT_GE(p.vertexOffset, 5u);
    EXPECT_EQ(p.indexCount, p.material == 2 ? 72u : 6u);
  }
}

TEST(MeshBuilder, ArchedWallLeavesItsOpeningEmpty) {
  ArchedWallShape shape;
  shape.width = 4.0f;
  shape.height = 5.0f;
  shape.thickness = 0.5f;
  shape.archRadius = 1.2f;
  shape.springHeight = 2.0f;
  const Scene scene = shapeScene([&](MeshBuilder& b) { b.addArchedWall(glm::mat4(1.0f), shape, 16); });
  EXPECT_GE(fractionWoundWithNormals(scene), 1.0);
  // A ray straight through the opening (below the spring and under the crown) meets nothing;
  // one beside it, through the pier, meets the wall.
  EXPECT_FALSE(occluded(scene, {0.0f, 1.0f, -1.0f}, {0.0f, 1.0f, 1.0f}));
  EXPECT_FALSE(occluded(scene, {0.5f, 2.9f, -1.0f}, {0.5f, 2.9f, 1.0f}));
  EXPECT_TRUE(occluded(scene, {1.6f, 1.0f, -1.0f}, {1.6f, 1.0f, 1.0f}));
  EXPECT_TRUE(occluded(scene, {0.0f, 3.4f, -1.0f}, {0.0f, 3.4f, 1.0f}));
}

TEST(MeshBuilder, BannerHangsDownFromItsRodAndIsSeenFromBothSides) {
  BannerShape shape;
  shape.width = 1.0f;
  shape.length = 3.0f;
  shape.tail = 0.4f;
  const Scene scene = shapeScene([&](MeshBuilder& b) { b.addBanner(glm::mat4(1.0f), shape); });
  EXPECT_GE(fractionWoundWithNormals(scene), 1.0);
  const Bounds bounds = scene.worldBounds();
  EXPECT_NEAR(bounds.max.y, 0.0f, 0.02f);
  EXPECT_NEAR(bounds.min.y, -3.0f, 0.02f);
  EXPECT_NEAR(bounds.extent().x, 1.0f, 0.02f);
  int front = 0, back = 0;
  for (const Vertex& v : scene.vertices) (v.normal.z > 0 ? front : back)++;
  EXPECT_EQ(front, back);
}

}  // namespace
}  // namespace lll
