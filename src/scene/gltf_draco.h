#pragma once
// Private to the glTF loader: KHR_draco_mesh_compression (Blender's and Sketchfab's "Draco"
// exports, draco_transcoder), decoded with Google's Draco library (Debian's libdraco-dev). A
// compressed primitive keeps its accessors for their type and count but they have no data; the
// extension names a bufferView of Draco bytes and which Draco attribute holds each glTF attribute.
// After tinygltf has parsed the file, each such primitive is decoded into a buffer of its own and
// pointed at new accessors over it, so the rest of the loader reads it as any other primitive.
// Every value the extension gives is checked first: a broken or hostile file is an InputError
// naming it.
#include "scene/gltf_accessors.h"  // tiny_gltf.h as the loader includes it

#include <nlohmann/json_fwd.hpp>
#include <string>

namespace lll::gltf_detail {

// The extension's name, and the edit of the glTF's JSON (gltf_files.h: withJsonEdited) that drops
// the indices of every compressed primitive: their accessor has no data, which tinygltf refuses, and
// the decoded triangles replace it.
inline constexpr const char* kDracoExtension = "KHR_draco_mesh_compression";
bool dropDracoIndices(nlohmann::json& doc);

// Decodes every primitive of `model` compressed with KHR_draco_mesh_compression.
void decodeDracoPrimitives(tinygltf::Model& model, const std::string& file);

}  // namespace lll::gltf_detail
