// glTF 2.0 loading. tinygltf parses the JSON and reads the buffers, but it trusts most indices,
// offsets and sizes in the file; this file checks every one before use, so a corrupt or hostile
// file ends in an InputError that names it, never in a crash or an out-of-bounds read.
#include "scene/gltf_loader.h"

// Before the implementation macros: it includes tiny_gltf.h, whose implementation must come once.
#include "scene/gltf_accessors.h"
#include "scene/gltf_draco.h"
#include "scene/gltf_files.h"
#include "scene/gltf_importer.h"
#include "scene/gltf_meshopt.h"
#include "scene/gltf_numbers.h"
#include "scene/gltf_schema.h"

#define TINYGLTF_IMPLEMENTATION
#define TINYGLTF_NO_STB_IMAGE_WRITE  // stb_image_write belongs to the image output code
#define STB_IMAGE_IMPLEMENTATION
#include <tiny_gltf.h>
// A unity build compiles the sources after this one in the same translation unit: gltf_materials.cpp
// includes stb_image.h, which must not bring its implementation a second time.
#undef TINYGLTF_IMPLEMENTATION
#undef STB_IMAGE_IMPLEMENTATION

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>
#include <glm/gtc/type_ptr.hpp>
#include <glm/gtx/component_wise.hpp>
#include <limits>
#include <map>
#include <numeric>
#include <optional>
#include <set>
#include <type_traits>
#include <utility>

#include "core/errors.h"
#include "scene/lights.h"

namespace lll::gltf_detail {
namespace {
// Extensions we implement, and those a file may require that only refine the look when ignored
// (IOR nudges dielectric reflectance), which get a warning when used.
const std::set<std::string> kHandledExtensions = {
    "KHR_lights_punctual",     "KHR_materials_emissive_strength", "KHR_mesh_quantization",
    "EXT_meshopt_compression", "KHR_draco_mesh_compression",      "KHR_texture_transform",
    "EXT_texture_webp",        "EXT_mesh_gpu_instancing"};
const std::set<std::string> kIgnorableRequiredExtensions = {"KHR_materials_ior"};

// tinygltf's image callback. We only keep the encoded bytes and decode later, for the images a
// material uses; bufferView images are not even read here, because tinygltf hands over a pointer
// it has not checked against the buffer.
bool keepEncodedImage(tinygltf::Image* image, const int, std::string*, std::string*, int, int,
                      const unsigned char* bytes, int size, void*) {
  if (image->bufferView < 0 && bytes != nullptr && size > 0) image->image.assign(bytes, bytes + size);
  return true;
}

bool hasZeroNormal(const std::vector<float>& normals) {
  for (size_t i = 0; i + 2 < normals.size(); i += 3)
    if (glm::length(glm::make_vec3(&normals[i])) < 1e-6f) return true;
  return false;
}

glm::vec3 unitOr(const glm::dvec3& v, const glm::vec3& fallback) {
  const double length = glm::length(v);
  return std::isfinite(length) && length > 1e-12 ? glm::vec3(v / length) : fallback;
}

std::string describeList(const std::set<std::string>& names) {
  std::string list;
  for (const std::string& name : names) list += (list.empty() ? "" : ", ") + name;
  return list;
}

}  // namespace

Scene GltfImporter::run() {
  scene_.name = path_.stem().string();
  parse();
  checkVersionAndExtensions();
  decodeMeshoptBufferViews(model_, file_);
  decodeDracoPrimitives(model_, file_);
  checkBufferViews();
  images_.resize(model_.images.size());
  for (size_t i = 0; i < model_.materials.size(); ++i) {
    scene_.materials.push_back(convertMaterial(model_.materials[i], int(i)));
  }
  for (size_t i = 0; i < model_.meshes.size(); ++i)
    scene_.meshes.push_back(convertMesh(int(i), model_.meshes[i].weights));
  placeNodes();
  warnAboutIgnoredData();
  return std::move(scene_);
}

void GltfImporter::parse() {
  std::vector<unsigned char> bytes;
  std::string readError;
  if (!readFileBytes(path_, bytes, readError)) fail("cannot read the glTF file: " + readError);

  const bool binary = bytes.size() >= 4 && std::memcmp(bytes.data(), "glTF", 4) == 0;
  if (!binary && !looksLikeJsonObject(bytes)) {
    fail(
        "is not a glTF file: it is neither glTF JSON (a .gltf starts with '{') nor binary glTF (a .glb "
        "starts with 'glTF')");
  }
  size_t jsonBegin = 0;
  size_t jsonSize = bytes.size();
  if (binary && bytes.size() >= 20) {
    // GLB header: magic, version, length, then the JSON chunk's length and type.
    const uint32_t chunkLength = uint32_t(bytes[12]) | uint32_t(bytes[13]) << 8 | uint32_t(bytes[14]) << 16 |
                                 uint32_t(bytes[15]) << 24;
    jsonBegin = 20;
    jsonSize = std::min<size_t>(chunkLength, bytes.size() - 20);
  }
  if (!jsonNestingWithinLimit(bytes.data() + jsonBegin, jsonSize)) {
    fail("its JSON is nested more than " + std::to_string(kMaxJsonNesting) +
         " levels deep; no valid glTF needs that, so the file is corrupt or not glTF");
  }
  checkFieldTypes(reinterpret_cast<const char*>(bytes.data() + jsonBegin), jsonSize, file_);
  bytes = withJsonEdited(bytes, binary, kMeshoptExtension, stubMeshoptFallbacks);
  bytes = withJsonEdited(bytes, binary, kDracoExtension, dropDracoIndices);

  FileAccess access{std::filesystem::absolute(path_).parent_path().string()};
  tinygltf::TinyGLTF gltf;
  gltf.SetFsCallbacks({&fileExistsBesideGltf, &keepPath, &readWholeFile, &refuseWrite, &access});
  gltf.SetImageLoader(&keepEncodedImage, nullptr);
  std::string error;
  std::string warning;  // tinygltf only warns about images, which we report ourselves
  bool loaded = false;
  try {
    loaded = binary ? gltf.LoadBinaryFromMemory(&model_, &error, &warning, bytes.data(),
                                                unsigned(bytes.size()), access.baseDir)
                    : gltf.LoadASCIIFromString(&model_, &error, &warning,
                                               reinterpret_cast<const char*>(bytes.data()),
                                               unsigned(bytes.size()), access.baseDir);
  } catch (const std::exception& e) {
    error = e.what();
  }
  if (!loaded) {
    if (binary) fail("not a valid binary glTF (.glb): " + oneLine(error) + ". The file may be truncated.");
    fail("not a valid glTF 2.0 file: " + oneLine(error) +
         ". A .gltf must be glTF 2.0 JSON with its .bin (complete, byteLength bytes) and images beside it; "
         "a .glb must start with the 'glTF' header.");
  }
}

void GltfImporter::checkVersionAndExtensions() {
  if (model_.asset.version.rfind("2.", 0) != 0) {
    fail("is glTF version '" + model_.asset.version +
         "'; only glTF 2.0 is supported (convert it, e.g. by importing and re-exporting in Blender)");
  }
  for (const std::string& extension : model_.extensionsRequired) {
    if (!kHandledExtensions.contains(extension) && !kIgnorableRequiredExtensions.contains(extension)) {
      fail("requires the glTF extension " + extension +
           ", which this renderer does not support. Re-export the scene without it (for example with "
           "PNG, JPEG or WebP textures in place of KTX2).");
    }
  }
  quantized_ = std::find(model_.extensionsUsed.begin(), model_.extensionsUsed.end(),
                         "KHR_mesh_quantization") != model_.extensionsUsed.end();
  std::set<std::string> ignored;
  for (const std::string& extension : model_.extensionsUsed) {
    if (!kHandledExtensions.contains(extension)) ignored.insert(extension);
  }
  if (!ignored.empty()) {
    warn("uses glTF extension(s) " + describeList(ignored) +
         " that the renderer ignores; the scene may look different than in other viewers");
  }
}

Mesh GltfImporter::convertMesh(int index, const std::vector<double>& weights,
                               const std::vector<glm::dmat4>* joints) {
  const tinygltf::Mesh& in = model_.meshes[size_t(index)];
  Mesh out;
  out.name = in.name.empty() ? "mesh " + std::to_string(index) : in.name;
  if (in.primitives.empty())
    fail("mesh " + inQuotes(out.name) + " has no primitives; glTF requires at least one");
  for (size_t i = 0; i < in.primitives.size(); ++i) {
    convertPrimitive(in.primitives[i], "mesh " + inQuotes(out.name) + " primitive " + std::to_string(i),
                     weights, joints, out);
  }
  return out;
}

void GltfImporter::convertPrimitive(const tinygltf::Primitive& primitive, const std::string& where,
                                    const std::vector<double>& weights, const std::vector<glm::dmat4>* joints,
                                    Mesh& mesh) {
  static const char* const kModeNames[] = {"points", "lines", "a line loop", "a line strip"};
  if (primitive.mode >= TINYGLTF_MODE_POINTS && primitive.mode <= TINYGLTF_MODE_LINE_STRIP) {
    warn(where + " draws " + kModeNames[primitive.mode] + "; only triangles are rendered, so it is skipped");
    return;
  }
  if (primitive.mode < TINYGLTF_MODE_TRIANGLES || primitive.mode > TINYGLTF_MODE_TRIANGLE_FAN) {
    fail(where + " has mode " + std::to_string(primitive.mode) +
         ", which is not a glTF primitive mode (0 to 6)");
  }
  const auto position = primitive.attributes.find("POSITION");
  if (position == primitive.attributes.end()) {
    fail(where + " has no POSITION attribute; every glTF mesh primitive needs one. Re-export the mesh.");
  }
  // KHR_mesh_quantization: integer attributes, dequantized here (the node's transform usually
  // scales them back to metres).
  std::vector<float> positions =
      readAccessor<float>(position->second, where + " POSITION", TINYGLTF_TYPE_VEC3,
                          quantized_ ? Components::QuantizedPosition : Components::Float);
  const size_t vertexCount = positions.size() / 3;
  std::vector<float> normals;
  std::vector<float> uvs;
  std::vector<float> uvs1;
  std::vector<float> tangents;
  std::vector<float> colors;  // RGBA, alpha 1 where the file gives RGB
  for (const auto& [attribute, accessor] : primitive.attributes) {
    if (attribute == "NORMAL") {
      normals = readAccessor<float>(accessor, where + " NORMAL", TINYGLTF_TYPE_VEC3,
                                    quantized_ ? Components::QuantizedDirection : Components::Float);
    } else if (attribute == "TANGENT") {
      tangents = readAccessor<float>(accessor, where + " TANGENT", TINYGLTF_TYPE_VEC4,
                                     quantized_ ? Components::QuantizedDirection : Components::Float);
    } else if (attribute == "TEXCOORD_0") {
      uvs = readAccessor<float>(
          accessor, where + " TEXCOORD_0", TINYGLTF_TYPE_VEC2,
          quantized_ ? Components::QuantizedTexCoord : Components::FloatOrNormalizedUnsigned);
    } else if (attribute == "TEXCOORD_1") {
      uvs1 = readAccessor<float>(
          accessor, where + " TEXCOORD_1", TINYGLTF_TYPE_VEC2,
          quantized_ ? Components::QuantizedTexCoord : Components::FloatOrNormalizedUnsigned);
    } else if (attribute == "COLOR_0") {
      const bool rgb = accessor >= 0 && size_t(accessor) < model_.accessors.size() &&
                       model_.accessors[size_t(accessor)].type == TINYGLTF_TYPE_VEC3;
      colors =
          readAccessor<float>(accessor, where + " COLOR_0", rgb ? TINYGLTF_TYPE_VEC3 : TINYGLTF_TYPE_VEC4,
                              Components::FloatOrNormalizedUnsigned);
      checkFinite(colors, where + " COLOR_0");
      if (rgb) {
        std::vector<float> rgba;
        rgba.reserve(colors.size() / 3 * 4);
        for (size_t i = 0; i + 2 < colors.size(); i += 3)
          rgba.insert(rgba.end(), {colors[i], colors[i + 1], colors[i + 2], 1.0f});
        colors = std::move(rgba);
      }
    } else if (attribute != "POSITION" && attribute.rfind("JOINTS_", 0) != 0 &&
               attribute.rfind("WEIGHTS_", 0) != 0) {  // those two are read by applySkin
      ignoredAttributes_.insert(attribute);
    }
  }
  applyMorphTargets(primitive, where, weights, positions, normals, tangents);
  if (joints != nullptr) applySkin(primitive, where, *joints, positions, normals, tangents);
  checkFinite(positions, where + " POSITION");
  checkFinite(normals, where + " NORMAL");
  checkFinite(uvs, where + " TEXCOORD_0");
  checkFinite(uvs1, where + " TEXCOORD_1");
  if (hasZeroNormal(normals)) {
    // glTF requires unit normals; an accessor with no bufferView reads as all zeros. Without a
    // usable normal the triangle's own one is what glTF prescribes when NORMAL is absent.
    warn(where + " has a NORMAL of zero length (an accessor without data?); flat normals are used instead");
    normals.clear();
  }
  if ((!normals.empty() && normals.size() / 3 != vertexCount) ||
      (!uvs.empty() && uvs.size() / 2 != vertexCount) || (!uvs1.empty() && uvs1.size() / 2 != vertexCount) ||
      (!colors.empty() && colors.size() / 4 != vertexCount) ||
      (!tangents.empty() && tangents.size() / 4 != vertexCount)) {
    fail(where +
         " has NORMAL, TANGENT, TEXCOORD_0, TEXCOORD_1 or COLOR_0 with a different count than POSITION (" +
         std::to_string(vertexCount) + "); all attributes of a primitive must have the same count");
  }
  // glTF: tangents are ignored where normals are not given (flat shading builds its own frame).
  if (normals.empty()) tangents.clear();
  for (size_t i = 0; i < tangents.size(); i += 4) {
    const glm::vec4 t = glm::make_vec4(&tangents[i]);
    if (!std::isfinite(t.x) || !std::isfinite(t.y) || !std::isfinite(t.z) ||
        std::abs(std::abs(t.w) - 1.0f) > 1e-3f)
      fail(where + " has TANGENT " + std::to_string(i / 4) + " = (" + std::to_string(t.x) + ", " +
           std::to_string(t.y) + ", " + std::to_string(t.z) + ", " + std::to_string(t.w) +
           "); glTF needs a finite xyz and w = 1 or -1 (the bitangent's handedness)");
  }

  std::vector<uint32_t> indices;
  if (primitive.indices >= 0) {
    indices = readAccessor<uint32_t>(primitive.indices, where + " indices", TINYGLTF_TYPE_SCALAR,
                                     Components::Index);
    for (size_t i = 0; i < indices.size(); ++i) {
      if (indices[i] >= vertexCount) {
        fail(where + " has index " + std::to_string(indices[i]) + " at position " + std::to_string(i) +
             ", but only " + std::to_string(vertexCount) + " vertices. The file is corrupt; re-export it.");
      }
    }
  } else {
    indices.resize(vertexCount);
    std::iota(indices.begin(), indices.end(), 0u);
  }
  const std::vector<uint32_t> triangles = toTriangleList(primitive.mode, indices, where);
  if (triangles.empty()) {
    warn(where + " has no complete triangle, so it is skipped");
    return;
  }

  // glTF: a primitive without normals is shaded flat, so every triangle gets its own vertices.
  const size_t addedVertices = normals.empty() ? triangles.size() : vertexCount;
  if (scene_.vertices.size() + addedVertices > std::numeric_limits<uint32_t>::max() ||
      scene_.indices.size() + triangles.size() > std::numeric_limits<uint32_t>::max()) {
    fail("has more than 2^32 vertices or indices in total, beyond what 32-bit indices can address");
  }
  Primitive out;
  out.firstIndex = uint32_t(scene_.indices.size());
  out.indexCount = uint32_t(triangles.size());
  out.vertexOffset = uint32_t(scene_.vertices.size());
  out.material = materialFor(primitive.material, where);
  auto vertex = [&](uint32_t i) {
    Vertex v{};
    v.position = glm::make_vec3(&positions[size_t(i) * 3]);
    if (!normals.empty()) v.normal = glm::make_vec3(&normals[size_t(i) * 3]);
    if (!uvs.empty()) v.uv = glm::make_vec2(&uvs[size_t(i) * 2]);
    if (!tangents.empty()) v.tangent = glm::make_vec4(&tangents[size_t(i) * 4]);
    if (!uvs1.empty()) v.uv1 = glm::make_vec2(&uvs1[size_t(i) * 2]);
    // glTF colours lie in [0, 1]; half floats hold them to 1/2048.
    if (!colors.empty()) v.setColor(glm::clamp(glm::make_vec4(&colors[size_t(i) * 4]), 0.0f, 1.0f));
    return v;
  };
  if (!normals.empty()) {
    for (uint32_t i = 0; i < vertexCount; ++i) scene_.vertices.push_back(vertex(i));
    scene_.indices.insert(scene_.indices.end(), triangles.begin(), triangles.end());
  } else {
    for (size_t t = 0; t < triangles.size(); t += 3) {
      Vertex corners[3] = {vertex(triangles[t]), vertex(triangles[t + 1]), vertex(triangles[t + 2])};
      const glm::vec3 normal = unitOr(glm::cross(glm::dvec3(corners[1].position - corners[0].position),
                                                 glm::dvec3(corners[2].position - corners[0].position)),
                                      glm::vec3(0.0f, 0.0f, 1.0f));
      for (Vertex& corner : corners) {
        corner.normal = normal;
        scene_.indices.push_back(uint32_t(scene_.vertices.size()) - out.vertexOffset);
        scene_.vertices.push_back(corner);
      }
    }
  }
  mesh.primitives.push_back(out);
}

std::vector<uint32_t> GltfImporter::toTriangleList(int mode, const std::vector<uint32_t>& indices,
                                                   const std::string& where) {
  std::vector<uint32_t> triangles;
  if (mode == TINYGLTF_MODE_TRIANGLES) {
    const size_t extra = indices.size() % 3;
    if (extra != 0)
      warn(where + " has " + std::to_string(extra) + " indices after its last triangle; ignored");
    triangles.assign(indices.begin(), indices.end() - std::ptrdiff_t(extra));
    return triangles;
  }
  if (indices.size() < 3) return triangles;
  triangles.reserve((indices.size() - 2) * 3);
  for (size_t i = 0; i + 2 < indices.size(); ++i) {
    if (mode == TINYGLTF_MODE_TRIANGLE_STRIP) {
      // Every other strip triangle swaps its first two corners to keep the winding consistent.
      const size_t odd = i % 2;
      triangles.insert(triangles.end(), {indices[i + odd], indices[i + 1 - odd], indices[i + 2]});
    } else {
      triangles.insert(triangles.end(), {indices[i + 1], indices[i + 2], indices[0]});
    }
  }
  return triangles;
}

uint32_t GltfImporter::materialFor(int material, const std::string& where) {
  if (material >= 0) {
    if (size_t(material) >= model_.materials.size()) {
      fail(where + " uses material " + std::to_string(material) + ", but the file has " +
           std::to_string(model_.materials.size()) + " materials");
    }
    return uint32_t(material);
  }
  if (!defaultMaterial_) {
    Material fallback;  // the glTF default material: white, metallic 1, roughness 1
    fallback.name = "gltf-default-material";
    scene_.materials.push_back(fallback);
    defaultMaterial_ = uint32_t(scene_.materials.size() - 1);
  }
  return *defaultMaterial_;
}

void GltfImporter::placeNodes() {
  std::vector<int> roots;
  if (model_.defaultScene >= 0) {
    if (size_t(model_.defaultScene) >= model_.scenes.size()) {
      fail("its default scene is " + std::to_string(model_.defaultScene) + ", but the file has " +
           std::to_string(model_.scenes.size()) + " scenes");
    }
    roots = model_.scenes[size_t(model_.defaultScene)].nodes;
  } else if (!model_.scenes.empty()) {
    roots = model_.scenes[0].nodes;
  } else {
    std::vector<bool> isChild(model_.nodes.size(), false);
    for (const tinygltf::Node& node : model_.nodes) {
      for (int child : node.children) {
        if (child >= 0 && size_t(child) < isChild.size()) isChild[size_t(child)] = true;
      }
    }
    for (size_t i = 0; i < model_.nodes.size(); ++i) {
      if (!isChild[i]) roots.push_back(int(i));
    }
  }

  // Depth-first with an explicit stack: a deep chain of nodes must not overflow the call stack.
  // Skinned meshes are placed after it, once every joint's world transform is known.
  std::vector<bool> visited(model_.nodes.size(), false);
  std::vector<glm::dmat4> worlds(model_.nodes.size(), glm::dmat4(1.0));
  std::vector<int> skinned;
  std::vector<std::pair<int, glm::dmat4>> stack;
  for (auto root = roots.rbegin(); root != roots.rend(); ++root) stack.emplace_back(*root, glm::dmat4(1.0));
  while (!stack.empty()) {
    const auto [index, parentWorld] = stack.back();
    stack.pop_back();
    if (index < 0 || size_t(index) >= model_.nodes.size()) {
      fail("refers to node " + std::to_string(index) + ", but the file has " +
           std::to_string(model_.nodes.size()) + " nodes");
    }
    if (visited[size_t(index)]) {
      fail("node " + std::to_string(index) +
           " is reached twice (a cycle, or a node with two parents); glTF nodes must form trees");
    }
    visited[size_t(index)] = true;
    const tinygltf::Node& node = model_.nodes[size_t(index)];
    const glm::dmat4 world = parentWorld * localTransform(node, index);
    checkFiniteMatrix(glm::mat4(world), file_, "node " + std::to_string(index) + "'s world transform");
    worlds[size_t(index)] = world;
    if (node.mesh >= 0) {
      if (size_t(node.mesh) >= model_.meshes.size()) {
        fail("node " + std::to_string(index) + " uses mesh " + std::to_string(node.mesh) +
             ", but the file has " + std::to_string(model_.meshes.size()) + " meshes");
      }
      const std::vector<glm::dmat4> instances = instanceTransforms(node, index);
      if (node.skin >= 0) {
        if (!instances.empty())
          warn("node " + std::to_string(index) +
               " is skinned and instanced (EXT_mesh_gpu_instancing); "
               "only its one skinned copy is drawn");
        skinned.push_back(index);
      } else if (instances.empty()) {
        placeMesh(meshWithWeights(node, index), glm::mat4(world), index);
      } else {
        const uint32_t mesh = meshWithWeights(node, index);
        for (const glm::dmat4& instance : instances) placeMesh(mesh, glm::mat4(world * instance), index);
      }
    }
    if (node.camera >= 0) addCamera(node.camera, index, world);
    addLight(node, index, world);
    for (auto child = node.children.rbegin(); child != node.children.rend(); ++child) {
      stack.emplace_back(*child, world);
    }
  }
  for (int index : skinned) placeSkinnedMesh(index, worlds, visited);
}

// Every placed vertex must have coordinates whose squares are finite floats (distances, the far
// plane); a node scaled or moved too far would give an infinite projection and NaN pixels.
void GltfImporter::placeMesh(uint32_t mesh, const glm::mat4& world, int node) {
  if (scene_.instances.size() >= limits_.instances)
    fail("node " + std::to_string(node) + " places a mesh past the " + std::to_string(limits_.instances) +
         " placements accepted (nodes and EXT_mesh_gpu_instancing copies together)");
  auto known = meshBounds_.find(mesh);
  if (known == meshBounds_.end()) known = meshBounds_.emplace(mesh, scene_.meshBounds(mesh)).first;
  const Bounds placed = transformBounds(known->second, world);
  const float largest = glm::max(glm::compMax(glm::abs(placed.min)), glm::compMax(glm::abs(placed.max)));
  if (placed.valid() && !(largest <= kMaxWorldCoordinate))
    fail("node " + std::to_string(node) + " places mesh " + std::to_string(mesh) + " at coordinates up to " +
         fmt::format("{}", largest) + " m, beyond the " + fmt::format("{}", kMaxWorldCoordinate) +
         " m the renderer's 32-bit arithmetic takes");
  // glTF: a node whose world transform mirrors (negative determinant) winds its fronts clockwise.
  if (glm::determinant(glm::mat3(world)) < 0.0f) {
    auto reversed = reversedMeshes_.find(mesh);
    if (reversed == reversedMeshes_.end()) {
      uint64_t indices = scene_.indices.size();
      for (const Primitive& p : scene_.meshes[mesh].primitives) indices += p.indexCount;
      if (indices > std::numeric_limits<uint32_t>::max())
        fail("node " + std::to_string(node) + " mirrors mesh " + std::to_string(mesh) +
             ", whose reversed copy would take the scene past 2^32 indices");
      reversed = reversedMeshes_.emplace(mesh, addReversedWindingMesh(scene_, mesh)).first;
    }
    mesh = reversed->second;
  }
  scene_.instances.push_back({mesh, world});
}

glm::dmat4 GltfImporter::localTransform(const tinygltf::Node& node, int index) const {
  const std::string name = "node " + std::to_string(index);
  for (const auto& [values, what] :
       {std::pair(&node.matrix, " matrix"), std::pair(&node.translation, " translation"),
        std::pair(&node.rotation, " rotation"), std::pair(&node.scale, " scale")})
    for (size_t i = 0; i < values->size(); ++i)
      numbers_.finite((*values)[i], name + what + "[" + std::to_string(i) + "]");
  if (!node.matrix.empty()) {
    if (node.matrix.size() != 16)
      fail(name + " has a matrix of " + std::to_string(node.matrix.size()) + " numbers, not 16");
    return glm::make_mat4(node.matrix.data());  // glTF matrices are column-major, like glm's
  }
  auto checkSize = [&](const std::vector<double>& values, size_t expected, const char* what) {
    if (!values.empty() && values.size() != expected) {
      fail(name + " has a " + what + " of " + std::to_string(values.size()) + " numbers, not " +
           std::to_string(expected));
    }
  };
  checkSize(node.translation, 3, "translation");
  checkSize(node.rotation, 4, "rotation");
  checkSize(node.scale, 3, "scale");
  glm::dmat4 transform(1.0);
  if (!node.translation.empty())
    transform = glm::translate(transform, glm::make_vec3(node.translation.data()));
  if (!node.rotation.empty()) {
    const glm::dquat rotation(node.rotation[3], node.rotation[0], node.rotation[1], node.rotation[2]);
    const double length = glm::length(rotation);
    if (!(length > 1e-12)) fail(name + " has a rotation of zero length; glTF requires a unit quaternion");
    transform *= glm::mat4_cast(rotation / length);
  }
  if (!node.scale.empty()) transform = glm::scale(transform, glm::make_vec3(node.scale.data()));
  return transform;
}

void GltfImporter::addLight(const tinygltf::Node& node, int nodeIndex, const glm::dmat4& world) {
  const auto extension = node.extensions.find("KHR_lights_punctual");
  if (extension == node.extensions.end()) return;
  const tinygltf::Value& lightIndex = extension->second.Get("light");
  const int index = lightIndex.IsNumber() ? lightIndex.GetNumberAsInt() : -1;
  if (index < 0 || size_t(index) >= model_.lights.size()) {
    fail("node " + std::to_string(nodeIndex) + " refers to KHR_lights_punctual light " +
         std::to_string(index) + ", but the file defines " + std::to_string(model_.lights.size()) +
         " lights");
  }
  const tinygltf::Light& in = model_.lights[size_t(index)];
  const std::string name = "light " + (in.name.empty() ? std::to_string(index) : inQuotes(in.name));
  if (in.type == "directional") {
    addDirectionalLight(in, name, world);
    return;
  }
  if (in.type != "point" && in.type != "spot") {
    warn(name + " is of type '" + in.type +
         "'; only point, spot and directional lights are supported, so it is "
         "skipped");
    return;
  }
  Light out;
  out.type = in.type == "spot" ? LightType::Spot : LightType::Point;
  out.position = glm::vec3(world * glm::dvec4(0.0, 0.0, 0.0, 1.0));
  out.direction = unitOr(glm::dmat3(world) * glm::dvec3(0.0, 0.0, -1.0), glm::vec3(0.0f, 0.0f, -1.0f));
  if (!in.color.empty())
    out.color = glm::make_vec3(numbers_.clampedArray(in.color, 3, 0.0, 1.0, name + " color").data());
  out.intensity = numbers_.atLeast(in.intensity, 0.0, name + " intensity");
  if (out.intensity > kMaxLightIntensity)
    fail(name + " has intensity " + std::to_string(out.intensity) + " cd, above the " +
         std::to_string(kMaxLightIntensity) + " the renderer's 32-bit shading can take without overflow");
  // tinygltf stores an absent range as 0, which the extension forbids as a value.
  const float range = numbers_.atLeast(in.range, 0.0, name + " range");
  out.range = range > 0.0f ? range : rangeForUnboundedLight(out.intensity, out.color);
  if (out.type == LightType::Spot) {
    constexpr double kHalfPi = 1.5707963267948966;
    const double outer = std::clamp(in.spot.outerConeAngle, 1e-4, kHalfPi);
    const double inner = std::clamp(in.spot.innerConeAngle, 0.0, outer);
    if (outer != in.spot.outerConeAngle || inner != in.spot.innerConeAngle) {
      warn(name + " has cone angles outside 0 <= inner <= outer <= pi/2; clamped");
    }
    out.innerConeAngle = float(inner);
    out.outerConeAngle = float(outer);
  }
  scene_.lights.push_back(out);
}

// The sun: along the node's -Z; "intensity" is its illuminance in lux.
void GltfImporter::addDirectionalLight(const tinygltf::Light& in, const std::string& name,
                                       const glm::dmat4& world) {
  if (scene_.directionalLights.size() >= gpu::kMaxDirectionalLights) {
    warn(name + " is a directional light past the " + std::to_string(gpu::kMaxDirectionalLights) +
         " the renderer takes; it is skipped");
    return;
  }
  DirectionalLight out;
  out.name = name;
  out.direction = unitOr(glm::dmat3(world) * glm::dvec3(0.0, 0.0, -1.0), glm::vec3(0.0f, -1.0f, 0.0f));
  if (!in.color.empty())
    out.color = glm::make_vec3(numbers_.clampedArray(in.color, 3, 0.0, 1.0, name + " color").data());
  out.illuminance = numbers_.atLeast(in.intensity, 0.0, name + " intensity");
  if (out.illuminance > kMaxLightIntensity)
    fail(name + " has intensity " + std::to_string(out.illuminance) + " lux, above the " +
         std::to_string(kMaxLightIntensity) + " the renderer's 32-bit shading can take without overflow");
  scene_.directionalLights.push_back(out);
}

void GltfImporter::addCamera(int cameraIndex, int nodeIndex, const glm::dmat4& world) {
  if (size_t(cameraIndex) >= model_.cameras.size()) {
    fail("node " + std::to_string(nodeIndex) + " uses camera " + std::to_string(cameraIndex) +
         ", but the file has " + std::to_string(model_.cameras.size()) + " cameras");
  }
  const tinygltf::Camera& in = model_.cameras[size_t(cameraIndex)];
  Camera out;
  out.name = in.name.empty() ? "gltf-camera-" + std::to_string(cameraIndex) : in.name;
  if (in.type != "perspective") {
    warn("camera " + inQuotes(out.name) + " is " + in.type +
         "; only perspective cameras are supported, so it is skipped");
    return;
  }
  const float yfov = numbers_.finite(in.perspective.yfov, "camera " + inQuotes(out.name) + " yfov");
  if (!(yfov > 0.0f && yfov < 3.14159f))
    fail("camera " + inQuotes(out.name) + " has yfov " + fmt::format("{}", in.perspective.yfov) +
         (yfov == 0.0f ? ", which is 0 as a 32-bit float" : "") + "; it must be between 0 and pi");
  const glm::dmat3 rotation(world);
  out.eye = glm::vec3(world * glm::dvec4(0.0, 0.0, 0.0, 1.0));
  out.target = out.eye + unitOr(rotation * glm::dvec3(0.0, 0.0, -1.0), glm::vec3(0.0f, 0.0f, -1.0f));
  out.up = unitOr(rotation * glm::dvec3(0.0, 1.0, 0.0), glm::vec3(0.0f, 1.0f, 0.0f));
  out.yfov = yfov;
  scene_.cameras.push_back(out);
}

void GltfImporter::warnAboutIgnoredData() {
  if (!ignoredAttributes_.empty()) {
    warn("vertex attribute(s) " + describeList(ignoredAttributes_) +
         " are ignored; only POSITION, NORMAL, TANGENT, TEXCOORD_0, TEXCOORD_1 and COLOR_0 are used");
  }
  if (usesOtherTexCoords_)
    warn("some textures use a texCoord other than 0 and 1; TEXCOORD_0 is used for them");
  if (!ignoredTargetAttributes_.empty())
    warn("morph target attribute(s) " + describeList(ignoredTargetAttributes_) +
         " are ignored; only POSITION, NORMAL and TANGENT targets are applied");
  if (!model_.animations.empty()) warn("animations are ignored; the scene is drawn in its rest pose");
}

}  // namespace lll::gltf_detail

namespace lll {

Scene loadGltf(const std::filesystem::path& file, LoadReport* report, const GltfLimits& limits) {
  gltf_detail::GltfImporter importer(file, limits);
  Scene scene = importer.run();
  if (report != nullptr) {
    for (std::string& warning : importer.takeWarnings()) report->warnings.push_back(std::move(warning));
  }
  return scene;
}

}  // namespace lll
