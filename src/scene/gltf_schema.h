#pragma once
// Private to the glTF loader: the JSON types of the fields it reads. tinygltf treats a field of the
// wrong type as absent ("rotation": "NaN" becomes no rotation, "bufferView": "Infinity" no
// bufferView), so a broken file would load as something else; this check fails it instead.
#include <cstddef>
#include <string>

namespace lll::gltf_detail {

// Throws InputError, naming `file` and the field's JSON path, for a field whose type is not the
// one glTF 2.0 gives it (a number, an integer, an array of numbers, a string, an object...) among
// the fields the loader uses. Text that is not valid JSON is left to tinygltf's message.
void checkFieldTypes(const char* json, size_t size, const std::string& file);

}  // namespace lll::gltf_detail
