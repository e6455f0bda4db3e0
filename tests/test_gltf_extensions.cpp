// glTF beyond the core's first set of everything: the extensions the loader reads
// (KHR_mesh_quantization, KHR_texture_transform, EXT_texture_webp, EXT_mesh_gpu_instancing, and
// the compressed caves of EXT_meshopt_compression and KHR_draco_mesh_compression), TEXCOORD_1,
// COLOR_0, samplers, morph targets and skins, and the bounds on what a small file can make the
// loader allocate. Each with the InputErrors of its broken forms.
#include "gltf_test_support.h"

namespace lll {
namespace {

using namespace gltf_test;  // the files' builder and checks (gltf_test_support.h)

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
  expectInputError(b.writeGltf(dir_, "two-copies"), "node 2 needs a posed copy of mesh 0",
                   GltfLimits{.posedVertices = 4});

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

  // Placements are bounded.
  expectInputError(b.writeGltf(dir_, "limited"), "past the 2 placements", GltfLimits{.instances = 2});

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

}  // namespace
}  // namespace lll
