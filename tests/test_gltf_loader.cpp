// glTF loader tests: small files written per test with known contents, and the four shared scenes
// (broken input: test_gltf_broken_input.cpp).
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

// KHR_mesh_quantization (gltfpack's default output): positions and texture coordinates of 8- and
// 16-bit integers, normalized or not, normals and tangents of normalized signed ones, read as glTF
// defines them (a normalized signed c is max(c / max, -1)); the same types without the extension,
// and unsigned normals with it, are refused.
TEST_F(GltfLoaderTest, QuantizedAttributesWithKhrMeshQuantization) {
  constexpr int kByte = 5120, kShort = 5122;
  GltfBuilder b;
  const int position = b.addAccessor<int16_t>({0, 0, 0, 1000, 0, 0, 1000, -1000, 0}, kShort, "VEC3");
  const int normal = b.addAccessor<int8_t>({0, 0, 127, 0, -128, 0, 0, 127, 0, 0, 0, 64}, kByte, "VEC3", true);
  b.doc["accessors"][normal]["count"] = 3;
  const int tangent = b.addAccessor<int16_t>({32767, 0, 0, 32767, 0, 0, -32767, -32768, 0, 32767, 0, 32767},
                                             kShort, "VEC4", true);
  const int uv = b.addAccessor<uint16_t>({0, 0, 2, 0, 0, 3}, kUnsignedShort, "VEC2");
  b.addMesh(json::array(
      {{{"attributes",
         {{"POSITION", position}, {"NORMAL", normal}, {"TANGENT", tangent}, {"TEXCOORD_0", uv}}}}}));
  b.setScene({b.addNode({{"mesh", 0}, {"scale", {0.001, 0.001, 0.001}}})});
  expectInputError(b.writeGltf(dir_, "undeclared"), "KHR_mesh_quantization");
  b.doc["extensionsUsed"] = {"KHR_mesh_quantization"};
  b.doc["extensionsRequired"] = {"KHR_mesh_quantization"};
  const Scene scene = loadGltf(b.writeGltf(dir_, "quantized"));
  ASSERT_EQ(scene.vertices.size(), 3u);
  expectVec3Near(scene.vertices[1].position, {1000, 0, 0});
  expectVec3Near(scene.vertices[2].position, {1000, -1000, 0});
  expectVec3Near(glm::vec3(scene.instances[0].transform * glm::vec4(scene.vertices[2].position, 1.0f)),
                 {1, -1, 0});
  expectVec3Near(scene.vertices[0].normal, {0, 0, 1});
  expectVec3Near(scene.vertices[1].normal, {0, -1, 0});  // -128 is -1, as -127 is
  expectVec3Near(scene.vertices[2].normal, {0, 1, 0});
  EXPECT_EQ(scene.vertices[0].tangent, glm::vec4(1, 0, 0, 1));
  EXPECT_EQ(scene.vertices[1].tangent, glm::vec4(0, 0, -1, -1));
  EXPECT_EQ(scene.vertices[2].uv, glm::vec2(0, 3));  // not normalized: the integers themselves
  b.doc["accessors"][normal]["componentType"] = kUnsignedByte;
  expectInputError(b.writeGltf(dir_, "unsigned-normal"), "NORMAL");
}

// glTF's TEXCOORD_1 and COLOR_0 reach the vertices: the second set as given (floats or normalized
// integers), colours as RGB (alpha 1) or RGBA in floats, normalized bytes or shorts, clamped into
// [0, 1]; a texture's texCoord 1 is kept per slot; COLOR_0 of another type is an InputError.
TEST_F(GltfLoaderTest, SecondTexCoordsAndVertexColorsAreRead) {
  GltfBuilder b = quadScene();
  json& attributes = b.doc["meshes"][0]["primitives"][0]["attributes"];
  attributes["TEXCOORD_1"] =
      b.addAccessor<uint16_t>({0, 0, 65535, 0, 65535, 32768, 0, 65535}, kUnsignedShort, "VEC2", true);
  attributes["COLOR_0"] =
      b.addAccessor<uint8_t>({255, 0, 0, 0, 255, 0, 0, 0, 255, 51, 102, 153}, kUnsignedByte, "VEC3", true);
  writeBytes(dir_ / "checker.png", kPng2x2.data(), kPng2x2.size());
  b.doc["images"] = json::array({{{"uri", "checker.png"}}});
  b.doc["textures"] = json::array({{{"source", 0}}});
  b.doc["materials"][0]["occlusionTexture"] = {{"index", 0}, {"texCoord", 1}};
  b.doc["materials"][0]["pbrMetallicRoughness"] = {{"baseColorTexture", {{"index", 0}}}};
  LoadReport report;
  Scene scene = loadGltf(b.writeGltf(dir_, "sets"), &report);
  EXPECT_FALSE(anyWarningContains(report, "TEXCOORD_1"));
  EXPECT_FALSE(anyWarningContains(report, "COLOR_0"));
  EXPECT_FALSE(anyWarningContains(report, "texCoord"));
  ASSERT_EQ(scene.vertices.size(), 4u);
  EXPECT_EQ(scene.vertices[2].uv1, glm::vec2(1.0f, 32768.0f / 65535.0f));
  EXPECT_EQ(scene.vertices[3].uv1, glm::vec2(0.0f, 1.0f));
  EXPECT_EQ(scene.vertices[0].rgba(), glm::vec4(1, 0, 0, 1));
  const glm::vec4 last = scene.vertices[3].rgba();  // half floats: within 1/2048
  expectVec3Near(glm::vec3(last), glm::vec3(0.2f, 0.4f, 0.6f), 5e-4f);
  EXPECT_EQ(last.a, 1.0f);
  EXPECT_EQ(scene.materials[0].texCoords[kOcclusionSlot], 1);
  EXPECT_EQ(scene.materials[0].texCoords[kBaseColorSlot], 0);

  attributes["COLOR_0"] =
      b.addAccessor<float>({0.5f, 0.25f, 0.125f, 0.75f, 2, -1, 0, 1, 0, 0, 0, 0, 1, 1, 1, 0}, kFloat, "VEC4");
  scene = loadGltf(b.writeGltf(dir_, "rgba"));
  EXPECT_EQ(scene.vertices[0].rgba(), glm::vec4(0.5f, 0.25f, 0.125f, 0.75f));
  EXPECT_EQ(scene.vertices[1].rgba(), glm::vec4(1, 0, 0, 1));  // clamped into [0, 1]
  attributes["COLOR_0"] = b.addAccessor<uint16_t>(
      {65535, 0, 0, 65535, 0, 65535, 0, 0, 0, 0, 65535, 65535, 0, 0, 0, 0}, kUnsignedShort, "VEC4", true);
  EXPECT_EQ(loadGltf(b.writeGltf(dir_, "shorts")).vertices[2].rgba(), glm::vec4(0, 0, 1, 1));
  attributes["COLOR_0"] = b.addAccessor<float>({1, 1, 1, 1, 1, 1, 1, 1}, kFloat, "VEC2");
  expectInputError(b.writeGltf(dir_, "vec2"), "COLOR_0");
  attributes["COLOR_0"] = b.addAccessor<float>({1, 1, 1, 1, 1, 1, 1, 1, 1}, kFloat, "VEC3");
  expectInputError(b.writeGltf(dir_, "short"), "different count");
}

// glTF's samplers reach each texture: wrap modes, magnification and minification filters (mipmapped
// or not); one image under two samplers is two textures; an undefined filter is trilinear; values
// glTF does not define are InputErrors naming the sampler.
TEST_F(GltfLoaderTest, SamplersAreRead) {
  GltfBuilder b = quadScene();
  writeBytes(dir_ / "checker.png", kPng2x2.data(), kPng2x2.size());
  b.doc["images"] = json::array({{{"uri", "checker.png"}}});
  b.doc["samplers"] =
      json::array({{{"wrapS", 33071}, {"wrapT", 33648}, {"magFilter", 9728}, {"minFilter", 9984}},
                   {{"minFilter", 9729}}});
  b.doc["textures"] =
      json::array({{{"source", 0}, {"sampler", 0}}, {{"source", 0}, {"sampler", 1}}, {{"source", 0}}});
  b.doc["materials"][0]["pbrMetallicRoughness"] = {{"baseColorTexture", {{"index", 0}}}};
  b.doc["materials"][0]["emissiveTexture"] = {{"index", 1}};
  b.doc["materials"][0]["occlusionTexture"] = {{"index", 2}};
  const Scene scene = loadGltf(b.writeGltf(dir_, "samplers"));
  const Material& m = scene.materials[0];
  ASSERT_EQ(scene.textures.size(), 3u);  // base colour, emissive and occlusion: three samplers
  const TextureSampler& first = scene.textures[size_t(m.baseColorTexture)].sampler;
  EXPECT_EQ(first.wrapU, TextureWrap::ClampToEdge);
  EXPECT_EQ(first.wrapV, TextureWrap::MirroredRepeat);
  EXPECT_EQ(first.magnify, TextureFilter::Nearest);
  EXPECT_EQ(first.minify, TextureFilter::Nearest);
  EXPECT_EQ(first.mip, MipFilter::Nearest);
  const TextureSampler& second = scene.textures[size_t(m.emissiveTexture)].sampler;
  EXPECT_EQ(second.wrapU, TextureWrap::Repeat);
  EXPECT_EQ(second.minify, TextureFilter::Linear);
  EXPECT_EQ(second.mip, MipFilter::None);
  EXPECT_EQ(scene.textures[size_t(m.occlusionTexture)].sampler, TextureSampler{});

  b.doc["samplers"][1]["wrapT"] = 1234;
  expectInputError(b.writeGltf(dir_, "wrap"), "sampler 1 has wrapT 1234");
  b.doc["samplers"][1] = {{"magFilter", 9984}};
  expectInputError(b.writeGltf(dir_, "mag"), "sampler 1 has magFilter 9984");
  b.doc["samplers"][1] = {{"minFilter", 42}};
  expectInputError(b.writeGltf(dir_, "min"), "sampler 1 has minFilter 42");
  b.doc["samplers"][1] = json::object();
  b.doc["textures"][1]["sampler"] = 7;
  expectInputError(b.writeGltf(dir_, "missing"), "sampler 7");
}

// EXT_texture_webp: a texture's WebP source is decoded (libwebp) in place of its PNG fallback,
// required or not; a WebP without a fallback decodes too; a broken one is warned about and a
// neutral texture stands in, as for a broken PNG.
TEST_F(GltfLoaderTest, WebpTexturesAreDecoded) {
  GltfBuilder b = quadScene();
  writeBytes(dir_ / "checker.png", kPng2x2.data(), kPng2x2.size());
  writeBytes(dir_ / "colours.webp", kWebp2x2.data(), kWebp2x2.size());
  b.doc["images"] = json::array({{{"uri", "checker.png"}}, {{"uri", "colours.webp"}}});
  b.doc["textures"] = json::array({{{"source", 0}, {"extensions", {{"EXT_texture_webp", {{"source", 1}}}}}}});
  b.doc["materials"][0]["pbrMetallicRoughness"] = {{"baseColorTexture", {{"index", 0}}}};
  b.doc["extensionsUsed"] = {"EXT_texture_webp"};
  LoadReport report;
  Scene scene = loadGltf(b.writeGltf(dir_, "fallback"), &report);
  for (const std::string& warning : report.warnings) ADD_FAILURE() << "unexpected warning: " << warning;
  ASSERT_EQ(scene.textures.size(), 1u);
  EXPECT_EQ(scene.textures[0].width, 2u);
  EXPECT_EQ(scene.textures[0].rgba, kWebp2x2Rgba);

  b.doc["textures"][0].erase("source");
  b.doc["extensionsRequired"] = {"EXT_texture_webp"};
  EXPECT_EQ(loadGltf(b.writeGltf(dir_, "required")).textures[0].rgba, kWebp2x2Rgba);

  std::vector<uint8_t> broken = kWebp2x2;
  broken.resize(30);
  writeBytes(dir_ / "colours.webp", broken.data(), broken.size());
  LoadReport brokenReport;
  EXPECT_TRUE(loadGltf(b.writeGltf(dir_, "broken"), &brokenReport).textures.empty());
  EXPECT_TRUE(anyWarningContains(brokenReport, "colours.webp", "WebP"));

  b.doc["textures"][0]["extensions"]["EXT_texture_webp"] = {{"source", "one"}};
  expectInputError(b.writeGltf(dir_, "nosource"), "EXT_texture_webp has no source");
}

// The images of a scene decode to a bounded number of texels together: past it an image is one
// that could not be decoded (warned about, a neutral texture in its place); a WebP of one colour
// is kilobytes at any size.
TEST_F(GltfLoaderTest, DecodedTexturesAreBoundedTogether) {
  GltfBuilder b = quadScene();
  writeBytes(dir_ / "checker.png", kPng2x2.data(), kPng2x2.size());
  writeBytes(dir_ / "colours.webp", kWebp2x2.data(), kWebp2x2.size());
  b.doc["images"] = json::array({{{"uri", "checker.png"}}, {{"uri", "colours.webp"}}});
  b.doc["textures"] = json::array({{{"source", 0}}, {{"source", 1}}});
  b.doc["materials"][0]["pbrMetallicRoughness"] = {{"baseColorTexture", {{"index", 0}}}};
  b.doc["materials"][0]["emissiveTexture"] = {{"index", 1}};
  const fs::path path = b.writeGltf(dir_, "budget");
  EXPECT_EQ(loadGltf(path, nullptr, GltfLimits{.textureTexels = 8}).textures.size(), 2u);  // 4 + 4 texels
  LoadReport report;
  const Scene scene = loadGltf(path, &report, GltfLimits{.textureTexels = 7});
  ASSERT_EQ(scene.textures.size(), 1u);
  EXPECT_EQ(scene.materials[0].emissiveTexture, -1);
  EXPECT_TRUE(anyWarningContains(report, "colours.webp", "past the 7 texels"));

  // One image under two samplers is two copies, each counted.
  b.doc["samplers"] = json::array({{{"magFilter", 9728}}});
  b.doc["textures"][1] = {{"source", 0}, {"sampler", 0}};
  const fs::path copies = b.writeGltf(dir_, "copies");
  EXPECT_EQ(loadGltf(copies, nullptr, GltfLimits{.textureTexels = 8}).textures.size(), 2u);
  LoadReport copyReport;
  EXPECT_EQ(loadGltf(copies, &copyReport, GltfLimits{.textureTexels = 7}).textures.size(), 1u);
  EXPECT_TRUE(anyWarningContains(copyReport, "another copy", "checker.png"));
}

// glTF morph targets at their default weights (the mesh's, or a node's own, which gets a morphed
// copy of the mesh): POSITION, NORMAL and TANGENT displacements times the weights, sparse ones too;
// other target attributes are warned about; weights that do not match the targets are an
// InputError.
TEST_F(GltfLoaderTest, MorphTargetsAtTheirDefaultWeights) {
  GltfBuilder b = quadScene();
  // Target 0 lifts vertex 2 by 1 in z and tilts its normal; target 1 (sparse) moves vertex 0 in x.
  const int lift = b.addAccessor<float>({0, 0, 0, 0, 0, 0, 0, 0, 1, 0, 0, 0}, kFloat, "VEC3");
  const int tilt = b.addAccessor<float>({0, 0, 0, 0, 0, 0, 1, 0, 0, 0, 0, 0}, kFloat, "VEC3");
  const uint8_t sparseIndex[] = {0};
  const float sparseValue[] = {-2, 0, 0};
  json sparse = {{"bufferView", b.addBufferView(sparseValue, sizeof sparseValue)},
                 {"componentType", kFloat},
                 {"count", 4},
                 {"type", "VEC3"}};
  sparse.erase("bufferView");
  sparse["sparse"] = {
      {"count", 1},
      {"indices", {{"bufferView", b.addBufferView(sparseIndex, 1)}, {"componentType", kUnsignedByte}}},
      {"values", {{"bufferView", int(b.doc["bufferViews"].size() - 2)}}}};
  b.doc["accessors"].push_back(sparse);
  const int move = int(b.doc["accessors"].size() - 1);
  json& primitive = b.doc["meshes"][0]["primitives"][0];
  primitive["targets"] = {{{"POSITION", lift}, {"NORMAL", tilt}, {"TEXCOORD_0", tilt}}, {{"POSITION", move}}};
  b.doc["meshes"][0]["weights"] = {0.5, 0.25};
  // A second node shows the mesh at weights of its own.
  b.doc["nodes"].push_back({{"mesh", 0}, {"weights", {1.0, 0.0}}, {"translation", {3, 0, 0}}});
  b.doc["scenes"][0]["nodes"] = {0, 1};
  LoadReport report;
  const Scene scene = loadGltf(b.writeGltf(dir_, "morph"), &report);
  EXPECT_TRUE(anyWarningContains(report, "TEXCOORD_0", "morph target"));
  ASSERT_EQ(scene.meshes.size(), 2u);
  ASSERT_EQ(scene.instances.size(), 2u);
  const auto vertex = [&](uint32_t instance, uint32_t i) {
    const Primitive& p = scene.meshes[scene.instances[instance].mesh].primitives[0];
    return scene.vertices[p.vertexOffset + i];
  };
  expectVec3Near(vertex(0, 2).position, glm::vec3(1, 1, 0.5f));
  expectVec3Near(vertex(0, 0).position, glm::vec3(-0.5f, 0, 0));  // the sparse target at 0.25
  expectVec3Near(vertex(0, 2).normal, glm::vec3(0.5f, 0, 1));     // shaders normalize it
  expectVec3Near(vertex(1, 2).position, glm::vec3(1, 1, 1));
  expectVec3Near(vertex(1, 0).position, glm::vec3(0, 0, 0));
  expectVec3Near(vertex(1, 2).normal, glm::vec3(1, 0, 1));

  // Posed copies are bounded together: the node's copy is 4 vertices, a second node's 4 more.
  EXPECT_EQ(loadGltf(b.writeGltf(dir_, "one-copy"), nullptr, GltfLimits{.posedVertices = 4}).meshes.size(),
            2u);
  b.doc["nodes"].push_back({{"mesh", 0}, {"weights", {0.0, 1.0}}});
  b.doc["scenes"][0]["nodes"] = {0, 1, 2};
  try {
    loadGltf(b.writeGltf(dir_, "two-copies"), nullptr, GltfLimits{.posedVertices = 4});
    ADD_FAILURE() << "a second posed copy past the limit loaded";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("node 2 needs a posed copy of mesh 0"), std::string::npos)
        << e.what();
  }

  b.doc["meshes"][0]["weights"] = {0.5};
  expectInputError(b.writeGltf(dir_, "weights"), "2 morph targets but 1 weights");
}

// glTF skins at the rest pose: each vertex moved by its joints' world transforms times their
// inverse bind matrices, blended by its weights; the skinned mesh's own node transform does not
// apply. Broken skins are InputErrors naming them.
TEST_F(GltfLoaderTest, SkinsAtTheRestPose) {
  GltfBuilder b = quadScene();
  json& primitive = b.doc["meshes"][0]["primitives"][0];
  // Vertices 0 and 1 follow joint 0; vertex 2 joint 1; vertex 3 half each.
  primitive["attributes"]["JOINTS_0"] =
      b.addAccessor<uint8_t>({0, 0, 0, 0, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0}, kUnsignedByte, "VEC4");
  primitive["attributes"]["WEIGHTS_0"] =
      b.addAccessor<float>({1, 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 0.5f, 0.5f, 0, 0}, kFloat, "VEC4");
  // Joint 1 was bound at y = 1 and rests 2 further along z: its matrix moves by (0, 0, 2).
  const int inverseBinds = b.addAccessor<float>(
      {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, -1, 0, 1},
      kFloat, "MAT4");
  b.doc["nodes"][0]["translation"] = {5, 0, 0};  // ignored: the joints place the skinned mesh
  b.doc["nodes"][0]["skin"] = 0;
  b.doc["nodes"].push_back({{"children", {2}}});           // 1: joint 0
  b.doc["nodes"].push_back({{"translation", {0, 1, 2}}});  // 2: joint 1
  b.doc["skins"] = json::array({{{"joints", {1, 2}}, {"inverseBindMatrices", inverseBinds}}});
  b.doc["scenes"][0]["nodes"] = {0, 1};
  LoadReport report;
  const Scene scene = loadGltf(b.writeGltf(dir_, "skin"), &report);
  for (const std::string& warning : report.warnings) ADD_FAILURE() << "unexpected warning: " << warning;
  ASSERT_EQ(scene.instances.size(), 1u);
  expectMat4Near(scene.instances[0].transform, glm::mat4(1.0f));
  const Primitive& p = scene.meshes[scene.instances[0].mesh].primitives[0];
  const auto position = [&](uint32_t i) { return scene.vertices[p.vertexOffset + i].position; };
  expectVec3Near(position(0), glm::vec3(0, 0, 0));
  expectVec3Near(position(1), glm::vec3(1, 0, 0));
  expectVec3Near(position(2), glm::vec3(1, 1, 2));
  expectVec3Near(position(3), glm::vec3(0, 1, 1));
  expectVec3Near(scene.vertices[p.vertexOffset + 2].normal, glm::vec3(0, 0, 1));

  json& joints = primitive["attributes"]["JOINTS_0"];
  const int goodJoints = joints;
  joints = b.addAccessor<uint8_t>({0, 0, 0, 0, 0, 0, 0, 0, 7, 0, 0, 0, 0, 1, 0, 0}, kUnsignedByte, "VEC4");
  expectInputError(b.writeGltf(dir_, "joint"), "JOINTS_0 7 at vertex 2, but its skin has 2 joints");
  joints = goodJoints;
  b.doc["scenes"][0]["nodes"] = {0};
  expectInputError(b.writeGltf(dir_, "outside"), "skin 0's joint 0 is node 1, which is not in the scene");
  b.doc["scenes"][0]["nodes"] = {0, 1};
  b.doc["skins"][0]["joints"] = {1};
  expectInputError(b.writeGltf(dir_, "binds"), "2 inverse bind matrices for 1 joints");
  b.doc["skins"][0]["joints"] = {1, 2};
  primitive["attributes"].erase("WEIGHTS_0");
  expectInputError(b.writeGltf(dir_, "weights"), "only one of JOINTS_0 and WEIGHTS_0");
}

// EXT_mesh_gpu_instancing: a node draws its mesh once per element of its TRANSLATION, ROTATION
// (normalized shorts allowed) and SCALE accessors, each as the node's transform times translation x
// rotation x scale; a mirroring instance gets the mesh's reversed copy; mismatched counts are an
// InputError.
TEST_F(GltfLoaderTest, GpuInstancingDrawsEveryInstance) {
  GltfBuilder b = quadScene();
  const int translation = b.addAccessor<float>({0, 0, 0, 10, 0, 0, 0, 5, 0}, kFloat, "VEC3");
  // Identity, and 90 degrees about z (sin 45 = 23170 / 32767 in normalized shorts).
  const int rotation =
      b.addAccessor<int16_t>({0, 0, 0, 32767, 0, 0, 0, 32767, 0, 0, 23170, 23170}, 5122, "VEC4", true);
  const int scale = b.addAccessor<float>({1, 1, 1, 2, 2, 2, -1, 1, 1}, kFloat, "VEC3");
  b.doc["nodes"][0]["translation"] = {0, 0, 1};
  b.doc["nodes"][0]["extensions"] = {
      {"EXT_mesh_gpu_instancing",
       {{"attributes",
         {{"TRANSLATION", translation}, {"ROTATION", rotation}, {"SCALE", scale}, {"_ID", scale}}}}}};
  b.doc["extensionsUsed"] = {"EXT_mesh_gpu_instancing"};
  b.doc["extensionsRequired"] = {"EXT_mesh_gpu_instancing"};
  LoadReport report;
  const Scene scene = loadGltf(b.writeGltf(dir_, "instanced"), &report);
  for (const std::string& warning : report.warnings) ADD_FAILURE() << "unexpected warning: " << warning;
  ASSERT_EQ(scene.instances.size(), 3u);
  const auto corner = [&](size_t i, glm::vec3 p) {
    return glm::vec3(scene.instances[i].transform * glm::vec4(p, 1));
  };
  expectVec3Near(corner(0, glm::vec3(1, 1, 0)), glm::vec3(1, 1, 1));
  expectVec3Near(corner(1, glm::vec3(1, 1, 0)), glm::vec3(12, 2, 1), 1e-4f);
  expectVec3Near(corner(2, glm::vec3(1, 1, 0)), glm::vec3(-1, 4, 1), 1e-4f);  // scaled -1 in x, turned
  EXPECT_EQ(scene.instances[0].mesh, scene.instances[1].mesh);
  EXPECT_NE(scene.instances[2].mesh, scene.instances[0].mesh);  // mirrored: the reversed copy

  // gltfpack's instanced cave (assets/cave-instanced, a mesh per primitive): every copy of a mesh
  // one node's instance, as many primitives placed as the cave's nodes place.
  const Scene packed = loadGltf(LLL_ASSETS_DIR "/cave-instanced/cave.glb");
  const Scene cave = loadGltf(LLL_ASSETS_DIR "/cave/cave.gltf");
  const auto placedPrimitives = [](const Scene& scene) {
    size_t count = 0;
    for (const Instance& instance : scene.instances) count += scene.meshes[instance.mesh].primitives.size();
    return count;
  };
  EXPECT_EQ(placedPrimitives(packed), placedPrimitives(cave));
  EXPECT_LT(packed.meshes.size(), packed.instances.size());
  EXPECT_EQ(packed.triangleCount(), cave.triangleCount());

  try {  // placements are bounded
    loadGltf(b.writeGltf(dir_, "limited"), nullptr, GltfLimits{.instances = 2});
    ADD_FAILURE() << "three placements loaded under a limit of two";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("past the 2 placements"), std::string::npos) << e.what();
  }

  b.doc["nodes"][0]["extensions"]["EXT_mesh_gpu_instancing"]["attributes"]["SCALE"] =
      b.addAccessor<float>({1, 1, 1, 2, 2, 2}, kFloat, "VEC3");
  expectInputError(b.writeGltf(dir_, "counts"), "different counts");
  b.doc["nodes"][0]["extensions"]["EXT_mesh_gpu_instancing"]["attributes"] = {{"_ID", scale}};
  expectInputError(b.writeGltf(dir_, "none"), "none of TRANSLATION, ROTATION and SCALE");
  b.doc["nodes"][0]["extensions"]["EXT_mesh_gpu_instancing"] = json::object();
  expectInputError(b.writeGltf(dir_, "empty"), "has no attributes");
}

// KHR_texture_transform on a material's textures: offset, rotation and scale read per texture
// (the identity where a texture has none), a texCoord in it counted like the texture's own, and
// values of the wrong shape or not finite as 32-bit floats refused naming the texture.
TEST_F(GltfLoaderTest, TextureTransformsAreRead) {
  GltfBuilder b = quadScene();
  writeBytes(dir_ / "checker.png", kPng2x2.data(), kPng2x2.size());
  b.doc["images"] = json::array({{{"uri", "checker.png"}}});
  b.doc["textures"] = json::array({{{"source", 0}}});
  const json transform = {{"offset", {0.5, -0.25}}, {"rotation", 1.5}, {"scale", {2, 3}}};
  b.doc["materials"][0]["pbrMetallicRoughness"]["baseColorTexture"] = {
      {"index", 0}, {"extensions", {{"KHR_texture_transform", transform}}}};
  b.doc["materials"][0]["normalTexture"] = {
      {"index", 0}, {"extensions", {{"KHR_texture_transform", {{"scale", {-1, 1}}}}}}};
  b.doc["materials"][0]["emissiveTexture"] = {{"index", 0}};
  b.doc["extensionsUsed"] = {"KHR_texture_transform"};
  LoadReport report;
  const Scene scene = loadGltf(b.writeGltf(dir_, "transformed"), &report);
  ASSERT_EQ(scene.materials.size(), 1u);
  const Material& m = scene.materials[0];
  EXPECT_EQ(m.transforms[kBaseColorSlot].offset, glm::vec2(0.5f, -0.25f));
  EXPECT_EQ(m.transforms[kBaseColorSlot].rotation, 1.5f);
  EXPECT_EQ(m.transforms[kBaseColorSlot].scale, glm::vec2(2.0f, 3.0f));
  EXPECT_EQ(m.transforms[kNormalSlot].scale, glm::vec2(-1.0f, 1.0f));
  EXPECT_TRUE(m.transforms[kEmissiveSlot].identity());
  EXPECT_TRUE(m.transforms[kMetallicRoughnessSlot].identity());
  EXPECT_FALSE(anyWarningContains(report, "KHR_texture_transform"));
  EXPECT_FALSE(anyWarningContains(report, "texCoord"));

  json& extension = b.doc["materials"][0]["pbrMetallicRoughness"]["baseColorTexture"]["extensions"]
                         ["KHR_texture_transform"];
  // Its texCoord replaces the texture's: set 1 is read, a later one warned about.
  extension["texCoord"] = 1;
  LoadReport second;
  EXPECT_EQ(loadGltf(b.writeGltf(dir_, "texcoord1"), &second).materials[0].texCoords[kBaseColorSlot], 1);
  EXPECT_FALSE(anyWarningContains(second, "texCoord"));
  extension["texCoord"] = 2;
  LoadReport other;
  EXPECT_EQ(loadGltf(b.writeGltf(dir_, "texcoord2"), &other).materials[0].texCoords[kBaseColorSlot], 0);
  EXPECT_TRUE(anyWarningContains(other, "texCoord"));
  extension["texCoord"] = -1;
  expectInputError(b.writeGltf(dir_, "texcoordneg"), "texCoord is not a non-negative integer");
  extension.erase("texCoord");
  extension["offset"] = {1};
  expectInputError(b.writeGltf(dir_, "short"), "KHR_texture_transform's offset is not two numbers");
  extension["offset"] = {0, 1e39};
  expectInputError(b.writeGltf(dir_, "huge"), "offset[1]");
  extension["offset"] = {0, 0};
  extension["rotation"] = "quarter";
  expectInputError(b.writeGltf(dir_, "rotation"), "rotation");
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

// assets/cave-quantized is assets/cave through gltfpack 1.3 (KHR_mesh_quantization: 16-bit
// positions, 8-bit normals, its meshes and identical materials merged): the same triangles and
// world bounds to within gltfpack's 14-bit position grid.
TEST(GltfAssets, QuantizedCaveIsTheCave) {
  LoadReport report;
  const Scene quantized = loadGltf(LLL_ASSETS_DIR "/cave-quantized/cave.gltf", &report);
  for (const std::string& warning : report.warnings) ADD_FAILURE() << "unexpected warning: " << warning;
  const Scene cave = loadGltf(LLL_ASSETS_DIR "/cave/cave.gltf");
  EXPECT_EQ(quantized.triangleCount(), cave.triangleCount());
  const Bounds a = quantized.worldBounds(), b = cave.worldBounds();
  const float step = std::max({b.extent().x, b.extent().y, b.extent().z}) / 16383.0f;
  for (int axis = 0; axis < 3; ++axis) {
    EXPECT_NEAR(a.min[axis], b.min[axis], step) << "axis " << axis;
    EXPECT_NEAR(a.max[axis], b.max[axis], step) << "axis " << axis;
  }
}

// A .glb as its JSON and its binary chunk, the chunk written to `dir` as <stem>.bin, so that edited
// copies of the JSON load as .gltf files beside it.
struct SplitGlb {
  json doc;
  std::vector<uint8_t> bin;
  fs::path dir;
  std::string binName;
  fs::path gltf(json d, const std::string& name) const {
    d["buffers"][0]["uri"] = binName;
    writeText(dir / (name + ".gltf"), d.dump());
    return dir / (name + ".gltf");
  }
};

SplitGlb splitGlb(const fs::path& glb, const fs::path& dir) {
  std::ifstream in(glb, std::ios::binary);
  const std::vector<uint8_t> bytes{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
  uint32_t jsonLength = 0, binLength = 0;
  std::memcpy(&jsonLength, bytes.data() + 12, 4);
  std::memcpy(&binLength, bytes.data() + 20 + jsonLength, 4);
  SplitGlb out{json::parse(bytes.begin() + 20, bytes.begin() + 20 + jsonLength),
               {bytes.begin() + 28 + jsonLength, bytes.begin() + 28 + jsonLength + binLength},
               dir,
               glb.stem().string() + ".bin"};
  writeBytes(dir / out.binName, out.bin.data(), out.bin.size());
  return out;
}

// EXT_meshopt_compression (gltfpack -c): assets/cave-meshopt/cave.glb (gltfpack -cc -vpf: vertex
// and index codecs, EXPONENTIAL positions, OCTAHEDRAL normals) decodes to the cave's triangles and
// bounds. The same file as .gltf with its binary chunk beside it (its fallback buffer then a JSON
// buffer without data, which tinygltf alone refuses) loads to the same vertices and indices, and
// broken extension values are InputErrors naming them.
TEST_F(GltfLoaderTest, MeshoptCompressedCave) {
  const fs::path glb = fs::path(LLL_ASSETS_DIR) / "cave-meshopt" / "cave.glb";
  LoadReport report;
  const Scene packed = loadGltf(glb, &report);
  for (const std::string& warning : report.warnings) ADD_FAILURE() << "unexpected warning: " << warning;
  const Scene cave = loadGltf(LLL_ASSETS_DIR "/cave/cave.gltf");
  EXPECT_EQ(packed.triangleCount(), cave.triangleCount());
  // The EXPONENTIAL filter keeps positions to a shared exponent and a 16-bit mantissa: within the
  // quantized cave's 14-bit grid of the scene's extent.
  const Bounds a = packed.worldBounds(), b = cave.worldBounds();
  const float step = std::max({b.extent().x, b.extent().y, b.extent().z}) / 16383.0f;
  for (int axis = 0; axis < 3; ++axis) {
    EXPECT_NEAR(a.min[axis], b.min[axis], step) << "axis " << axis;
    EXPECT_NEAR(a.max[axis], b.max[axis], step) << "axis " << axis;
  }

  const SplitGlb split = splitGlb(glb, dir_);
  const json& doc = split.doc;
  const auto written = [&](const json& d, const std::string& name) { return split.gltf(d, name); };
  const Scene text = loadGltf(written(doc, "cave"));
  ASSERT_EQ(text.vertices.size(), packed.vertices.size());
  for (size_t i = 0; i < text.vertices.size(); ++i)
    ASSERT_EQ(text.vertices[i].position, packed.vertices[i].position) << "vertex " << i;
  EXPECT_EQ(text.indices, packed.indices);

  // The first compressed attribute view of four bytes a vertex, as a JSON pointer.
  std::string view;
  for (size_t i = 0; i < doc["bufferViews"].size() && view.empty(); ++i) {
    const json& e = doc["bufferViews"][i]["extensions"]["EXT_meshopt_compression"];
    if (e.value("mode", "") == "ATTRIBUTES" && e.value("byteStride", 0) == 4)
      view = "/bufferViews/" + std::to_string(i) + "/extensions/EXT_meshopt_compression";
  }
  ASSERT_FALSE(view.empty());
  const json::json_pointer at(view);
  const auto broken = [&](const std::string& name, const std::string& detail, const auto& edit) {
    json d = doc;
    edit(d[at]);
    expectInputError(written(d, name), detail);
  };
  broken("truncated", "does not decode", [](json& e) { e["byteLength"] = e["byteLength"].get<int>() / 2; });
  broken("mode", "mode 'POINTS'", [](json& e) { e["mode"] = "POINTS"; });
  broken("stride", "byteStride 6", [](json& e) { e["byteStride"] = 6; });
  broken("count", "decodes to", [](json& e) { e["count"] = e["count"].get<int>() + 1; });
  broken("buffer", "names buffer 7", [](json& e) { e["buffer"] = 7; });
  broken("filter", "filter 'QUATERNION'", [](json& e) { e["filter"] = "QUATERNION"; });
  broken("nocount", "has no count", [](json& e) { e.erase("count"); });
  broken("range", "covers bytes", [](json& e) { e["byteOffset"] = 1 << 30; });
  broken("expansion", "more than meshoptimizer", [](json& e) { e["count"] = 1 << 28; });
}

// KHR_draco_mesh_compression: assets/cave-draco/cave.glb (draco_transcoder with Blender's default
// quantization: 14-bit positions, 10-bit normals) decodes to the cave's primitives, each with its
// triangles and every vertex within its 14-bit grid of the original's (the meshes named as there); broken
// extension values are InputErrors naming them.
TEST_F(GltfLoaderTest, DracoCompressedCave) {
  const fs::path glb = fs::path(LLL_ASSETS_DIR) / "cave-draco" / "cave.glb";
  LoadReport report;
  const Scene draco = loadGltf(glb, &report);
  for (const std::string& warning : report.warnings) ADD_FAILURE() << "unexpected warning: " << warning;
  const Scene cave = loadGltf(LLL_ASSETS_DIR "/cave/cave.gltf");
  ASSERT_EQ(draco.meshes.size(), cave.meshes.size());
  EXPECT_EQ(draco.triangleCount(), cave.triangleCount());
  const auto corners = [](const Scene& scene, const Primitive& p) {
    std::vector<glm::vec3> out;
    for (uint32_t i = 0; i < p.indexCount; ++i)
      out.push_back(scene.vertices[p.vertexOffset + scene.indices[p.firstIndex + i]].position);
    return out;
  };
  for (const Mesh& original : cave.meshes) {  // the transcoder reorders the meshes
    const auto found = std::find_if(draco.meshes.begin(), draco.meshes.end(),
                                    [&](const Mesh& m) { return m.name == original.name; });
    ASSERT_NE(found, draco.meshes.end()) << original.name;
    const std::string& m = original.name;
    ASSERT_EQ(found->primitives.size(), original.primitives.size()) << m;
    for (size_t p = 0; p < original.primitives.size(); ++p) {
      const std::vector<glm::vec3> a = corners(draco, found->primitives[p]);
      const std::vector<glm::vec3> b = corners(cave, original.primitives[p]);
      ASSERT_EQ(a.size(), b.size()) << "mesh " << m << " primitive " << p;
      glm::vec3 lo(INFINITY), hi(-INFINITY);
      for (const glm::vec3& v : b) lo = glm::min(lo, v), hi = glm::max(hi, v);
      const float step = std::max({hi.x - lo.x, hi.y - lo.y, hi.z - lo.z}) / 16383.0f;
      float worst = 0.0f;
      for (const glm::vec3& v : a) {
        float nearest = INFINITY;
        for (const glm::vec3& w : b) nearest = std::min(nearest, glm::distance(v, w));
        worst = std::max(worst, nearest);
      }
      EXPECT_LE(worst, step) << "mesh " << m << " primitive " << p;
    }
  }

  const SplitGlb split = splitGlb(glb, dir_);
  const json& doc = split.doc;
  const auto written = [&](const json& d, const std::string& name) { return split.gltf(d, name); };
  const Scene text = loadGltf(written(doc, "cave"));
  EXPECT_EQ(text.indices, draco.indices);
  const json::json_pointer primitive("/meshes/0/primitives/0");
  const auto broken = [&](const std::string& name, const std::string& detail, const auto& edit) {
    json d = doc;
    edit(d, d[primitive]["extensions"]["KHR_draco_mesh_compression"]);
    expectInputError(written(d, name), detail);
  };
  const int view = doc[primitive]["extensions"]["KHR_draco_mesh_compression"]["bufferView"];
  broken("truncated", "does not decode", [&](json& d, json&) {
    d["bufferViews"][view]["byteLength"] = d["bufferViews"][view]["byteLength"].get<int>() / 2;
  });
  broken("notdraco", "not Draco data", [&](json& d, json&) {  // its "DRACO" header skipped
    d["bufferViews"][view]["byteOffset"] = d["bufferViews"][view].value("byteOffset", 0) + 1;
    d["bufferViews"][view]["byteLength"] = d["bufferViews"][view]["byteLength"].get<int>() - 1;
  });
  broken("view", "names bufferView 999", [](json&, json& e) { e["bufferView"] = 999; });
  broken("attribute", "Draco attribute 7", [](json&, json& e) { e["attributes"]["NORMAL"] = 7; });
  broken("negative", "not a non-negative integer", [](json&, json& e) { e["attributes"]["NORMAL"] = -1; });
  broken("components", "components", [&](json& d, json&) {
    d["accessors"][d[primitive]["attributes"]["NORMAL"].get<int>()]["type"] = "VEC2";
  });
  broken("fan", "mode 6", [&](json& d, json&) { d[primitive]["mode"] = 6; });
  broken("noview", "needs a bufferView", [](json&, json& e) { e.erase("bufferView"); });

  // A header claiming 2^26 triangles and vertices from a few hundred bytes: Draco itself allocated
  // 1.6 GB for it before finding the data short; its counts are refused first.
  const json& v = doc["bufferViews"][view];
  const uint8_t* compressed = split.bin.data() + v.value("byteOffset", 0);
  std::vector<uint8_t> bomb(compressed,
                            compressed + 12);  // "DRACO", 2.2, mesh, edgebreaker, flags, traversal
  for (int field = 0; field < 5; ++field) {    // vertices, faces, attribute data, symbols, splits
    if (field == 2) {
      bomb.push_back(1);
      continue;
    }
    const uint32_t value = field == 4 ? 0u : 1u << 26;
    for (uint32_t rest = value;; rest >>= 7) {
      bomb.push_back(uint8_t((rest & 0x7F) | (rest >= 0x80 ? 0x80 : 0)));
      if (rest < 0x80) break;
    }
  }
  bomb.insert(bomb.end(), compressed + 17, compressed + v["byteLength"].get<size_t>());
  writeBytes(dir_ / "bomb.bin", bomb.data(), bomb.size());
  json d = doc;
  d["buffers"][0]["uri"] = split.binName;
  d["buffers"].push_back({{"uri", "bomb.bin"}, {"byteLength", bomb.size()}});
  d["bufferViews"].push_back({{"buffer", 1}, {"byteLength", bomb.size()}});
  d[primitive]["extensions"]["KHR_draco_mesh_compression"]["bufferView"] = d["bufferViews"].size() - 1;
  writeText(dir_ / "bomb.gltf", d.dump());
  expectInputError(dir_ / "bomb.gltf", "claims 67108864 triangles");
}

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
