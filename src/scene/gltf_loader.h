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
// Images decode to at most `maxTextureTexels` texels together (4 GiB of RGBA8 by default); one past
// that is an image that could not be decoded, as above. Small glTF files can hold images that
// decode to gigabytes (a WebP or JPEG of one colour is kilobytes at any size).
inline constexpr uint64_t kDefaultMaxTextureTexels = uint64_t(1) << 30;
Scene loadGltf(const std::filesystem::path& file, LoadReport* report = nullptr,
               uint64_t maxTextureTexels = kDefaultMaxTextureTexels);

}  // namespace lll
