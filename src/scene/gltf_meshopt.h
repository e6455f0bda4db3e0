#pragma once
// Private to the glTF loader: EXT_meshopt_compression (gltfpack -c), decoded with meshoptimizer's
// decoders (Debian's libmeshoptimizer-dev). A compressed bufferView names the compressed bytes in
// its extension; its own buffer is usually a "fallback" buffer with no data at all, which tinygltf
// would refuse, so the fallback buffers are given a 4-byte stand-in before tinygltf parses the
// JSON, and after it each compressed bufferView is decoded into a buffer of its own. Every value
// the extension gives is checked first: a broken or hostile file is an InputError naming it.
#define TINYGLTF_NO_STB_IMAGE_WRITE  // as gltf_accessors.h
#include <tiny_gltf.h>

#include <nlohmann/json_fwd.hpp>
#include <string>
#include <vector>

namespace lll::gltf_detail {

// The extension's name, and the edit of the glTF's JSON (gltf_files.h: withJsonEdited) that gives
// every buffer it marks as a fallback a 4-byte data URI in place of its missing data.
inline constexpr const char* kMeshoptExtension = "EXT_meshopt_compression";
bool stubMeshoptFallbacks(nlohmann::json& doc);

// Decodes every bufferView compressed with EXT_meshopt_compression into a new buffer of `model`
// and points the bufferView at it.
void decodeMeshoptBufferViews(tinygltf::Model& model, const std::string& file);

}  // namespace lll::gltf_detail
