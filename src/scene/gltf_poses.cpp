// Posing glTF meshes for the loader (scene/gltf_importer.h): morph targets at their default weights,
// skins at the rest pose of their joints, and EXT_mesh_gpu_instancing's copies. A pose that a node
// gives its mesh alone (its own weights, a skin) is a copy of the mesh, counted against
// GltfLimits::posedVertices before it is made.
#include <fmt/format.h>

#include <algorithm>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>
#include <glm/gtc/type_ptr.hpp>
#include <limits>
#include <tuple>

#include "scene/gltf_importer.h"

namespace lll::gltf_detail {

// glTF morph targets at `weights` (a node's, else its mesh's; without any the base shape): each
// target's POSITION, NORMAL and TANGENT displacements, times its weight, added to the base.
void GltfImporter::applyMorphTargets(const tinygltf::Primitive& primitive, const std::string& where,
                                     const std::vector<double>& weights, std::vector<float>& positions,
                                     std::vector<float>& normals, std::vector<float>& tangents) {
  if (primitive.targets.empty()) return;
  if (!weights.empty() && weights.size() != primitive.targets.size())
    fail(where + " has " + std::to_string(primitive.targets.size()) + " morph targets but " +
         std::to_string(weights.size()) + " weights; glTF needs one weight per target");
  for (size_t t = 0; t < primitive.targets.size(); ++t) {
    const std::string target = where + " morph target " + std::to_string(t);
    const float weight = t < weights.size() ? numbers_.finite(weights[t], target + "'s weight") : 0.0f;
    for (const auto& [attribute, accessor] : primitive.targets[t]) {
      const bool position = attribute == "POSITION";
      std::vector<float>* base = position                 ? &positions
                                 : attribute == "NORMAL"  ? &normals
                                 : attribute == "TANGENT" ? &tangents
                                                          : nullptr;
      if (base == nullptr) {
        ignoredTargetAttributes_.insert(attribute);
        continue;
      }
      if (weight == 0.0f || base->empty()) continue;    // nothing to move, or no base to move
      const size_t stride = base == &tangents ? 4 : 3;  // a tangent's w (handedness) stays
      const std::vector<float> delta =
          readAccessor<float>(accessor, target + " " + attribute, TINYGLTF_TYPE_VEC3,
                              !quantized_ ? Components::Float
                              : position  ? Components::QuantizedPosition
                                          : Components::QuantizedDirection);
      checkFinite(delta, target + " " + attribute);
      if (delta.size() / 3 != base->size() / stride)
        fail(target + "'s " + attribute + " has " + std::to_string(delta.size() / 3) + " elements, but the " +
             "primitive has " + std::to_string(base->size() / stride) + " vertices");
      for (size_t i = 0; i < delta.size() / 3; ++i)
        for (size_t c = 0; c < 3; ++c) (*base)[i * stride + c] += weight * delta[i * 3 + c];
    }
  }
}

// glTF skinning at the rest pose: each vertex moved by the blend of its joints' matrices
// (`joints`: each joint's world transform times its inverse bind matrix), weighted by WEIGHTS_n
// for JOINTS_n (sets 0 and 1, four joints each). The result is in world space: a skinned mesh's
// own node transform does not apply.
void GltfImporter::applySkin(const tinygltf::Primitive& primitive, const std::string& where,
                             const std::vector<glm::dmat4>& joints, std::vector<float>& positions,
                             std::vector<float>& normals, std::vector<float>& tangents) {
  const size_t vertexCount = positions.size() / 3;
  std::vector<glm::dmat4> blend(vertexCount, glm::dmat4(0.0));
  std::vector<double> sums(vertexCount, 0.0);
  std::vector<uint32_t> firstJoint(vertexCount, 0);
  bool any = false;
  for (int set = 0; set < 2; ++set) {
    const std::string jointsName = "JOINTS_" + std::to_string(set),
                      weightsName = "WEIGHTS_" + std::to_string(set);
    const auto jointAccessor = primitive.attributes.find(jointsName);
    const auto weightAccessor = primitive.attributes.find(weightsName);
    if (jointAccessor == primitive.attributes.end() && weightAccessor == primitive.attributes.end()) continue;
    if (jointAccessor == primitive.attributes.end() || weightAccessor == primitive.attributes.end())
      fail(where + " has only one of " + jointsName + " and " + weightsName + "; skinning needs both");
    const std::vector<uint32_t> indices = readAccessor<uint32_t>(
        jointAccessor->second, where + " " + jointsName, TINYGLTF_TYPE_VEC4, Components::Index);
    const std::vector<float> weights =
        readAccessor<float>(weightAccessor->second, where + " " + weightsName, TINYGLTF_TYPE_VEC4,
                            Components::FloatOrNormalizedUnsigned);
    checkFinite(weights, where + " " + weightsName);
    if (indices.size() != vertexCount * 4 || weights.size() != vertexCount * 4)
      fail(where + " has " + jointsName + " or " + weightsName + " with a different count than POSITION (" +
           std::to_string(vertexCount) + ")");
    for (size_t i = 0; i < indices.size(); ++i) {
      if (indices[i] >= joints.size())
        fail(where + " has " + jointsName + " " + std::to_string(indices[i]) + " at vertex " +
             std::to_string(i / 4) + ", but its skin has " + std::to_string(joints.size()) + " joints");
      if (set == 0 && i % 4 == 0) firstJoint[i / 4] = indices[i];
      if (weights[i] == 0.0f) continue;
      blend[i / 4] += double(weights[i]) * joints[indices[i]];
      sums[i / 4] += double(weights[i]);
    }
    any = true;
  }
  if (!any) fail(where + " is skinned (its node has a skin) but has no JOINTS_0 and WEIGHTS_0");
  for (size_t v = 0; v < vertexCount; ++v) {
    // glTF's weights sum to 1; exporters round them, so they are normalized. A vertex with none
    // follows its first joint.
    const glm::dmat4 m = sums[v] > 1e-8 ? blend[v] / sums[v] : joints[firstJoint[v]];
    const glm::dvec3 p = glm::dvec3(m * glm::dvec4(glm::dvec3(glm::make_vec3(&positions[v * 3])), 1.0));
    for (int c = 0; c < 3; ++c) positions[v * 3 + c] = float(p[c]);
    const glm::dmat3 linear(m);
    if (!normals.empty()) {
      const glm::dvec3 n = glm::transpose(glm::inverse(linear)) * glm::dvec3(glm::make_vec3(&normals[v * 3]));
      for (int c = 0; c < 3; ++c) normals[v * 3 + c] = float(n[c]);
    }
    if (!tangents.empty()) {
      const glm::dvec3 t = linear * glm::dvec3(glm::make_vec3(&tangents[v * 4]));
      for (int c = 0; c < 3; ++c) tangents[v * 4 + c] = float(t[c]);
    }
  }
}

// EXT_mesh_gpu_instancing: the transforms (translation x rotation x scale, in the node's frame) of
// the copies of its mesh that node `index` draws; none where the node has no such extension.
std::vector<glm::dmat4> GltfImporter::instanceTransforms(const tinygltf::Node& node, int index) {
  const auto found = node.extensions.find("EXT_mesh_gpu_instancing");
  if (found == node.extensions.end()) return {};
  const std::string where = "node " + std::to_string(index) + "'s EXT_mesh_gpu_instancing";
  const tinygltf::Value& e = found->second;
  if (!e.IsObject() || !e.Has("attributes") || !e.Get("attributes").IsObject())
    fail(where + " has no attributes object");
  const tinygltf::Value& attributes = e.Get("attributes");
  std::vector<float> translations, rotations, scales;
  for (const std::string& name : attributes.Keys()) {
    const int accessor = int(std::min<uint64_t>(unsignedMember(attributes, name.c_str(), 0, file_, where),
                                                uint64_t(std::numeric_limits<int>::max())));
    const std::string what = where + " " + name;
    if (name == "TRANSLATION") {
      translations = readAccessor<float>(accessor, what, TINYGLTF_TYPE_VEC3,
                                         quantized_ ? Components::QuantizedPosition : Components::Float);
      checkFinite(translations, what);
    } else if (name == "ROTATION") {  // unit quaternions, x y z w; normalized integers allowed
      rotations = readAccessor<float>(accessor, what, TINYGLTF_TYPE_VEC4, Components::QuantizedDirection);
      checkFinite(rotations, what);
    } else if (name == "SCALE") {
      scales = readAccessor<float>(accessor, what, TINYGLTF_TYPE_VEC3,
                                   quantized_ ? Components::QuantizedPosition : Components::Float);
      checkFinite(scales, what);
    } else if (name.rfind('_', 0) != 0) {  // "_ID" and the like are applications' own
      warn(what + " is not an attribute the extension defines; it is ignored");
    }
  }
  const size_t count = std::max({translations.size() / 3, rotations.size() / 4, scales.size() / 3});
  if (count == 0) fail(where + " has none of TRANSLATION, ROTATION and SCALE");
  if ((!translations.empty() && translations.size() / 3 != count) ||
      (!rotations.empty() && rotations.size() / 4 != count) ||
      (!scales.empty() && scales.size() / 3 != count))
    fail(where + "'s TRANSLATION, ROTATION and SCALE have different counts; each gives one per instance");
  std::vector<glm::dmat4> out;
  out.reserve(count);
  for (size_t i = 0; i < count; ++i) {
    glm::dmat4 m(1.0);
    if (!translations.empty()) m = glm::translate(m, glm::dvec3(glm::make_vec3(&translations[i * 3])));
    if (!rotations.empty()) {
      const float* q = &rotations[i * 4];
      const glm::dquat rotation(q[3], q[0], q[1], q[2]);  // glm: w first
      const double length = glm::length(rotation);
      if (!(length > 1e-6)) fail(where + " ROTATION " + std::to_string(i) + " is not a unit quaternion");
      m *= glm::mat4_cast(rotation / length);
    }
    if (!scales.empty()) m = glm::scale(m, glm::dvec3(glm::make_vec3(&scales[i * 3])));
    out.push_back(m);
  }
  return out;
}

// Counts the vertices of a posed copy (morphed by a node's weights, or skinned) of mesh `mesh` for
// node `node` against the limit (GltfLimits::posedVertices), before it is made.
void GltfImporter::reservePosedCopy(int mesh, int node) {
  uint64_t vertices = 0;
  for (const tinygltf::Primitive& p : model_.meshes[size_t(mesh)].primitives) {
    const auto position = p.attributes.find("POSITION");
    if (position != p.attributes.end() && position->second >= 0 &&
        size_t(position->second) < model_.accessors.size())
      vertices += model_.accessors[size_t(position->second)].count;
  }
  posedVertices_ += vertices;
  if (posedVertices_ > limits_.posedVertices)
    fail("node " + std::to_string(node) + " needs a posed copy of mesh " + std::to_string(mesh) +
         " (its own morph weights or a skin), which takes the scene's posed copies to " +
         std::to_string(posedVertices_) + " vertices, more than the " +
         std::to_string(limits_.posedVertices) + " accepted");
}

// A skinned mesh at the rest pose of its joints (their node transforms, as the scene places them):
// one copy of the mesh for each (mesh, weights, skin), in world space.
void GltfImporter::placeSkinnedMesh(int index, const std::vector<glm::dmat4>& worlds,
                                    const std::vector<bool>& visited) {
  const tinygltf::Node& node = model_.nodes[size_t(index)];
  const std::string name = "node " + std::to_string(index);
  if (size_t(node.skin) >= model_.skins.size())
    fail(name + " uses skin " + std::to_string(node.skin) + ", but the file has " +
         std::to_string(model_.skins.size()) + " skins");
  const tinygltf::Skin& skin = model_.skins[size_t(node.skin)];
  const std::vector<double>& weights =
      node.weights.empty() ? model_.meshes[size_t(node.mesh)].weights : node.weights;
  const auto key = std::make_tuple(node.mesh, weights, node.skin);
  auto known = skinnedMeshes_.find(key);
  if (known == skinnedMeshes_.end()) {
    const std::string where = "skin " + std::to_string(node.skin);
    if (skin.joints.empty()) fail(where + " has no joints; glTF requires at least one");
    std::vector<float> inverseBinds;
    if (skin.inverseBindMatrices >= 0) {
      inverseBinds = readAccessor<float>(skin.inverseBindMatrices, where + " inverseBindMatrices",
                                         TINYGLTF_TYPE_MAT4, Components::Float);
      checkFinite(inverseBinds, where + " inverseBindMatrices");
      if (inverseBinds.size() != skin.joints.size() * 16)
        fail(where + " has " + std::to_string(inverseBinds.size() / 16) + " inverse bind matrices for " +
             std::to_string(skin.joints.size()) + " joints; glTF needs one per joint");
    }
    std::vector<glm::dmat4> joints;
    for (size_t j = 0; j < skin.joints.size(); ++j) {
      const int joint = skin.joints[j];
      if (joint < 0 || size_t(joint) >= model_.nodes.size() || !visited[size_t(joint)])
        fail(where + "'s joint " + std::to_string(j) + " is node " + std::to_string(joint) +
             ", which is not in the scene drawn; glTF places a skin's joints in its mesh's scene");
      const glm::dmat4 inverseBind =
          inverseBinds.empty() ? glm::dmat4(1.0) : glm::dmat4(glm::make_mat4(&inverseBinds[j * 16]));
      joints.push_back(worlds[size_t(joint)] * inverseBind);
    }
    reservePosedCopy(node.mesh, index);
    scene_.meshes.push_back(convertMesh(node.mesh, weights, &joints));
    known = skinnedMeshes_.emplace(key, uint32_t(scene_.meshes.size() - 1)).first;
  }
  placeMesh(known->second, glm::mat4(1.0f), index);
}

// The scene mesh node `node` shows: its glTF mesh, or, where the node gives morph weights of its
// own, a copy of the mesh morphed by them (one for each distinct set of weights).
uint32_t GltfImporter::meshWithWeights(const tinygltf::Node& node, int index) {
  const tinygltf::Mesh& mesh = model_.meshes[size_t(node.mesh)];
  const bool targets = std::any_of(mesh.primitives.begin(), mesh.primitives.end(),
                                   [](const tinygltf::Primitive& p) { return !p.targets.empty(); });
  if (!targets || node.weights.empty() || node.weights == mesh.weights) return uint32_t(node.mesh);
  const auto key = std::make_pair(node.mesh, node.weights);
  auto known = morphedMeshes_.find(key);
  if (known == morphedMeshes_.end()) {
    reservePosedCopy(node.mesh, index);
    scene_.meshes.push_back(convertMesh(node.mesh, node.weights));
    known = morphedMeshes_.emplace(key, uint32_t(scene_.meshes.size() - 1)).first;
  }
  return known->second;
}

}  // namespace lll::gltf_detail
