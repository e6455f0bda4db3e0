#pragma once
// Loads a glTF 2.0 scene (.gltf with its .bin and images, or a self-contained .glb) into a Scene:
// the default scene's node tree flattened into instances, metallic-roughness materials, RGBA8
// textures, KHR_lights_punctual point and spot lights, and perspective cameras.
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "scene/scene.h"

namespace lll {

// What loaded, but not as the file describes it: skipped primitives, lights and cameras, images
// that could not be read or decoded, extensions whose effect is ignored. One sentence each.
struct LoadReport {
  std::vector<std::string> warnings;
};

// Throws InputError, with a message naming `file`, for anything wrong with the file: unreadable,
// not glTF, invalid JSON, a missing or short .bin, accessors or indices out of range, a required
// extension we do not support, a mesh without positions. A missing or undecodable image is not an
// error: the material keeps texture index -1 (the renderer substitutes a neutral texture) and a
// warning is appended to `report` when one is given.
//
// `limits` bound what a small file can make the loader allocate: past textureTexels an image is
// one that could not be decoded, as above; past posedVertices the file is an InputError.
struct GltfLimits {
  // The texels the scene's images decode to together: 4 GiB of RGBA8. A WebP or JPEG of one colour
  // is kilobytes at any size.
  uint64_t textureTexels = uint64_t(1) << 30;
  // The vertices of the copies of meshes posed for their nodes (a node's own morph weights, a
  // skin): 2 GiB of vertices, 64 skinned characters of half a million vertices. A few bytes of
  // JSON per node can ask for a copy of a large mesh.
  uint64_t posedVertices = uint64_t(1) << 25;
  // The meshes the scene places in all (a node's, and each of EXT_mesh_gpu_instancing's copies):
  // an accessor without data reads as 4 million zeros, so a tiny file could place a mesh that often.
  uint64_t instances = uint64_t(1) << 20;
};
Scene loadGltf(const std::filesystem::path& file, LoadReport* report = nullptr,
               const GltfLimits& limits = {});

}  // namespace lll
