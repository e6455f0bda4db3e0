#pragma once
// Private to the glTF loader: checked reading of accessors and bufferViews. Each function throws
// InputError, with a message starting with `file`, for anything in the model it cannot use safely.
// Declarations only: gltf_loader.cpp holds the implementation. The macro changes the declarations,
// so it must be the same as there.
#define TINYGLTF_NO_STB_IMAGE_WRITE  // stb_image_write belongs to the image output code
#include <tiny_gltf.h>

#include <cstdint>
#include <string>
#include <vector>

namespace lll::gltf_detail {

// Which component types glTF allows for what we read. The Quantized kinds are
// KHR_mesh_quantization's, for files that use it: positions and texture coordinates of any 8- or
// 16-bit integer type, normalized or not; normals and tangents of normalized signed ones.
enum class Components {
  Float,
  FloatOrNormalizedUnsigned,
  Index,
  QuantizedPosition,
  QuantizedDirection,
  QuantizedTexCoord
};

// Checks that every bufferView lies within its buffer.
void checkBufferViews(const tinygltf::Model& model, const std::string& file);

// The elements of accessor `index` (sparse values applied), `type` components each, converted to T
// (normalized unsigned integers to 0..1, normalized signed ones to -1..1 as glTF defines). `what` names the
// accessor's use in error messages. Instantiated for float and uint32_t.
template <typename T>
std::vector<T> readAccessor(const tinygltf::Model& model, const std::string& file, int index,
                            const std::string& what, int type, Components allowed);

}  // namespace lll::gltf_detail
