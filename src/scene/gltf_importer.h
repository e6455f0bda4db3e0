#pragma once
// Private to the glTF loader: the importer, whose work is split between gltf_loader.cpp (the file,
// its extensions, meshes, nodes, lights and cameras) and gltf_materials.cpp (materials, their
// textures and images). tiny_gltf.h comes in for its declarations (gltf_accessors.h); its
// implementation is gltf_loader.cpp's.
#include "scene/gltf_accessors.h"
#include "scene/gltf_loader.h"
#include "scene/gltf_numbers.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <glm/glm.hpp>
#include <map>
#include <optional>
#include <set>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include "core/errors.h"
#include "scene/scene.h"

namespace lll::gltf_detail {

inline std::string inQuotes(const std::string& name) {
  return "'" + name + "'";
}

class GltfImporter {
 public:
  GltfImporter(const std::filesystem::path& file, const GltfLimits& limits)
      : path_(file), file_(file.string()), limits_(limits) {}

  Scene run();

  std::vector<std::string> takeWarnings() { return std::move(warnings_); }

 private:
  struct DecodedImage {
    bool attempted = false;
    std::string failure;  // why it could not be used; empty once decoded
    uint32_t width = 0;
    uint32_t height = 0;
    std::vector<uint8_t> rgba;
    uint32_t textures = 0;  // Scene textures made of it (one per colour space and sampler)
  };

  [[noreturn]] void fail(const std::string& what) const { throw InputError(file_ + ": " + what); }
  void warn(const std::string& what) { warnings_.push_back(file_ + ": " + what); }

  void parse();
  void checkVersionAndExtensions();
  void checkBufferViews() const { gltf_detail::checkBufferViews(model_, file_); }
  void checkFinite(const std::vector<float>& values, const std::string& what) const {
    const auto bad = std::find_if(values.begin(), values.end(), [](float x) { return !std::isfinite(x); });
    if (bad != values.end())
      fail(what + " has a component that is infinite or NaN (" + std::to_string(*bad) + " at component " +
           std::to_string(bad - values.begin()) + ")");
  }
  template <typename T>
  std::vector<T> readAccessor(int index, const std::string& what, int type, Components allowed) const {
    return gltf_detail::readAccessor<T>(model_, file_, index, what, type, allowed);
  }

  Material convertMaterial(const tinygltf::Material& in, int index);
  // A texture's KHR_texture_transform; its texCoord, where it gives one, replaces `texCoord`.
  TextureTransform textureTransform(const tinygltf::ExtensionMap& extensions, const std::string& what,
                                    int& texCoord);
  // The texture that `info` names for `material`'s `slot` (-1: none, or a neutral one), with the
  // slot's transform and texture coordinates set in `material`; `name` names the slot in messages.
  template <typename Info>
  int textureFor(const Info& info, bool srgb, const char* name, TextureSlot slot, Material& material);
  // The image glTF texture `texture` shows: EXT_texture_webp's where it has one, else its source.
  int textureSource(int texture);
  // glTF sampler `index` (-1: the default) as the renderer's.
  TextureSampler textureSampler(int index);
  const DecodedImage& decodeImage(int index);
  // False, with `decoded`'s failure set, where a width x height image is past the size we accept
  // alone or, with the images decoded before, together; otherwise counts it.
  bool withinTextureBounds(int width, int height, DecodedImage& decoded);
  std::string imageName(int index) const;

  // Mesh `index` with its morph targets at `weights`.
  // Mesh `index` with its morph targets at `weights` and, given `joints` (a skin's joint
  // matrices), skinned into world space.
  Mesh convertMesh(int index, const std::vector<double>& weights,
                   const std::vector<glm::dmat4>* joints = nullptr);
  void convertPrimitive(const tinygltf::Primitive& primitive, const std::string& where,
                        const std::vector<double>& weights, const std::vector<glm::dmat4>* joints,
                        Mesh& mesh);
  void applySkin(const tinygltf::Primitive& primitive, const std::string& where,
                 const std::vector<glm::dmat4>& joints, std::vector<float>& positions,
                 std::vector<float>& normals, std::vector<float>& tangents);
  void placeSkinnedMesh(int index, const std::vector<glm::dmat4>& worlds, const std::vector<bool>& visited);
  std::vector<glm::dmat4> instanceTransforms(const tinygltf::Node& node, int index);
  void reservePosedCopy(int mesh, int node);
  void applyMorphTargets(const tinygltf::Primitive& primitive, const std::string& where,
                         const std::vector<double>& weights, std::vector<float>& positions,
                         std::vector<float>& normals, std::vector<float>& tangents);
  uint32_t meshWithWeights(const tinygltf::Node& node, int index);
  std::vector<uint32_t> toTriangleList(int mode, const std::vector<uint32_t>& indices,
                                       const std::string& where);
  uint32_t materialFor(int material, const std::string& where);

  void placeNodes();
  void placeMesh(uint32_t mesh, const glm::mat4& world, int node);
  glm::dmat4 localTransform(const tinygltf::Node& node, int index) const;
  void addLight(const tinygltf::Node& node, int nodeIndex, const glm::dmat4& world);
  void addCamera(int cameraIndex, int nodeIndex, const glm::dmat4& world);
  void addDirectionalLight(const tinygltf::Light& in, const std::string& name, const glm::dmat4& world);
  void warnAboutIgnoredData();

  std::filesystem::path path_;
  std::string file_;
  tinygltf::Model model_;
  Scene scene_;
  std::vector<std::string> warnings_;
  gltf_detail::NumberReader numbers_{file_, warnings_};
  std::vector<DecodedImage> images_;  // per glTF image, decoded on first use
  uint64_t decodedTexels_ = 0;        // over images_
  GltfLimits limits_;
  // (glTF image, srgb, glTF sampler) -> Scene::textures
  std::map<std::tuple<int, bool, int>, int> textureIndex_;
  std::optional<uint32_t> defaultMaterial_;
  std::map<uint32_t, Bounds> meshBounds_;        // object-space bounds of each placed mesh
  std::map<uint32_t, uint32_t> reversedMeshes_;  // a mesh's reversed copy, for mirroring nodes
  std::set<std::string> ignoredAttributes_;
  std::set<std::string> ignoredTargetAttributes_;
  // A mesh morphed by a node's own weights, by (glTF mesh, weights).
  std::map<std::pair<int, std::vector<double>>, uint32_t> morphedMeshes_;
  // A skinned mesh at its rest pose, by (glTF mesh, morph weights, skin).
  std::map<std::tuple<int, std::vector<double>, int>, uint32_t> skinnedMeshes_;
  uint64_t posedVertices_ = 0;  // in the copies of both maps
  bool usesOtherTexCoords_ = false;
  bool quantized_ = false;  // the file uses KHR_mesh_quantization: integer attributes are allowed
};

}  // namespace lll::gltf_detail
