// glTF loader tests: small files written per test with known contents, and the four shared scenes
// (broken input: test_gltf_broken_input.cpp; extensions, further attributes, samplers, posed meshes
// and compressed files: test_gltf_extensions.cpp).
#include "gltf_test_support.h"

namespace lll {
namespace {

using namespace gltf_test;  // the files' builder and checks (gltf_test_support.h)

TEST_F(GltfLoaderTest, LoadsQuadGeometry) {
  const Scene scene = loadGltf(quadScene().writeGltf(dir_, "quad"));
  EXPECT_EQ(scene.name, "quad");
  ASSERT_EQ(scene.vertices.size(), 4u);
  expectVec3Near(scene.vertices[2].position, {1, 1, 0});
  expectVec3Near(scene.vertices[3].position, {0, 1, 0});
  expectVec3Near(scene.vertices[1].normal, {0, 0, 1});
  EXPECT_EQ(scene.vertices[2].uv, glm::vec2(1, 1));
  EXPECT_EQ(scene.indices, (std::vector<uint32_t>{0, 1, 2, 0, 2, 3}));
  ASSERT_EQ(scene.meshes.size(), 1u);
  EXPECT_EQ(scene.meshes[0].name, "quad");
  ASSERT_EQ(scene.meshes[0].primitives.size(), 1u);
  EXPECT_EQ(scene.meshes[0].primitives[0].indexCount, 6u);
  ASSERT_EQ(scene.instances.size(), 1u);
  expectMat4Near(scene.instances[0].transform, glm::mat4(1.0f));
  ASSERT_EQ(scene.materials.size(), 1u);
  EXPECT_EQ(scene.materials[0].name, "Painted");
}

// TANGENT (xyz and the bitangent's handedness w) reaches the vertices; without it w is 0, which
// tells the shaders to build the frame from derivatives; a w that is not +-1 is an error.
TEST_F(GltfLoaderTest, TangentsAreReadAndChecked) {
  EXPECT_EQ(loadGltf(quadScene().writeGltf(dir_, "plain")).vertices[0].tangent, glm::vec4(0.0f));
  GltfBuilder b = quadScene();
  const int tangent =
      b.addAccessor<float>({1, 0, 0, 1, 1, 0, 0, 1, 0, 1, 0, -1, 0, 1, 0, -1}, kFloat, "VEC4");
  b.doc["meshes"][0]["primitives"][0]["attributes"]["TANGENT"] = tangent;
  const Scene scene = loadGltf(b.writeGltf(dir_, "tangents"));
  ASSERT_EQ(scene.vertices.size(), 4u);
  EXPECT_EQ(scene.vertices[1].tangent, glm::vec4(1, 0, 0, 1));
  EXPECT_EQ(scene.vertices[3].tangent, glm::vec4(0, 1, 0, -1));
  const size_t w = b.accessorByteOffset[size_t(tangent)] + 3 * sizeof(float);
  const float half = 0.5f;
  std::memcpy(b.bin.data() + w, &half, sizeof(half));
  expectInputError(b.writeGltf(dir_, "bad-tangent"), "TANGENT 0");
}

TEST_F(GltfLoaderTest, SecondPrimitiveIndicesAreRelativeToItsFirstVertex) {
  GltfBuilder b = quadScene();
  const int position = b.addPositions({5, 0, 0, 6, 0, 0, 5, 1, 0});
  const int indices = b.addAccessor<uint32_t>({2, 1, 0}, kUnsignedInt, "SCALAR");
  b.doc["meshes"][0]["primitives"].push_back(
      {{"attributes", {{"POSITION", position}}}, {"indices", indices}});
  const Scene scene = loadGltf(b.writeGltf(dir_, "two"));
  ASSERT_EQ(scene.meshes[0].primitives.size(), 2u);
  const Primitive& second = scene.meshes[0].primitives[1];
  EXPECT_EQ(second.firstIndex, 6u);
  EXPECT_EQ(second.indexCount, 3u);
  EXPECT_EQ(second.vertexOffset, 4u);
  // No normals: flat shading gives the triangle its own three vertices, in triangle order.
  EXPECT_EQ(std::vector<uint32_t>(scene.indices.begin() + 6, scene.indices.end()),
            (std::vector<uint32_t>{0, 1, 2}));
  expectVec3Near(scene.vertices[second.vertexOffset].position, {5, 1, 0});
  expectVec3Near(scene.vertices[second.vertexOffset].normal, {0, 0, -1});  // (2,1,0) winds clockwise
  EXPECT_EQ(scene.vertices[second.vertexOffset].uv, glm::vec2(0, 0));      // no TEXCOORD_0
}

TEST_F(GltfLoaderTest, MaterialFactors) {
  GltfBuilder b = quadScene();
  b.doc["materials"][0] = {
      {"name", "Glow"},
      {"pbrMetallicRoughness",
       {{"baseColorFactor", {0.5, 0.25, 1.0, 0.75}}, {"metallicFactor", 0.2}, {"roughnessFactor", 0.7}}},
      {"emissiveFactor", {1.0, 0.5, 0.0}},
      {"extensions", {{"KHR_materials_emissive_strength", {{"emissiveStrength", 4.0}}}}},
      {"alphaMode", "MASK"},
      {"alphaCutoff", 0.3},
      {"doubleSided", true}};
  b.doc["materials"].push_back({{"alphaMode", "BLEND"}});
  b.doc["extensionsUsed"] = {"KHR_materials_emissive_strength"};
  const Scene scene = loadGltf(b.writeGltf(dir_, "materials"));
  ASSERT_EQ(scene.materials.size(), 2u);
  const Material& glow = scene.materials[0];
  EXPECT_EQ(glow.name, "Glow");
  EXPECT_EQ(glow.baseColorFactor, glm::vec4(0.5f, 0.25f, 1.0f, 0.75f));
  EXPECT_FLOAT_EQ(glow.metallic, 0.2f);
  EXPECT_FLOAT_EQ(glow.roughness, 0.7f);
  EXPECT_EQ(glow.emissiveFactor, glm::vec3(1.0f, 0.5f, 0.0f));
  EXPECT_FLOAT_EQ(glow.emissiveStrength, 4.0f);
  EXPECT_EQ(glow.alphaMode, AlphaMode::Mask);
  EXPECT_FLOAT_EQ(glow.alphaCutoff, 0.3f);
  EXPECT_TRUE(glow.doubleSided);
  EXPECT_EQ(glow.baseColorTexture, -1);
  EXPECT_EQ(scene.materials[1].alphaMode, AlphaMode::Blend);
  EXPECT_FALSE(scene.materials[1].doubleSided);
  EXPECT_FLOAT_EQ(scene.materials[1].metallic, 1.0f);  // glTF default
}

TEST_F(GltfLoaderTest, PrimitivesWithoutMaterialShareOneDefaultMaterial) {
  GltfBuilder b = quadScene();
  b.doc["meshes"][0]["primitives"][0].erase("material");
  b.doc["meshes"][0]["primitives"].push_back(b.doc["meshes"][0]["primitives"][0]);
  const Scene scene = loadGltf(b.writeGltf(dir_, "nomaterial"));
  ASSERT_EQ(scene.materials.size(), 2u);  // "Painted", unused, then the default
  const auto& primitives = scene.meshes[0].primitives;
  ASSERT_EQ(primitives.size(), 2u);
  EXPECT_EQ(primitives[0].material, 1u);
  EXPECT_EQ(primitives[1].material, 1u);
  EXPECT_EQ(scene.materials[1].baseColorFactor, glm::vec4(1.0f));
  EXPECT_FLOAT_EQ(scene.materials[1].metallic, 1.0f);
  EXPECT_FLOAT_EQ(scene.materials[1].roughness, 1.0f);
}

TEST_F(GltfLoaderTest, NodeHierarchyGivesWorldTransforms) {
  GltfBuilder b = quadScene();
  b.doc["nodes"] =
      json::array({{{"translation", {1, 2, 3}}, {"children", {1, 2}}},
                   {{"scale", {2, 2, 2}}, {"mesh", 0}},
                   // column-major: translation (0, 0, 10) in the last column
                   {{"matrix", {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 10, 1}}, {"children", {3}}},
                   {{"rotation", {0, 0, 0.7071068, 0.7071068}}, {"mesh", 0}}});
  const Scene scene = loadGltf(b.writeGltf(dir_, "hierarchy"));
  ASSERT_EQ(scene.instances.size(), 2u);
  const glm::mat4 parent = glm::translate(glm::mat4(1.0f), glm::vec3(1, 2, 3));
  expectMat4Near(scene.instances[0].transform, glm::scale(parent, glm::vec3(2.0f)));
  expectVec3Near(glm::vec3(scene.instances[0].transform * glm::vec4(1, 1, 0, 1)), {3, 4, 3});
  // 90 degrees about z maps x to y, below a translation of (1, 2, 13).
  expectVec3Near(glm::vec3(scene.instances[1].transform * glm::vec4(1, 0, 0, 1)), {1, 3, 13});
}

// glTF: where a node's world transform mirrors (negative determinant) its mesh's fronts wind
// clockwise. The renderer's fronts are counter-clockwise after the transform, so such a node must
// be placed with the mesh's triangles reversed: every instance's triangles then face the way its
// normals do in the world (the geometric normal of the transformed winding along the transformed
// vertex normal), as they do for the unmirrored node. Two mirroring nodes share one reversed copy.
TEST_F(GltfLoaderTest, MirroringNodesKeepTheirFrontFaces) {
  GltfBuilder b = quadScene();
  b.doc["nodes"] = json::array({{{"mesh", 0}},
                                {{"scale", {-1, 1, 1}}, {"mesh", 0}},
                                {{"scale", {-1, -1, 1}}, {"mesh", 0}},  // a half turn: no mirror
                                {{"scale", {1, 1, -2}}, {"children", {4}}},
                                {{"rotation", {0, 0.7071068, 0, 0.7071068}}, {"mesh", 0}},
                                {{"scale", {-1, 1, 1}}, {"children", {6}}},
                                {{"scale", {1, -1, 1}}, {"mesh", 0}}});  // mirrored twice: none
  b.setScene({0, 1, 2, 3, 5});
  const Scene scene = loadGltf(b.writeGltf(dir_, "mirrored"));
  ASSERT_EQ(scene.instances.size(), 5u);
  ASSERT_EQ(scene.meshes.size(), 2u);  // the quad and its reversed copy, shared
  const bool mirrored[5] = {false, true, false, true, false};
  for (size_t i = 0; i < scene.instances.size(); ++i) {
    const Instance& instance = scene.instances[i];
    EXPECT_EQ(instance.mesh, mirrored[i] ? 1u : 0u) << "instance " << i;
    EXPECT_EQ(glm::determinant(glm::mat3(instance.transform)) < 0.0f, mirrored[i]) << "instance " << i;
    const Primitive& p = scene.meshes[instance.mesh].primitives.at(0);
    ASSERT_EQ(p.indexCount, 6u);
    const glm::mat3 normalMatrix = glm::transpose(glm::inverse(glm::mat3(instance.transform)));
    for (uint32_t t = 0; t < p.indexCount; t += 3) {
      glm::vec3 corner[3], normal(0.0f);
      for (uint32_t k = 0; k < 3; ++k) {
        const Vertex& v = scene.vertices[p.vertexOffset + scene.indices[p.firstIndex + t + k]];
        corner[k] = glm::vec3(instance.transform * glm::vec4(v.position, 1.0f));
        normal += normalMatrix * v.normal;
      }
      const glm::vec3 front = glm::cross(corner[1] - corner[0], corner[2] - corner[0]);
      EXPECT_GT(glm::dot(glm::normalize(front), glm::normalize(normal)), 0.99f)
          << "instance " << i << " triangle " << t / 3;
    }
  }
  // The copy's triangles are the quad's, each with its last two corners swapped.
  const Primitive& reversed = scene.meshes[1].primitives[0];
  EXPECT_EQ(std::vector<uint32_t>(scene.indices.begin() + reversed.firstIndex,
                                  scene.indices.begin() + reversed.firstIndex + reversed.indexCount),
            (std::vector<uint32_t>{0, 2, 1, 0, 3, 2}));
  EXPECT_EQ(reversed.vertexOffset, scene.meshes[0].primitives[0].vertexOffset);
  EXPECT_EQ(reversed.material, scene.meshes[0].primitives[0].material);
}

TEST_F(GltfLoaderTest, UsesTheDefaultSceneOnly) {
  GltfBuilder b = quadScene();
  b.addNode({{"mesh", 0}, {"translation", {0, 7, 0}}});
  b.doc["scenes"] = json::array({{{"nodes", {0}}}, {{"nodes", {1}}}});
  b.doc["scene"] = 1;
  const Scene scene = loadGltf(b.writeGltf(dir_, "scenes"));
  ASSERT_EQ(scene.instances.size(), 1u);
  EXPECT_FLOAT_EQ(scene.instances[0].transform[3].y, 7.0f);
}

TEST_F(GltfLoaderTest, NoScenesMeansAllRootNodes) {
  GltfBuilder b = quadScene();
  b.doc.erase("scenes");
  b.doc.erase("scene");
  b.doc["nodes"] = json::array({{{"mesh", 0}, {"children", {2}}}, {{"mesh", 0}}, {{"mesh", 0}}});
  const Scene scene = loadGltf(b.writeGltf(dir_, "noscenes"));
  EXPECT_EQ(scene.instances.size(), 3u);
}

TEST_F(GltfLoaderTest, PunctualLights) {
  GltfBuilder b = quadScene();
  b.doc["extensionsUsed"] = {"KHR_lights_punctual"};
  b.doc["extensions"]["KHR_lights_punctual"]["lights"] =
      json::array({{{"type", "point"}, {"color", {1.0, 0.5, 0.25}}, {"intensity", 10.0}, {"range", 5.0}},
                   {{"type", "spot"},
                    {"intensity", 20.0},
                    {"range", 8.0},
                    {"spot", {{"innerConeAngle", 0.2}, {"outerConeAngle", 0.6}}}},
                   {{"type", "point"}, {"intensity", 3.0}, {"color", {0.0, 1.0, 0.0}}},
                   {{"type", "directional"}, {"intensity", 5.0}, {"color", {1.0, 0.9, 0.8}}},
                   {{"type", "spot"}, {"spot", json::object()}}});
  auto light = [](int index) { return json{{"KHR_lights_punctual", {{"light", index}}}}; };
  const float s = std::sqrt(0.5f);
  b.doc["nodes"] =
      json::array({{{"translation", {10, 0, 0}}, {"children", {1}}},
                   {{"translation", {1, 2, 3}}, {"extensions", light(0)}},
                   // -90 degrees about x: the spot's -z turns to -y
                   {{"translation", {0, 5, 0}}, {"rotation", {-s, 0, 0, s}}, {"extensions", light(1)}},
                   {{"extensions", light(2)}},
                   // -90 degrees about x: the sun shines straight down
                   {{"rotation", {-s, 0, 0, s}}, {"extensions", light(3)}},
                   {{"extensions", light(4)}}});
  b.setScene({0, 2, 3, 4, 5});
  LoadReport report;
  const Scene scene = loadGltf(b.writeGltf(dir_, "lights"), &report);
  ASSERT_EQ(scene.lights.size(), 4u);

  const Light& point = scene.lights[0];
  EXPECT_EQ(point.type, LightType::Point);
  expectVec3Near(point.position, {11, 2, 3});
  EXPECT_EQ(point.color, glm::vec3(1.0f, 0.5f, 0.25f));
  EXPECT_FLOAT_EQ(point.intensity, 10.0f);
  EXPECT_FLOAT_EQ(point.range, 5.0f);

  const Light& spot = scene.lights[1];
  EXPECT_EQ(spot.type, LightType::Spot);
  expectVec3Near(spot.position, {0, 5, 0});
  expectVec3Near(spot.direction, {0, -1, 0});
  EXPECT_FLOAT_EQ(spot.range, 8.0f);
  EXPECT_FLOAT_EQ(spot.innerConeAngle, 0.2f);
  EXPECT_FLOAT_EQ(spot.outerConeAngle, 0.6f);

  const Light& unbounded = scene.lights[2];
  EXPECT_FLOAT_EQ(unbounded.range, rangeForUnboundedLight(3.0f, glm::vec3(0, 1, 0)));

  const Light& defaultSpot = scene.lights[3];  // glTF defaults: intensity 1, cone 0 .. pi/4
  EXPECT_FLOAT_EQ(defaultSpot.innerConeAngle, 0.0f);
  EXPECT_FLOAT_EQ(defaultSpot.outerConeAngle, 0.7853982f);
  EXPECT_FLOAT_EQ(defaultSpot.range, rangeForUnboundedLight(1.0f, glm::vec3(1.0f)));
  // The sun: lux as given, travelling along its node's -z, kept out of the punctual lights.
  ASSERT_EQ(scene.directionalLights.size(), 1u);
  const DirectionalLight& sun = scene.directionalLights[0];
  expectVec3Near(sun.direction, {0, -1, 0});
  EXPECT_FLOAT_EQ(sun.illuminance, 5.0f);
  EXPECT_EQ(sun.color, glm::vec3(1.0f, 0.9f, 0.8f));
  EXPECT_FALSE(anyWarningContains(report, "directional"));
}

TEST_F(GltfLoaderTest, PerspectiveCameras) {
  GltfBuilder b = quadScene();
  b.doc["cameras"] = json::array(
      {{{"name", "Main"}, {"type", "perspective"}, {"perspective", {{"yfov", 0.8}, {"znear", 0.1}}}},
       {{"type", "perspective"}, {"perspective", {{"yfov", 1.2}, {"znear", 0.1}}}}});
  const float s = std::sqrt(0.5f);
  b.addNode({{"camera", 0}, {"translation", {0, 1, 5}}});
  // 90 degrees about y: looks along -x.
  b.addNode({{"camera", 1}, {"rotation", {0, s, 0, s}}});
  b.setScene({0, 1, 2});
  const Scene scene = loadGltf(b.writeGltf(dir_, "cameras"));
  ASSERT_EQ(scene.cameras.size(), 2u);
  EXPECT_EQ(scene.cameras[0].name, "Main");
  expectVec3Near(scene.cameras[0].eye, {0, 1, 5});
  expectVec3Near(scene.cameras[0].target, {0, 1, 4});
  expectVec3Near(scene.cameras[0].up, {0, 1, 0});
  EXPECT_FLOAT_EQ(scene.cameras[0].yfov, 0.8f);
  EXPECT_EQ(scene.cameras[1].name, "gltf-camera-1");
  expectVec3Near(scene.cameras[1].target, {-1, 0, 0});
  EXPECT_FLOAT_EQ(scene.cameras[1].yfov, 1.2f);
}

TEST_F(GltfLoaderTest, IndexTypesAndNormalizedTexcoords) {
  GltfBuilder b;
  const int position = b.addPositions({0, 0, 0, 1, 0, 0, 0, 1, 0});
  const int normal = b.addAccessor<float>({0, 0, 1, 0, 0, 1, 0, 0, 1}, kFloat, "VEC3");
  const int uvByte = b.addAccessor<uint8_t>({255, 0, 0, 255, 51, 102}, kUnsignedByte, "VEC2", true);
  const int uvShort = b.addAccessor<uint16_t>({65535, 0, 0, 65535, 0, 0}, kUnsignedShort, "VEC2", true);
  const int bytes = b.addAccessor<uint8_t>({2, 1, 0}, kUnsignedByte, "SCALAR");
  const int words = b.addAccessor<uint32_t>({1, 2, 0}, kUnsignedInt, "SCALAR");
  const json attributes = {{"POSITION", position}, {"NORMAL", normal}};
  json withByteUv = attributes;
  withByteUv["TEXCOORD_0"] = uvByte;
  json withShortUv = attributes;
  withShortUv["TEXCOORD_0"] = uvShort;
  b.addMesh(json::array({{{"attributes", withByteUv}, {"indices", bytes}},
                         {{"attributes", withShortUv}, {"indices", words}},
                         {{"attributes", attributes}}}));
  b.setScene({b.addNode({{"mesh", 0}})});
  const Scene scene = loadGltf(b.writeGltf(dir_, "types"));
  EXPECT_EQ(scene.indices, (std::vector<uint32_t>{2, 1, 0, 1, 2, 0, 0, 1, 2}));
  ASSERT_EQ(scene.vertices.size(), 9u);
  EXPECT_NEAR(scene.vertices[0].uv.x, 1.0f, 1e-6f);
  EXPECT_NEAR(scene.vertices[2].uv.x, 0.2f, 1e-6f);
  EXPECT_NEAR(scene.vertices[2].uv.y, 0.4f, 1e-6f);
  EXPECT_NEAR(scene.vertices[4].uv.y, 1.0f, 1e-6f);
}

TEST_F(GltfLoaderTest, StripsAndFansBecomeListsAndLinesAreSkipped) {
  GltfBuilder b;
  const int position = b.addPositions({0, 0, 0, 1, 0, 0, 0, 1, 0, 1, 1, 0});
  const int normal = b.addAccessor<float>({0, 0, 1, 0, 0, 1, 0, 0, 1, 0, 0, 1}, kFloat, "VEC3");
  const json attributes = {{"POSITION", position}, {"NORMAL", normal}};
  b.addMesh(json::array({{{"attributes", attributes}, {"mode", 5}},
                         {{"attributes", attributes}, {"mode", 6}},
                         {{"attributes", attributes}, {"mode", 1}},
                         {{"attributes", attributes}, {"mode", 0}}}));
  b.setScene({b.addNode({{"mesh", 0}})});
  LoadReport report;
  const Scene scene = loadGltf(b.writeGltf(dir_, "modes"), &report);
  ASSERT_EQ(scene.meshes[0].primitives.size(), 2u);
  EXPECT_EQ(scene.indices, (std::vector<uint32_t>{0, 1, 2, 2, 1, 3, 1, 2, 0, 2, 3, 0}));
  EXPECT_TRUE(anyWarningContains(report, "primitive 2", "lines"));
  EXPECT_TRUE(anyWarningContains(report, "primitive 3", "points"));
}

TEST_F(GltfLoaderTest, TexturesAreDecodedPerColourSpace) {
  GltfBuilder b = quadScene();
  writeBytes(dir_ / "checker.png", kPng2x2.data(), kPng2x2.size());
  b.doc["images"] = json::array({{{"uri", "checker.png"}}});
  b.doc["textures"] = json::array({{{"source", 0}}});
  b.doc["materials"][0]["pbrMetallicRoughness"] = {{"baseColorTexture", {{"index", 0}}},
                                                   {"metallicRoughnessTexture", {{"index", 0}}}};
  b.doc["materials"][0]["emissiveTexture"] = {{"index", 0}};
  b.doc["materials"][0]["normalTexture"] = {{"index", 0}, {"scale", 0.5}};
  b.doc["materials"][0]["occlusionTexture"] = {{"index", 0}, {"strength", 0.25}};
  const Scene scene = loadGltf(b.writeGltf(dir_, "textured"));
  ASSERT_EQ(scene.textures.size(), 2u);  // one image used as sRGB colour and as linear data
  const Material& m = scene.materials[0];
  ASSERT_GE(m.baseColorTexture, 0);
  ASSERT_GE(m.metallicRoughnessTexture, 0);
  EXPECT_EQ(m.emissiveTexture, m.baseColorTexture);
  EXPECT_EQ(m.normalTexture, m.metallicRoughnessTexture);
  EXPECT_EQ(m.occlusionTexture, m.metallicRoughnessTexture);
  EXPECT_NE(m.baseColorTexture, m.metallicRoughnessTexture);
  EXPECT_FLOAT_EQ(m.normalScale, 0.5f);
  EXPECT_FLOAT_EQ(m.occlusionStrength, 0.25f);
  const Texture& colour = scene.textures[size_t(m.baseColorTexture)];
  EXPECT_TRUE(colour.srgb);
  EXPECT_FALSE(scene.textures[size_t(m.metallicRoughnessTexture)].srgb);
  EXPECT_EQ(colour.width, 2u);
  EXPECT_EQ(colour.height, 2u);
  EXPECT_EQ(colour.rgba, kPng2x2Rgba);
}

TEST_F(GltfLoaderTest, MissingOrUndecodableImageWarnsAndLeavesNoTexture) {
  GltfBuilder b = quadScene();
  writeText(dir_ / "garbage.png", "this is not an image at all");
  b.doc["images"] = json::array({{{"uri", "missing.png"}}, {{"uri", "garbage.png"}}});
  b.doc["textures"] = json::array({{{"source", 0}}, {{"source", 1}}});
  b.doc["materials"][0]["pbrMetallicRoughness"] = {{"baseColorTexture", {{"index", 0}}}};
  b.doc["materials"][0]["normalTexture"] = {{"index", 1}};
  LoadReport report;
  const Scene scene = loadGltf(b.writeGltf(dir_, "missingtexture"), &report);
  EXPECT_EQ(scene.materials[0].baseColorTexture, -1);
  EXPECT_EQ(scene.materials[0].normalTexture, -1);
  EXPECT_TRUE(scene.textures.empty());
  EXPECT_TRUE(anyWarningContains(report, "missing.png", "Painted"));
  EXPECT_TRUE(anyWarningContains(report, "garbage.png", "Painted"));
  EXPECT_EQ(scene.vertices.size(), 4u);  // the rest of the file still loads
}

TEST_F(GltfLoaderTest, GlbMatchesGltfAndDecodesBufferViewImages) {
  GltfBuilder b = quadScene();
  const int view = b.addBufferView(kPng2x2.data(), kPng2x2.size());
  b.doc["images"] = json::array({{{"bufferView", view}, {"mimeType", "image/png"}}});
  b.doc["textures"] = json::array({{{"source", 0}}});
  b.doc["materials"][0]["pbrMetallicRoughness"] = {{"baseColorTexture", {{"index", 0}}},
                                                   {"baseColorFactor", {0.1, 0.2, 0.3, 1.0}}};
  const Scene fromGlb = loadGltf(b.writeGlb(dir_, "binary"));
  GltfBuilder text = quadScene();
  const Scene fromGltf = loadGltf(text.writeGltf(dir_, "text"));
  EXPECT_EQ(fromGlb.name, "binary");
  ASSERT_EQ(fromGlb.vertices.size(), fromGltf.vertices.size());
  for (size_t i = 0; i < fromGlb.vertices.size(); ++i) {
    EXPECT_EQ(fromGlb.vertices[i].position, fromGltf.vertices[i].position);
    EXPECT_EQ(fromGlb.vertices[i].normal, fromGltf.vertices[i].normal);
    EXPECT_EQ(fromGlb.vertices[i].uv, fromGltf.vertices[i].uv);
  }
  EXPECT_EQ(fromGlb.indices, fromGltf.indices);
  EXPECT_EQ(fromGlb.materials[0].baseColorFactor, glm::vec4(0.1f, 0.2f, 0.3f, 1.0f));
  ASSERT_EQ(fromGlb.materials[0].baseColorTexture, 0);
  EXPECT_EQ(fromGlb.textures[0].rgba, kPng2x2Rgba);
}

// The shared CC-BY scenes load whole and consistent.
struct AssetScene {
  const char* name;
  uint64_t triangles;  // from assets/README.md
};

class GltfAssetsTest : public ::testing::TestWithParam<AssetScene> {};

TEST_P(GltfAssetsTest, LoadsConsistently) {
  const std::string name = GetParam().name;
  const fs::path path = fs::path(LLL_ASSETS_DIR) / name / (name + ".gltf");
  LoadReport report;
  const Scene scene = loadGltf(path, &report);
  for (const std::string& warning : report.warnings) ADD_FAILURE() << "unexpected warning: " << warning;
  EXPECT_EQ(scene.name, name);
  ASSERT_FALSE(scene.vertices.empty());
  ASSERT_FALSE(scene.instances.empty());
  for (const Vertex& v : scene.vertices) {
    ASSERT_TRUE(std::isfinite(v.position.x) && std::isfinite(v.position.y) && std::isfinite(v.position.z));
  }
  for (const Mesh& mesh : scene.meshes) {
    for (const Primitive& p : mesh.primitives) {
      ASSERT_LE(uint64_t(p.firstIndex) + p.indexCount, scene.indices.size()) << mesh.name;
      ASSERT_LT(p.material, scene.materials.size()) << mesh.name;
      for (uint32_t i = p.firstIndex; i < p.firstIndex + p.indexCount; ++i) {
        ASSERT_LT(uint64_t(scene.indices[i]) + p.vertexOffset, scene.vertices.size()) << mesh.name;
      }
    }
  }
  uint64_t triangles = 0;
  for (const Instance& instance : scene.instances) {
    ASSERT_LT(instance.mesh, scene.meshes.size());
    for (const Primitive& p : scene.meshes[instance.mesh].primitives) triangles += p.indexCount / 3;
  }
  EXPECT_EQ(triangles, GetParam().triangles);
  std::ifstream file(path);
  EXPECT_EQ(scene.materials.size(), json::parse(file)["materials"].size());
}

INSTANTIATE_TEST_SUITE_P(GltfSharedScenes, GltfAssetsTest,
                         ::testing::Values(AssetScene{"camp", 6285}, AssetScene{"cave", 5894},
                                           AssetScene{"garage", 11358}, AssetScene{"space", 15861}),
                         [](const auto& info) { return std::string(info.param.name); });

TEST(GltfAssets, CaveHasABlendedMaterial) {
  const Scene scene = loadGltf(LLL_ASSETS_DIR "/cave/cave.gltf");
  EXPECT_TRUE(std::any_of(scene.materials.begin(), scene.materials.end(),
                          [](const Material& m) { return m.alphaMode == AlphaMode::Blend; }));
}

TEST(GltfAssets, CampHasItsCamera) {
  const Scene scene = loadGltf(LLL_ASSETS_DIR "/camp/camp.gltf");
  ASSERT_EQ(scene.cameras.size(), 1u);
  EXPECT_EQ(scene.cameras[0].name, "Camera.001");
  EXPECT_NEAR(scene.cameras[0].yfov, 0.50338f, 1e-4f);
  EXPECT_NEAR(glm::length(scene.cameras[0].target - scene.cameras[0].eye), 1.0f, 1e-4f);
}

}  // namespace
}  // namespace lll
