// EXT_meshopt_compression for the glTF loader (scene/gltf_meshopt.h).
#include "scene/gltf_meshopt.h"

#include <meshoptimizer.h>

#include <cstdint>
#include <cstring>
#include <limits>
#include <nlohmann/json.hpp>

#include "core/errors.h"
#include "scene/gltf_numbers.h"

namespace lll::gltf_detail {

namespace {

constexpr const char* kExtension = kMeshoptExtension;
// The most bytes one bufferView may decode to: what a glTF buffer may hold (gltf_files.cpp reads
// files up to this size too).
constexpr uint64_t kMaxDecodedBytes = std::numeric_limits<int32_t>::max();
// meshoptimizer's codecs expand at most 64 times (the vertex codec's 2-bit header for 16 zero bytes;
// the index codecs far less): a count claiming more is refused before anything is allocated.
constexpr uint64_t kMaxExpansion = 64;
// A buffer of 4 zero bytes: tinygltf needs data behind every buffer.
constexpr const char* kStubUri = "data:application/octet-stream;base64,AAAAAA==";

[[noreturn]] void fail(const std::string& file, const std::string& what) {
  throw InputError(file + ": " + what);
}

std::string stringMember(const tinygltf::Value& object, const char* name, const std::string& fallback,
                         const std::string& file, const std::string& where) {
  if (!object.Has(name)) return fallback;
  const tinygltf::Value& v = object.Get(name);
  if (!v.IsString()) fail(file, where + "'s " + name + " is not a string");
  return v.Get<std::string>();
}

}  // namespace

bool stubMeshoptFallbacks(nlohmann::json& doc) {
  if (!doc.is_object() || !doc.contains("buffers") || !doc["buffers"].is_array()) return false;
  bool stubbed = false;
  for (nlohmann::json& buffer : doc["buffers"]) {
    if (!buffer.is_object()) continue;
    const auto extensions = buffer.find("extensions");
    if (extensions == buffer.end() || !extensions->is_object()) continue;
    const auto extension = extensions->find(kExtension);
    if (extension == extensions->end() || !extension->is_object()) continue;
    const auto fallback = extension->find("fallback");
    if (fallback == extension->end() || !fallback->is_boolean() || !fallback->get<bool>()) continue;
    if (buffer.contains("uri")) continue;  // a fallback with data of its own: read as it is
    buffer["uri"] = kStubUri;
    buffer["byteLength"] = 4;
    stubbed = true;
  }
  return stubbed;
}

void decodeMeshoptBufferViews(tinygltf::Model& model, const std::string& file) {
  for (size_t i = 0; i < model.bufferViews.size(); ++i) {
    tinygltf::BufferView& view = model.bufferViews[i];
    const auto found = view.extensions.find(kExtension);
    if (found == view.extensions.end()) continue;
    const tinygltf::Value& e = found->second;
    const std::string where = "bufferView " + std::to_string(i) + "'s " + kExtension;
    if (!e.IsObject()) fail(file, where + " is not an object");
    for (const char* required : {"buffer", "byteLength", "byteStride", "count", "mode"})
      if (!e.Has(required)) fail(file, where + " has no " + required + ", which the extension requires");
    const uint64_t buffer = unsignedMember(e, "buffer", 0, file, where);
    const uint64_t offset = unsignedMember(e, "byteOffset", 0, file, where);
    const uint64_t length = unsignedMember(e, "byteLength", 0, file, where);
    const uint64_t stride = unsignedMember(e, "byteStride", 0, file, where);
    const uint64_t count = unsignedMember(e, "count", 0, file, where);
    const std::string mode = stringMember(e, "mode", "", file, where);
    const std::string filter = stringMember(e, "filter", "NONE", file, where);
    if (buffer >= model.buffers.size())
      fail(file, where + " names buffer " + std::to_string(buffer) + ", but the file has " +
                     std::to_string(model.buffers.size()));
    const std::vector<unsigned char>& source = model.buffers[size_t(buffer)].data;
    if (offset > source.size() || length > source.size() - offset)
      fail(file, where + " covers bytes " + std::to_string(offset) + " + " + std::to_string(length) +
                     " of buffer " + std::to_string(buffer) + ", which has " + std::to_string(source.size()));
    const bool indices = mode == "TRIANGLES" || mode == "INDICES";
    if (mode != "ATTRIBUTES" && !indices)
      fail(file, where + " has mode '" + mode + "'; expected ATTRIBUTES, TRIANGLES or INDICES");
    if (mode == "ATTRIBUTES" ? (stride == 0 || stride % 4 != 0 || stride > 256)
                             : (stride != 2 && stride != 4))
      fail(file, where + " has byteStride " + std::to_string(stride) + ", which mode " + mode +
                     " does not allow (ATTRIBUTES: a multiple of 4 up to 256; indices: 2 or 4)");
    if (count == 0 || (mode == "TRIANGLES" && count % 3 != 0))
      fail(file, where + " has count " + std::to_string(count) +
                     (mode == "TRIANGLES" ? ", not a positive multiple of 3" : ", not positive"));
    if (count > kMaxDecodedBytes / stride)
      fail(file, where + " decodes to " + std::to_string(count) + " x " + std::to_string(stride) +
                     " bytes, more than the " + std::to_string(kMaxDecodedBytes) + " a buffer may hold");
    if (count * stride > kMaxExpansion * length + 4096)
      fail(file, where + " claims " + std::to_string(count * stride) + " bytes from " +
                     std::to_string(length) + " compressed ones, more than meshoptimizer's codecs expand to");
    if (view.byteLength != count * stride)
      fail(file, "bufferView " + std::to_string(i) + " has byteLength " + std::to_string(view.byteLength) +
                     ", but its " + kExtension + " decodes to " + std::to_string(count * stride) + " bytes");
    std::vector<unsigned char> decoded(size_t(count * stride));
    const unsigned char* data = source.data() + offset;
    int result = 0;
    if (mode == "ATTRIBUTES")
      result =
          meshopt_decodeVertexBuffer(decoded.data(), size_t(count), size_t(stride), data, size_t(length));
    else if (mode == "TRIANGLES")
      result = meshopt_decodeIndexBuffer(decoded.data(), size_t(count), size_t(stride), data, size_t(length));
    else
      result =
          meshopt_decodeIndexSequence(decoded.data(), size_t(count), size_t(stride), data, size_t(length));
    if (result != 0)
      fail(file, where + " does not decode (meshoptimizer error " + std::to_string(result) +
                     "): the compressed data is corrupt");
    if (filter != "NONE") {
      if (mode != "ATTRIBUTES") fail(file, where + " has filter " + filter + " on indices");
      if (filter == "OCTAHEDRAL" && (stride == 4 || stride == 8))
        meshopt_decodeFilterOct(decoded.data(), size_t(count), size_t(stride));
      else if (filter == "QUATERNION" && stride == 8)
        meshopt_decodeFilterQuat(decoded.data(), size_t(count), size_t(stride));
      else if (filter == "EXPONENTIAL")
        meshopt_decodeFilterExp(decoded.data(), size_t(count), size_t(stride));
      else
        fail(file, where + " has filter '" + filter + "' with byteStride " + std::to_string(stride) +
                       "; expected OCTAHEDRAL (4 or 8), QUATERNION (8) or EXPONENTIAL");
    }
    tinygltf::Buffer out;
    out.data = std::move(decoded);
    model.buffers.push_back(std::move(out));
    view.buffer = int(model.buffers.size() - 1);
    view.byteOffset = 0;
  }
}

}  // namespace lll::gltf_detail
