// KHR_draco_mesh_compression for the glTF loader (scene/gltf_draco.h).
#include "scene/gltf_draco.h"

#include <draco/compression/decode.h>
#include <fmt/format.h>

#include <cstdint>
#include <cstring>
#include <limits>
#include <map>
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>

#include "core/errors.h"
#include "scene/gltf_numbers.h"

namespace lll::gltf_detail {

namespace {

constexpr const char* kExtension = kDracoExtension;
// The most bytes one primitive may decode to: what a glTF buffer may hold.
constexpr uint64_t kMaxDecodedBytes = std::numeric_limits<int32_t>::max();

[[noreturn]] void fail(const std::string& file, const std::string& what) {
  throw InputError(file + ": " + what);
}

// Draco decodes whatever counts its header claims, allocating for them before it finds that the
// data does not hold them: 60 bytes claiming 67 million triangles took 1.6 GB here, and the
// counts go to 1.4 billion. So the counts are read first and bounded by the compressed size.
// Draco's best case is far below the bound: a regular 700 x 700 grid, all of it predictable, is
// 27 triangles and 13 vertices a byte at its highest compression level.
constexpr uint64_t kMaxElementsPerByte = 64;

// A cursor over Draco's bitstream header, every read bounded.
struct DracoReader {
  const unsigned char* at;
  const unsigned char* end;
  bool ok = true;

  uint64_t byte() {
    if (at >= end) return ok = false, 0;
    return *at++;
  }
  // Draco's unsigned LEB128 varint (at most 10 bytes).
  uint64_t varint() {
    uint64_t value = 0;
    for (int shift = 0; shift < 70 && ok; shift += 7) {
      const uint64_t b = byte();
      value |= (b & 0x7F) << shift;
      if ((b & 0x80) == 0) return value;
    }
    return ok = false, 0;
  }
  void skip(uint64_t bytes) {
    if (bytes > uint64_t(end - at))
      ok = false, at = end;
    else
      at += bytes;
  }
  // A metadata block: named entries, then named sub-blocks (to `depth` levels).
  void skipMetadata(int depth) {
    if (depth > 32) return void(ok = false);
    const uint64_t entries = varint();
    for (uint64_t i = 0; i < entries && ok; ++i) {
      skip(byte());    // the name
      skip(varint());  // the value
    }
    const uint64_t blocks = varint();
    for (uint64_t i = 0; i < blocks && ok; ++i) {
      skip(byte());
      skipMetadata(depth + 1);
    }
  }
};

// Checks the header of Draco `data` (bitstream 2.2, the one KHR_draco_mesh_compression uses) and
// that the triangle and vertex counts it claims are within kMaxElementsPerByte of its size.
void checkDracoHeader(const unsigned char* data, size_t size, const std::string& file,
                      const std::string& where) {
  DracoReader r{data, data + size};
  if (size < 11 || std::memcmp(data, "DRACO", 5) != 0)
    fail(file, where + " is not Draco data (no DRACO header)");
  r.skip(5);
  const uint64_t major = r.byte(), minor = r.byte();
  if (major != 2 || minor != 2)
    fail(file, where + " is Draco bitstream " + std::to_string(major) + "." + std::to_string(minor) +
                   "; the extension uses bitstream 2.2 (re-encode it with a current Draco)");
  const uint64_t type = r.byte(), method = r.byte();
  const uint64_t flags = r.byte() | r.byte() << 8;
  if (type != 1) fail(file, where + " holds a Draco point cloud, not a triangle mesh");
  if (flags & 0x8000) {  // metadata: per attribute, then the geometry's
    const uint64_t attributes = r.varint();
    for (uint64_t i = 0; i < attributes && r.ok; ++i) {
      r.varint();  // the attribute's id
      r.skipMetadata(0);
    }
    r.skipMetadata(0);
  }
  uint64_t faces = 0, vertices = 0;
  if (method == 0) {  // sequential
    faces = r.varint();
    vertices = r.varint();
  } else if (method == 1) {  // edgebreaker: its traversal's kind, then the counts
    r.byte();
    vertices = r.varint();
    faces = r.varint();
  } else {
    fail(file, where + " has Draco encoding method " + std::to_string(method) + "; Draco defines 0 and 1");
  }
  if (!r.ok) fail(file, where + " ends inside its Draco header: the compressed data is corrupt");
  const uint64_t bound = kMaxElementsPerByte * size;
  if (faces > bound || vertices > bound)
    fail(file, where + " claims " + std::to_string(faces) + " triangles and " + std::to_string(vertices) +
                   " vertices from " + std::to_string(size) + " bytes, more than " +
                   std::to_string(kMaxElementsPerByte) + " a byte, which no Draco mesh compresses to");
}

// The decoded bytes of one primitive and the accessors that will describe them.
struct DecodedPrimitive {
  std::vector<unsigned char> bytes;
  std::map<std::string, tinygltf::Accessor> attributes;  // by glTF semantic
  std::optional<tinygltf::Accessor> indices;
};

// Appends `values` to `bytes` (4-byte aligned) and returns the accessor over them: `like`'s name,
// type and bounds, `componentType` and `count`, its bufferView to be set by the caller (its index
// is not known yet, so byteOffset holds the offset into `bytes` until then).
template <typename T>
tinygltf::Accessor appendAccessor(std::vector<unsigned char>& bytes, const std::vector<T>& values,
                                  const tinygltf::Accessor& like, int componentType, size_t count) {
  while (bytes.size() % 4 != 0) bytes.push_back(0);
  tinygltf::Accessor out;
  out.name = like.name;
  out.type = like.type;
  out.minValues = like.minValues;
  out.maxValues = like.maxValues;
  out.componentType = componentType;
  out.normalized = false;
  out.count = count;
  out.byteOffset = bytes.size();
  const size_t size = values.size() * sizeof(T);
  bytes.resize(bytes.size() + size);
  if (size > 0) std::memcpy(bytes.data() + out.byteOffset, values.data(), size);
  return out;
}

DecodedPrimitive decodePrimitive(const tinygltf::Model& model, const tinygltf::Primitive& primitive,
                                 const tinygltf::Value& e, const std::string& file,
                                 const std::string& where) {
  if (!e.IsObject()) fail(file, where + " is not an object");
  if (!e.Has("bufferView") || !e.Has("attributes"))
    fail(file, where + " needs a bufferView and attributes, which the extension requires");
  const uint64_t viewIndex = unsignedMember(e, "bufferView", 0, file, where);
  if (viewIndex >= model.bufferViews.size())
    fail(file, where + " names bufferView " + std::to_string(viewIndex) + ", but the file has " +
                   std::to_string(model.bufferViews.size()));
  const tinygltf::BufferView& view = model.bufferViews[size_t(viewIndex)];
  if (view.buffer < 0 || size_t(view.buffer) >= model.buffers.size())
    fail(file, where + "'s bufferView " + std::to_string(viewIndex) + " names buffer " +
                   std::to_string(view.buffer) + ", which the file does not have");
  const std::vector<unsigned char>& source = model.buffers[size_t(view.buffer)].data;
  if (view.byteOffset > source.size() || view.byteLength > source.size() - view.byteOffset)
    fail(file, where + "'s bufferView " + std::to_string(viewIndex) + " covers bytes " +
                   std::to_string(view.byteOffset) + " + " + std::to_string(view.byteLength) + " of buffer " +
                   std::to_string(view.buffer) + ", which has " + std::to_string(source.size()));

  checkDracoHeader(source.data() + view.byteOffset, view.byteLength, file, where);
  draco::DecoderBuffer buffer;
  buffer.Init(reinterpret_cast<const char*>(source.data() + view.byteOffset), view.byteLength);
  const auto type = draco::Decoder::GetEncodedGeometryType(&buffer);
  if (!type.ok()) fail(file, where + " is not Draco data: " + type.status().error_msg_string());
  if (type.value() != draco::TRIANGULAR_MESH)
    fail(file, where + " holds a Draco point cloud, not a triangle mesh");
  draco::Decoder decoder;
  auto decoded = decoder.DecodeMeshFromBuffer(&buffer);
  if (!decoded.ok())
    fail(file, where + " does not decode (Draco: " + decoded.status().error_msg_string() +
                   "): the compressed data is corrupt");
  const std::unique_ptr<draco::Mesh> mesh = std::move(decoded).value();
  const uint64_t points = mesh->num_points();
  const uint64_t corners = uint64_t(mesh->num_faces()) * 3;
  if (points > std::numeric_limits<uint32_t>::max() || corners > kMaxDecodedBytes / 4)
    fail(file, where + " decodes to " + std::to_string(points) + " vertices and " +
                   std::to_string(corners / 3) + " triangles, more than a glTF buffer may hold");

  DecodedPrimitive out;
  const tinygltf::Value& attributes = e.Get("attributes");
  if (!attributes.IsObject()) fail(file, where + "'s attributes is not an object");
  uint64_t bytes = corners * 4;
  for (const std::string& semantic : attributes.Keys()) {
    const auto accessorIndex = primitive.attributes.find(semantic);
    // The extension maps only attributes the primitive has; any other has nowhere to go.
    if (accessorIndex == primitive.attributes.end()) continue;
    if (accessorIndex->second < 0 || size_t(accessorIndex->second) >= model.accessors.size())
      fail(file, where + ": the primitive's " + semantic + " names accessor " +
                     std::to_string(accessorIndex->second) + ", which the file does not have");
    const tinygltf::Accessor& accessor = model.accessors[size_t(accessorIndex->second)];
    const int components = tinygltf::GetNumComponentsInType(uint32_t(accessor.type));
    if (components < 1 || components > 16)
      fail(file, where + ": accessor " + std::to_string(accessorIndex->second) + " (" + semantic +
                     ") has no valid type");
    const uint64_t id = unsignedMember(attributes, semantic.c_str(), 0, file, where + "'s attributes");
    const draco::PointAttribute* attribute =
        id <= std::numeric_limits<uint32_t>::max() ? mesh->GetAttributeByUniqueId(uint32_t(id)) : nullptr;
    if (attribute == nullptr)
      fail(file, where + " maps " + semantic + " to Draco attribute " + std::to_string(id) +
                     ", which the compressed mesh does not have");
    if (attribute->num_components() != components)
      fail(file, where + "'s " + semantic + " has " + std::to_string(attribute->num_components()) +
                     " components in the Draco data but " + std::to_string(components) + " in its accessor");
    bytes += points * uint64_t(components) * 4;
    if (bytes > kMaxDecodedBytes)
      fail(file, where + " decodes to more than the " + std::to_string(kMaxDecodedBytes) +
                     " bytes a glTF buffer may hold");
    // Floats whatever Draco stored: its normalized integers come out divided as glTF's would be,
    // its plain ones as their values (KHR_mesh_quantization's node transforms still apply).
    std::vector<float> values(size_t(points) * size_t(components));
    for (uint64_t i = 0; i < points; ++i) {
      const draco::AttributeValueIndex value = attribute->mapped_index(draco::PointIndex(uint32_t(i)));
      if (value.value() >= attribute->size() ||
          !attribute->ConvertValue<float>(value, int8_t(components), &values[size_t(i) * size_t(components)]))
        fail(file, where + "'s " + semantic + " has no value for vertex " + std::to_string(i) +
                       ": the compressed data is corrupt");
    }
    out.attributes[semantic] =
        appendAccessor(out.bytes, values, accessor, TINYGLTF_COMPONENT_TYPE_FLOAT, size_t(points));
  }

  std::vector<uint32_t> indices;
  indices.reserve(size_t(corners));
  for (draco::FaceIndex f(0); f < mesh->num_faces(); ++f) {
    const draco::Mesh::Face& face = mesh->face(f);
    for (int corner = 0; corner < 3; ++corner) {
      if (face[corner].value() >= points)
        fail(file, where + " has a triangle with vertex " + std::to_string(face[corner].value()) + " of " +
                       std::to_string(points) + ": the compressed data is corrupt");
      indices.push_back(face[corner].value());
    }
  }
  tinygltf::Accessor like;  // the file's indices accessor was dropped before parsing
  like.type = TINYGLTF_TYPE_SCALAR;
  out.indices =
      appendAccessor(out.bytes, indices, like, TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT, indices.size());
  return out;
}

}  // namespace

bool dropDracoIndices(nlohmann::json& doc) {
  if (!doc.is_object() || !doc.contains("meshes") || !doc["meshes"].is_array()) return false;
  bool dropped = false;
  for (nlohmann::json& mesh : doc["meshes"]) {
    if (!mesh.is_object() || !mesh.contains("primitives") || !mesh["primitives"].is_array()) continue;
    for (nlohmann::json& primitive : mesh["primitives"]) {
      if (!primitive.is_object() || !primitive.contains("indices")) continue;
      const auto extensions = primitive.find("extensions");
      if (extensions == primitive.end() || !extensions->is_object() || !extensions->contains(kExtension))
        continue;
      primitive.erase("indices");
      dropped = true;
    }
  }
  return dropped;
}

void decodeDracoPrimitives(tinygltf::Model& model, const std::string& file) {
  for (size_t m = 0; m < model.meshes.size(); ++m) {
    for (size_t p = 0; p < model.meshes[m].primitives.size(); ++p) {
      tinygltf::Primitive& primitive = model.meshes[m].primitives[p];
      const auto found = primitive.extensions.find(kExtension);
      if (found == primitive.extensions.end()) continue;
      const std::string where = fmt::format("mesh {} primitive {}'s {}", m, p, kExtension);
      // Draco holds triangles; a strip is decoded to them. Points and lines are skipped by the
      // loader, so their data is never needed.
      if (primitive.mode >= TINYGLTF_MODE_POINTS && primitive.mode <= TINYGLTF_MODE_LINE_STRIP) continue;
      if (primitive.mode != TINYGLTF_MODE_TRIANGLES && primitive.mode != TINYGLTF_MODE_TRIANGLE_STRIP)
        fail(file, where + " is on a primitive of mode " + std::to_string(primitive.mode) +
                       "; the extension compresses triangles (mode 4) and triangle strips (5)");
      DecodedPrimitive decoded = decodePrimitive(model, primitive, found->second, file, where);

      tinygltf::Buffer buffer;
      buffer.data = std::move(decoded.bytes);
      const size_t size = buffer.data.size();
      model.buffers.push_back(std::move(buffer));
      tinygltf::BufferView view;
      view.buffer = int(model.buffers.size() - 1);
      view.byteOffset = 0;
      view.byteLength = size;
      model.bufferViews.push_back(view);
      const int viewIndex = int(model.bufferViews.size() - 1);
      // New accessors, never the file's: another primitive may share those.
      const auto add = [&](tinygltf::Accessor accessor) {
        accessor.bufferView = viewIndex;
        model.accessors.push_back(std::move(accessor));
        return int(model.accessors.size() - 1);
      };
      for (auto& [semantic, accessor] : decoded.attributes) primitive.attributes[semantic] = add(accessor);
      primitive.indices = add(*decoded.indices);
      primitive.mode = TINYGLTF_MODE_TRIANGLES;
    }
  }
}

}  // namespace lll::gltf_detail
