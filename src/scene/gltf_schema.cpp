#include "scene/gltf_schema.h"

#include <fmt/format.h>

#include <cmath>
#include <nlohmann/json.hpp>
#include <vector>

#include "core/errors.h"

namespace lll::gltf_detail {
namespace {

using nlohmann::json;

enum class Kind { Number, Integer, Boolean, String, Numbers, Integers, Object, Objects, IntegerValues };

struct Field;
// The fields of one kind of object, each with its type and, for objects, its own fields.
using Fields = std::vector<Field>;
struct Field {
  const char* name;
  Kind kind;
  const Fields* members = nullptr;  // for Object and Objects
};

const char* describe(Kind kind) {
  switch (kind) {
    case Kind::Number:
      return "a number";
    case Kind::Integer:
      return "an integer";
    case Kind::Boolean:
      return "true or false";
    case Kind::String:
      return "a string";
    case Kind::Numbers:
      return "an array of numbers";
    case Kind::Integers:
      return "an array of integers";
    case Kind::Object:
      return "an object";
    case Kind::Objects:
      return "an array of objects";
    case Kind::IntegerValues:
      return "an object whose values are integers";
  }
  return "";
}

bool isInteger(const json& v) {
  if (v.is_number_integer()) return true;
  return v.is_number_float() && std::isfinite(v.get<double>()) &&
         std::trunc(v.get<double>()) == v.get<double>();
}

bool hasKind(const json& v, Kind kind) {
  auto all = [&](bool (*test)(const json&)) {
    for (const json& item : v)
      if (!test(item)) return false;
    return true;
  };
  switch (kind) {
    case Kind::Number:
      return v.is_number();
    case Kind::Integer:
      return isInteger(v);
    case Kind::Boolean:
      return v.is_boolean();
    case Kind::String:
      return v.is_string();
    case Kind::Numbers:
      return v.is_array() && all([](const json& x) { return x.is_number(); });
    case Kind::Integers:
      return v.is_array() && all(isInteger);
    case Kind::Object:
      return v.is_object();
    case Kind::Objects:
      return v.is_array() && all([](const json& x) { return x.is_object(); });
    case Kind::IntegerValues:
      return v.is_object() && all(isInteger);
  }
  return false;
}

// glTF 2.0's schema, for the fields the loader reads (and the indices tinygltf follows).
const Fields kTextureTransform = {{"offset", Kind::Numbers},
                                  {"rotation", Kind::Number},
                                  {"scale", Kind::Numbers},
                                  {"texCoord", Kind::Integer}};
const Fields kTextureInfoExtensions = {{"KHR_texture_transform", Kind::Object, &kTextureTransform}};
const Fields kTextureInfo = {{"index", Kind::Integer},
                             {"texCoord", Kind::Integer},
                             {"scale", Kind::Number},
                             {"strength", Kind::Number},
                             {"extensions", Kind::Object, &kTextureInfoExtensions}};
const Fields kPbr = {{"baseColorFactor", Kind::Numbers},
                     {"metallicFactor", Kind::Number},
                     {"roughnessFactor", Kind::Number},
                     {"baseColorTexture", Kind::Object, &kTextureInfo},
                     {"metallicRoughnessTexture", Kind::Object, &kTextureInfo}};
const Fields kEmissiveStrength = {{"emissiveStrength", Kind::Number}};
const Fields kMaterialExtensions = {{"KHR_materials_emissive_strength", Kind::Object, &kEmissiveStrength}};
const Fields kMaterial = {{"name", Kind::String},
                          {"pbrMetallicRoughness", Kind::Object, &kPbr},
                          {"normalTexture", Kind::Object, &kTextureInfo},
                          {"occlusionTexture", Kind::Object, &kTextureInfo},
                          {"emissiveTexture", Kind::Object, &kTextureInfo},
                          {"emissiveFactor", Kind::Numbers},
                          {"alphaMode", Kind::String},
                          {"alphaCutoff", Kind::Number},
                          {"doubleSided", Kind::Boolean},
                          {"extensions", Kind::Object, &kMaterialExtensions}};
const Fields kSparseIndices = {
    {"bufferView", Kind::Integer}, {"byteOffset", Kind::Integer}, {"componentType", Kind::Integer}};
const Fields kSparseValues = {{"bufferView", Kind::Integer}, {"byteOffset", Kind::Integer}};
const Fields kSparse = {{"count", Kind::Integer},
                        {"indices", Kind::Object, &kSparseIndices},
                        {"values", Kind::Object, &kSparseValues}};
const Fields kAccessor = {
    {"bufferView", Kind::Integer}, {"byteOffset", Kind::Integer}, {"componentType", Kind::Integer},
    {"normalized", Kind::Boolean}, {"count", Kind::Integer},      {"type", Kind::String},
    {"min", Kind::Numbers},        {"max", Kind::Numbers},        {"sparse", Kind::Object, &kSparse}};
const Fields kBufferView = {{"buffer", Kind::Integer},
                            {"byteOffset", Kind::Integer},
                            {"byteLength", Kind::Integer},
                            {"byteStride", Kind::Integer},
                            {"target", Kind::Integer}};
const Fields kBuffer = {{"uri", Kind::String}, {"byteLength", Kind::Integer}};
const Fields kPerspective = {
    {"yfov", Kind::Number}, {"znear", Kind::Number}, {"zfar", Kind::Number}, {"aspectRatio", Kind::Number}};
const Fields kCamera = {
    {"name", Kind::String}, {"type", Kind::String}, {"perspective", Kind::Object, &kPerspective}};
const Fields kImage = {{"uri", Kind::String}, {"bufferView", Kind::Integer}, {"mimeType", Kind::String}};
const Fields kTexture = {{"sampler", Kind::Integer}, {"source", Kind::Integer}};
const Fields kSampler = {{"magFilter", Kind::Integer},
                         {"minFilter", Kind::Integer},
                         {"wrapS", Kind::Integer},
                         {"wrapT", Kind::Integer}};
const Fields kPrimitive = {{"attributes", Kind::IntegerValues},
                           {"indices", Kind::Integer},
                           {"material", Kind::Integer},
                           {"mode", Kind::Integer}};
const Fields kMesh = {{"name", Kind::String}, {"primitives", Kind::Objects, &kPrimitive}};
const Fields kNodeLight = {{"light", Kind::Integer}};
const Fields kNodeExtensions = {{"KHR_lights_punctual", Kind::Object, &kNodeLight}};
const Fields kNode = {{"camera", Kind::Integer},      {"children", Kind::Integers},
                      {"mesh", Kind::Integer},        {"matrix", Kind::Numbers},
                      {"rotation", Kind::Numbers},    {"scale", Kind::Numbers},
                      {"translation", Kind::Numbers}, {"extensions", Kind::Object, &kNodeExtensions}};
const Fields kScene = {{"nodes", Kind::Integers}};
const Fields kSpot = {{"innerConeAngle", Kind::Number}, {"outerConeAngle", Kind::Number}};
const Fields kLight = {{"name", Kind::String},      {"type", Kind::String},  {"color", Kind::Numbers},
                       {"intensity", Kind::Number}, {"range", Kind::Number}, {"spot", Kind::Object, &kSpot}};
const Fields kLightsPunctual = {{"lights", Kind::Objects, &kLight}};
const Fields kRootExtensions = {{"KHR_lights_punctual", Kind::Object, &kLightsPunctual}};
const Fields kRoot = {{"accessors", Kind::Objects, &kAccessor},
                      {"bufferViews", Kind::Objects, &kBufferView},
                      {"buffers", Kind::Objects, &kBuffer},
                      {"cameras", Kind::Objects, &kCamera},
                      {"images", Kind::Objects, &kImage},
                      {"materials", Kind::Objects, &kMaterial},
                      {"meshes", Kind::Objects, &kMesh},
                      {"nodes", Kind::Objects, &kNode},
                      {"scene", Kind::Integer},
                      {"scenes", Kind::Objects, &kScene},
                      {"samplers", Kind::Objects, &kSampler},
                      {"textures", Kind::Objects, &kTexture},
                      {"extensions", Kind::Object, &kRootExtensions}};

class TypeChecker {
 public:
  explicit TypeChecker(const std::string& file) : file_(file) {}

  void object(const json& value, const Fields& fields, const std::string& path) const {
    for (const Field& field : fields) {
      const auto it = value.find(field.name);
      if (it == value.end()) continue;
      const std::string where = path.empty() ? field.name : path + "." + field.name;
      if (!hasKind(*it, field.kind)) {
        std::string shown = it->dump();
        if (shown.size() > 60) shown = shown.substr(0, 57) + "...";
        throw InputError(
            fmt::format("{}: {} must be {} (got {})", file_, where, describe(field.kind), shown));
      }
      if (!field.members) continue;
      if (field.kind == Kind::Object) object(*it, *field.members, where);
      for (size_t i = 0; field.kind == Kind::Objects && i < it->size(); ++i)
        object((*it)[i], *field.members, fmt::format("{}[{}]", where, i));
    }
  }

 private:
  const std::string& file_;
};

}  // namespace

void checkFieldTypes(const char* text, size_t size, const std::string& file) {
  const json doc = json::parse(text, text + size, nullptr, false);
  if (doc.is_discarded() || !doc.is_object()) return;
  TypeChecker(file).object(doc, kRoot, "");
}

}  // namespace lll::gltf_detail
