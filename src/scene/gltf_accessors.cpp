// Checked reading of glTF accessors and bufferViews for the glTF loader: every index, offset,
// stride, count and component type in the file is checked before use, so that a corrupt or hostile
// file ends in an InputError that names it, never in an out-of-bounds read.
#include "scene/gltf_accessors.h"

#include <algorithm>
#include <cstring>
#include <limits>
#include <type_traits>

#include "core/errors.h"

namespace lll::gltf_detail {
namespace {

// An accessor without a bufferView is all zeros (plus sparse values), so no data in the file bounds
// its count; this does, instead of allocating whatever the count asks for.
constexpr size_t kMaxElementsWithoutData = size_t{1} << 22;

std::string typeName(int type) {
  if (type == TINYGLTF_TYPE_SCALAR) return "SCALAR";
  if (type >= TINYGLTF_TYPE_VEC2 && type <= TINYGLTF_TYPE_VEC4) return "VEC" + std::to_string(type);
  return "a matrix type";
}

bool isSmallInteger(int componentType) {
  return componentType == TINYGLTF_COMPONENT_TYPE_BYTE ||
         componentType == TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE ||
         componentType == TINYGLTF_COMPONENT_TYPE_SHORT ||
         componentType == TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT;
}

bool componentsAllowed(Components allowed, int componentType, bool normalized) {
  const bool isFloat = componentType == TINYGLTF_COMPONENT_TYPE_FLOAT;
  switch (allowed) {
    case Components::QuantizedPosition:
    case Components::QuantizedTexCoord:
      return isFloat || isSmallInteger(componentType);
    case Components::QuantizedDirection:
      return isFloat || (normalized && (componentType == TINYGLTF_COMPONENT_TYPE_BYTE ||
                                        componentType == TINYGLTF_COMPONENT_TYPE_SHORT));
    case Components::Float:
      return componentType == TINYGLTF_COMPONENT_TYPE_FLOAT;
    case Components::FloatOrNormalizedUnsigned:
      return componentType == TINYGLTF_COMPONENT_TYPE_FLOAT ||
             (normalized && (componentType == TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE ||
                             componentType == TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT));
    case Components::Index:
      return !normalized && (componentType == TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE ||
                             componentType == TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT ||
                             componentType == TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT);
  }
  return false;
}

const char* describe(Components allowed) {
  switch (allowed) {
    case Components::Float:
      return "FLOAT (5126) (integer types need KHR_mesh_quantization in extensionsUsed)";
    case Components::FloatOrNormalizedUnsigned:
      return "FLOAT (5126), or normalized UNSIGNED_BYTE (5121) or UNSIGNED_SHORT (5123)";
    case Components::Index:
      return "UNSIGNED_BYTE, UNSIGNED_SHORT or UNSIGNED_INT, not normalized";
    case Components::QuantizedPosition:
    case Components::QuantizedTexCoord:
      return "FLOAT (5126), or BYTE, UNSIGNED_BYTE, SHORT or UNSIGNED_SHORT (5120 to 5123) with "
             "KHR_mesh_quantization";
    case Components::QuantizedDirection:
      return "FLOAT (5126), or normalized BYTE (5120) or SHORT (5122) with KHR_mesh_quantization";
  }
  return "";
}

template <typename T>
double loadComponent(const uint8_t* p, bool normalized) {
  T value;
  std::memcpy(&value, p, sizeof value);
  if constexpr (std::is_floating_point_v<T>) {
    return value;
  } else {
    // glTF: a normalized signed integer is max(c / max, -1), so that -128 and -127 are both -1.
    return normalized ? std::max(double(value) / double(std::numeric_limits<T>::max()), -1.0) : double(value);
  }
}

// Only called for the component types that componentsAllowed() accepts.
double loadComponent(const uint8_t* p, int componentType, bool normalized) {
  switch (componentType) {
    case TINYGLTF_COMPONENT_TYPE_BYTE:
      return loadComponent<int8_t>(p, normalized);
    case TINYGLTF_COMPONENT_TYPE_SHORT:
      return loadComponent<int16_t>(p, normalized);
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE:
      return loadComponent<uint8_t>(p, normalized);
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT:
      return loadComponent<uint16_t>(p, normalized);
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT:
      return loadComponent<uint32_t>(p, normalized);
    case TINYGLTF_COMPONENT_TYPE_FLOAT:
      return loadComponent<float>(p, normalized);
    default:
      return 0.0;
  }
}

class AccessorReader {
 public:
  AccessorReader(const tinygltf::Model& model, const std::string& file) : model_(model), file_(file) {}

  void checkBufferViews() const;
  template <typename T>
  std::vector<T> readAccessor(int index, const std::string& what, int type, Components allowed) const;

 private:
  // Where an accessor's elements start in memory, and how far apart they are.
  struct ElementSpan {
    const uint8_t* data = nullptr;
    size_t stride = 0;
  };

  [[noreturn]] void fail(const std::string& what) const { throw InputError(file_ + ": " + what); }

  ElementSpan checkedElements(int bufferView, size_t byteOffset, size_t count, size_t elementSize,
                              size_t componentSize, bool useViewStride, const std::string& name) const;
  template <typename T>
  void applySparse(const tinygltf::Accessor& accessor, const std::string& name, std::vector<T>& values) const;

  const tinygltf::Model& model_;
  const std::string& file_;
};

void AccessorReader::checkBufferViews() const {
  for (size_t i = 0; i < model_.bufferViews.size(); ++i) {
    const tinygltf::BufferView& view = model_.bufferViews[i];
    const std::string name = "bufferView " + std::to_string(i);
    if (view.buffer < 0 || size_t(view.buffer) >= model_.buffers.size()) {
      fail(name + " refers to buffer " + std::to_string(view.buffer) + ", but the file has " +
           std::to_string(model_.buffers.size()) + " buffers");
    }
    const size_t bufferSize = model_.buffers[size_t(view.buffer)].data.size();
    if (view.byteOffset > bufferSize || view.byteLength > bufferSize - view.byteOffset) {
      fail(name + " covers bytes " + std::to_string(view.byteOffset) + " + " +
           std::to_string(view.byteLength) + " of buffer " + std::to_string(view.buffer) +
           ", which has only " + std::to_string(bufferSize) + " bytes. The file is corrupt; re-export it.");
    }
  }
}

AccessorReader::ElementSpan AccessorReader::checkedElements(int bufferView, size_t byteOffset, size_t count,
                                                            size_t elementSize, size_t componentSize,
                                                            bool useViewStride,
                                                            const std::string& name) const {
  if (bufferView < 0 || size_t(bufferView) >= model_.bufferViews.size()) {
    fail(name + " refers to bufferView " + std::to_string(bufferView) + ", but the file has " +
         std::to_string(model_.bufferViews.size()) + " bufferViews");
  }
  const tinygltf::BufferView& view = model_.bufferViews[size_t(bufferView)];
  const size_t stride = useViewStride && view.byteStride != 0 ? view.byteStride : elementSize;
  if (stride < elementSize) {
    fail(name + " has elements of " + std::to_string(elementSize) + " bytes, but bufferView " +
         std::to_string(bufferView) + " has the smaller byteStride " + std::to_string(stride));
  }
  // Phrased with divisions so that a forged count cannot overflow the arithmetic. count >= 1.
  if (byteOffset > view.byteLength || view.byteLength - byteOffset < elementSize ||
      count - 1 > (view.byteLength - byteOffset - elementSize) / stride) {
    fail(name + " reads " + std::to_string(count) + " elements of " + std::to_string(elementSize) +
         " bytes (stride " + std::to_string(stride) + ") from byte " + std::to_string(byteOffset) +
         " of bufferView " + std::to_string(bufferView) + ", which is only " +
         std::to_string(view.byteLength) + " bytes long. The file is corrupt or truncated; re-export it.");
  }
  // glTF: an accessor's start in its buffer, and the stride, are multiples of its component size.
  // A misaligned start reads the bytes of neighbouring values as floats: garbage, often NaN.
  if ((view.byteOffset + byteOffset) % componentSize != 0 || stride % componentSize != 0) {
    fail(name + " starts at byte " + std::to_string(view.byteOffset + byteOffset) +
         " of its buffer (bufferView " + std::to_string(bufferView) + " byteOffset " +
         std::to_string(view.byteOffset) + " + accessor byteOffset " + std::to_string(byteOffset) +
         ", stride " + std::to_string(stride) + "), not a multiple of its " + std::to_string(componentSize) +
         "-byte components as glTF requires");
  }
  const uint8_t* base = model_.buffers[size_t(view.buffer)].data.data();
  return {base + view.byteOffset + byteOffset, stride};
}

template <typename T>
std::vector<T> AccessorReader::readAccessor(int index, const std::string& what, int type,
                                            Components allowed) const {
  if (index < 0 || size_t(index) >= model_.accessors.size()) {
    fail(what + " refers to accessor " + std::to_string(index) + ", but the file has " +
         std::to_string(model_.accessors.size()) + " accessors");
  }
  const tinygltf::Accessor& accessor = model_.accessors[size_t(index)];
  const std::string name = "accessor " + std::to_string(index) + " (" + what + ")";
  if (accessor.type != type) {
    fail(name + " has type " + typeName(accessor.type) + ", but glTF requires " + typeName(type));
  }
  if (!componentsAllowed(allowed, accessor.componentType, accessor.normalized)) {
    const bool isFloat = accessor.componentType == TINYGLTF_COMPONENT_TYPE_FLOAT;
    fail(name + " has componentType " + std::to_string(accessor.componentType) +
         (isFloat               ? ""
          : accessor.normalized ? " (normalized)"
                                : " (not normalized)") +
         "; glTF allows only " + describe(allowed) + " here");
  }
  if (accessor.count == 0) fail(name + " has count 0; glTF requires at least 1");

  const size_t components = size_t(tinygltf::GetNumComponentsInType(uint32_t(accessor.type)));
  const size_t componentSize = size_t(tinygltf::GetComponentSizeInBytes(uint32_t(accessor.componentType)));
  std::vector<T> values;
  if (accessor.bufferView < 0) {
    if (accessor.count > kMaxElementsWithoutData) {
      fail(name + " has no bufferView but a count of " + std::to_string(accessor.count) +
           ", above the limit of " + std::to_string(kMaxElementsWithoutData) +
           " for data that is all zeros or sparse");
    }
    values.assign(accessor.count * components, T{0});
  } else {
    const ElementSpan span = checkedElements(accessor.bufferView, accessor.byteOffset, accessor.count,
                                             components * componentSize, componentSize, true, name);
    values.resize(accessor.count * components);
    for (size_t i = 0; i < accessor.count; ++i) {
      for (size_t c = 0; c < components; ++c) {
        values[i * components + c] = static_cast<T>(loadComponent(
            span.data + i * span.stride + c * componentSize, accessor.componentType, accessor.normalized));
      }
    }
  }
  if (accessor.sparse.isSparse) applySparse(accessor, name, values);
  return values;
}

template <typename T>
void AccessorReader::applySparse(const tinygltf::Accessor& accessor, const std::string& name,
                                 std::vector<T>& values) const {
  const auto& sparse = accessor.sparse;
  if (sparse.count < 1 || size_t(sparse.count) > accessor.count) {
    fail(name + " has a sparse count of " + std::to_string(sparse.count) + "; it must be between 1 and " +
         std::to_string(accessor.count));
  }
  if (!componentsAllowed(Components::Index, sparse.indices.componentType, false)) {
    fail(name + " has sparse indices of componentType " + std::to_string(sparse.indices.componentType) +
         "; glTF allows " + describe(Components::Index));
  }
  if (sparse.indices.byteOffset < 0 || sparse.values.byteOffset < 0)
    fail(name + " has a negative sparse byteOffset");
  const size_t count = size_t(sparse.count);
  const size_t components = values.size() / accessor.count;
  const size_t componentSize = size_t(tinygltf::GetComponentSizeInBytes(uint32_t(accessor.componentType)));
  const size_t indexSize = size_t(tinygltf::GetComponentSizeInBytes(uint32_t(sparse.indices.componentType)));
  const ElementSpan indices = checkedElements(sparse.indices.bufferView, size_t(sparse.indices.byteOffset),
                                              count, indexSize, indexSize, false, name + " sparse indices");
  const ElementSpan replacements =
      checkedElements(sparse.values.bufferView, size_t(sparse.values.byteOffset), count,
                      components * componentSize, componentSize, false, name + " sparse values");
  for (size_t k = 0; k < count; ++k) {
    const auto target =
        size_t(loadComponent(indices.data + k * indices.stride, sparse.indices.componentType, false));
    if (target >= accessor.count) {
      fail(name + " has sparse index " + std::to_string(target) + ", but the accessor has only " +
           std::to_string(accessor.count) + " elements");
    }
    for (size_t c = 0; c < components; ++c) {
      values[target * components + c] =
          static_cast<T>(loadComponent(replacements.data + k * replacements.stride + c * componentSize,
                                       accessor.componentType, accessor.normalized));
    }
  }
}

}  // namespace

void checkBufferViews(const tinygltf::Model& model, const std::string& file) {
  AccessorReader(model, file).checkBufferViews();
}

template <typename T>
std::vector<T> readAccessor(const tinygltf::Model& model, const std::string& file, int index,
                            const std::string& what, int type, Components allowed) {
  return AccessorReader(model, file).readAccessor<T>(index, what, type, allowed);
}

template std::vector<float> readAccessor<float>(const tinygltf::Model&, const std::string&, int,
                                                const std::string&, int, Components);
template std::vector<uint32_t> readAccessor<uint32_t>(const tinygltf::Model&, const std::string&, int,
                                                      const std::string&, int, Components);

}  // namespace lll::gltf_detail
