#include "particles/presets.h"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "core/errors.h"
#include "particles/embedded_presets.h"
#include "shared/particle_types.h"

namespace lll {

namespace {

using nlohmann::json;

// Reads one preset's fields, each by its dotted path ("velocity.speed"), so every complaint names
// the file and the field.
class FieldReader {
 public:
  explicit FieldReader(const std::string& source) : source_(source) {}

  [[noreturn]] void fail(const std::string& field, const std::string& what) const {
    throw InputError(fmt::format("particle preset {}: field \"{}\" {}", source_, field, what));
  }

  // The member `name` of the object at `parent` ("" for the top level).
  const json& member(const json& object, const std::string& parent, const char* name) const {
    const std::string field = join(parent, name);
    if (!object.is_object()) fail(parent, fmt::format("must be an object (got {})", object.dump()));
    const auto it = object.find(name);
    if (it == object.end()) fail(field, "is missing");
    return *it;
  }

  // Rejects members not in `known`: a misspelt field would otherwise be silently ignored.
  void onlyKnown(const json& object, const std::string& parent,
                 std::initializer_list<const char*> known) const {
    if (!object.is_object()) fail(parent, fmt::format("must be an object (got {})", object.dump()));
    for (const auto& [key, value] : object.items()) {
      if (std::find_if(known.begin(), known.end(), [&](const char* k) { return key == k; }) == known.end())
        fail(join(parent, key.c_str()),
             fmt::format("is not a preset field (fields here: {})", fmt::join(known, ", ")));
    }
  }

  float number(const json& value, const std::string& field, double lo, double hi) const {
    if (!value.is_number()) fail(field, fmt::format("must be a number (got {})", value.dump()));
    const double v = value.get<double>();
    if (!std::isfinite(v) || v < lo || v > hi)
      fail(field, fmt::format("must be between {} and {} (got {})", lo, hi, v));
    return float(v);
  }

  uint32_t count(const json& value, const std::string& field) const {
    if (!value.is_number_integer())
      fail(field, fmt::format("must be a whole number of particles (got {})", value.dump()));
    const int64_t v = value.get<int64_t>();
    if (v < 1 || v > int64_t(gpu::kMaxParticles))
      fail(field, fmt::format("is {}: a system holds 1 to {} particles", v, gpu::kMaxParticles));
    return uint32_t(v);
  }

  std::string choice(const json& value, const std::string& field,
                     std::initializer_list<const char*> options) const {
    const std::string choices = fmt::format("{}", fmt::join(options, ", "));
    if (!value.is_string()) fail(field, fmt::format("must be one of {} (got {})", choices, value.dump()));
    const std::string s = value.get<std::string>();
    if (std::find_if(options.begin(), options.end(), [&](const char* o) { return s == o; }) == options.end())
      fail(field, fmt::format("must be one of {} (got \"{}\")", choices, s));
    return s;
  }

  glm::vec3 vec3(const json& value, const std::string& field, double lo, double hi) const {
    if (!value.is_array() || value.size() != 3)
      fail(field, fmt::format("must be an array of 3 numbers (got {})", value.dump()));
    return {number(value[0], field + "[0]", lo, hi), number(value[1], field + "[1]", lo, hi),
            number(value[2], field + "[2]", lo, hi)};
  }

  // [min, max] with lo <= min <= max <= hi.
  std::pair<float, float> range(const json& value, const std::string& field, double lo, double hi) const {
    if (!value.is_array() || value.size() != 2)
      fail(field, fmt::format("must be [min, max] (got {})", value.dump()));
    const float a = number(value[0], field + "[0]", lo, hi), b = number(value[1], field + "[1]", lo, hi);
    if (a > b) fail(field, fmt::format("must be [min, max] with min <= max (got {})", value.dump()));
    return {a, b};
  }

  // 1 to kMaxCurveKeys keys, evenly spaced over the particle's life.
  template <typename Key>
  std::vector<Key> curve(const json& value, const std::string& field,
                         Key (FieldReader::*read)(const json&, const std::string&, double, double) const,
                         double lo, double hi) const {
    if (!value.is_array() || value.empty() || value.size() > gpu::kMaxCurveKeys)
      fail(field, fmt::format("must be an array of 1 to {} keys over the particle's life (got {})",
                              gpu::kMaxCurveKeys, value.dump()));
    std::vector<Key> keys;
    for (size_t i = 0; i < value.size(); ++i)
      keys.push_back((this->*read)(value[i], fmt::format("{}[{}]", field, i), lo, hi));
    return keys;
  }

  static std::string join(const std::string& parent, const char* name) {
    return parent.empty() ? std::string(name) : parent + "." + name;
  }

 private:
  const std::string& source_;
};

void readMotion(const FieldReader& r, const json& doc, ParticlePreset& p) {
  const json& emitter = r.member(doc, "", "emitter");
  r.onlyKnown(emitter, "emitter", {"shape", "radius", "offset"});
  const std::string shape =
      r.choice(r.member(emitter, "emitter", "shape"), "emitter.shape", {"point", "disc", "sphere"});
  p.shape = shape == "point"  ? EmitterShape::Point
            : shape == "disc" ? EmitterShape::Disc
                              : EmitterShape::Sphere;
  p.emitterRadius = r.number(r.member(emitter, "emitter", "radius"), "emitter.radius", 0.0, 100.0);
  p.emitterOffset = r.vec3(r.member(emitter, "emitter", "offset"), "emitter.offset", -1000.0, 1000.0);

  const json& velocity = r.member(doc, "", "velocity");
  r.onlyKnown(velocity, "velocity", {"direction", "spread", "speed"});
  const glm::vec3 direction =
      r.vec3(r.member(velocity, "velocity", "direction"), "velocity.direction", -1e3, 1e3);
  if (glm::length(direction) < 1e-6f) r.fail("velocity.direction", "must not be the zero vector");
  p.direction = glm::normalize(direction);
  p.spreadDegrees = r.number(r.member(velocity, "velocity", "spread"), "velocity.spread", 0.0, 180.0);
  std::tie(p.speedMin, p.speedMax) =
      r.range(r.member(velocity, "velocity", "speed"), "velocity.speed", 0.0, 1000.0);

  p.gravity = r.vec3(r.member(doc, "", "gravity"), "gravity", -1000.0, 1000.0);
  p.buoyancy = r.number(r.member(doc, "", "buoyancy"), "buoyancy", -1000.0, 1000.0);
  p.drag = r.number(r.member(doc, "", "drag"), "drag", 0.0, 100.0);
  const json& turbulence = r.member(doc, "", "turbulence");
  r.onlyKnown(turbulence, "turbulence", {"strength", "size", "speed"});
  p.turbulenceStrength =
      r.number(r.member(turbulence, "turbulence", "strength"), "turbulence.strength", 0.0, 1000.0);
  p.turbulenceSize = r.number(r.member(turbulence, "turbulence", "size"), "turbulence.size", 1e-3, 1000.0);
  p.turbulenceSpeed = r.number(r.member(turbulence, "turbulence", "speed"), "turbulence.speed", 0.0, 100.0);
  p.spin = r.number(r.member(doc, "", "spin"), "spin", 0.0, 100.0);
  const json& floor = r.member(doc, "", "floor");
  r.onlyKnown(floor, "floor", {"mode", "restitution"});
  const std::string mode =
      r.choice(r.member(floor, "floor", "mode"), "floor.mode", {"none", "bounce", "kill"});
  p.floor = mode == "none" ? FloorMode::None : mode == "bounce" ? FloorMode::Bounce : FloorMode::Kill;
  p.restitution = r.number(r.member(floor, "floor", "restitution"), "floor.restitution", 0.0, 1.0);
}

void readLook(const FieldReader& r, const json& doc, ParticlePreset& p) {
  p.size = r.curve(r.member(doc, "", "size"), "size", &FieldReader::number, 1e-4, 100.0);
  p.sizeVariation = r.number(r.member(doc, "", "sizeVariation"), "sizeVariation", 0.0, 1.0);
  p.color = r.curve(r.member(doc, "", "color"), "color", &FieldReader::vec3, 0.0, 1.0);
  p.colorVariation = r.number(r.member(doc, "", "colorVariation"), "colorVariation", 0.0, 1.0);
  p.opacity = r.curve(r.member(doc, "", "opacity"), "opacity", &FieldReader::number, 0.0, 1.0);
  p.emission = r.curve(r.member(doc, "", "emission"), "emission", &FieldReader::number, 0.0, 1000.0);
  const json& scattering = r.member(doc, "", "scattering");
  r.onlyKnown(scattering, "scattering", {"wrap", "back", "focus"});
  p.wrap = r.number(r.member(scattering, "scattering", "wrap"), "scattering.wrap", 0.0, 1.0);
  p.back = r.number(r.member(scattering, "scattering", "back"), "scattering.back", 0.0, 100.0);
  p.focus = r.number(r.member(scattering, "scattering", "focus"), "scattering.focus", 1.0, 1000.0);
  p.softness = r.number(r.member(doc, "", "softness"), "softness", 1e-3, 100.0);
  p.additive = r.number(r.member(doc, "", "additive"), "additive", 0.0, 1.0);
}

// nlohmann keeps the last of two equal keys: a preset edited by hand would silently lose the first.
json parseRejectingDuplicateKeys(const std::string& text, const std::string& source) {
  std::vector<std::vector<std::string>> open;  // the keys seen in each object being parsed
  std::string duplicate;
  const json doc = json::parse(
      text,
      [&](int, json::parse_event_t event, json& value) {
        if (event == json::parse_event_t::object_start) open.emplace_back();
        if (event == json::parse_event_t::object_end && !open.empty()) open.pop_back();
        if (event == json::parse_event_t::key && !open.empty() && duplicate.empty()) {
          const std::string key = value.get<std::string>();
          if (std::find(open.back().begin(), open.back().end(), key) != open.back().end()) duplicate = key;
          open.back().push_back(key);
        }
        return true;
      },
      false);
  if (doc.is_discarded()) throw InputError(fmt::format("particle preset {}: not valid JSON", source));
  if (!duplicate.empty())
    throw InputError(
        fmt::format("particle preset {}: the key \"{}\" appears twice in one object", source, duplicate));
  return doc;
}

std::string readTextFile(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(fmt::format("particle preset {}: cannot read the file", path.string()));
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

}  // namespace

std::vector<std::string> builtinParticlePresets() {
  std::vector<std::string> names;
  for (const EmbeddedText& preset : embeddedParticlePresets()) names.emplace_back(preset.name);
  std::sort(names.begin(), names.end());
  return names;
}

ParticlePreset parseParticlePreset(const std::string& text, const std::string& source) {
  const json doc = parseRejectingDuplicateKeys(text, source);
  if (!doc.is_object())
    throw InputError(fmt::format("particle preset {}: expected a JSON object of fields", source));
  const FieldReader r(source);
  r.onlyKnown(doc, "", {"description", "count",    "lifetime",      "emitter",    "velocity",
                        "gravity",     "buoyancy", "drag",          "turbulence", "spin",
                        "floor",       "size",     "sizeVariation", "color",      "colorVariation",
                        "opacity",     "emission", "scattering",    "softness",   "additive"});
  if (doc.contains("description") && !doc["description"].is_string())
    r.fail("description", fmt::format("must be a string (got {})", doc["description"].dump()));
  ParticlePreset p;
  p.source = source;
  p.count = r.count(r.member(doc, "", "count"), "count");
  std::tie(p.lifetimeMin, p.lifetimeMax) = r.range(r.member(doc, "", "lifetime"), "lifetime", 0.05, 600.0);
  readMotion(r, doc, p);
  readLook(r, doc, p);
  return p;
}

ParticlePreset loadParticlePreset(const std::string& nameOrPath) {
  for (const EmbeddedText& preset : embeddedParticlePresets())
    if (preset.name == nameOrPath) return parseParticlePreset(std::string(preset.text), nameOrPath);
  const std::filesystem::path path(nameOrPath);
  std::error_code error;  // a name too long for the file system is an error, not an exception
  if (!std::filesystem::exists(path, error))
    throw InputError(fmt::format("--particles {}: neither a built-in preset ({}) nor an existing .json file",
                                 nameOrPath, fmt::join(builtinParticlePresets(), ", ")));
  return parseParticlePreset(readTextFile(path), path.string());
}

std::string particlePresetJson(const ParticlePreset& p, const std::string& description) {
  const auto vec3 = [](const glm::vec3& v) { return json::array({v.x, v.y, v.z}); };
  json colors = json::array();
  for (const glm::vec3& c : p.color) colors.push_back(vec3(c));
  const char* shapes[] = {"point", "disc", "sphere"};
  const char* floors[] = {"none", "bounce", "kill"};
  // Members in the order the built-in presets list them (nlohmann's ordered_json keeps it).
  nlohmann::ordered_json doc;
  doc["description"] = description;
  doc["count"] = p.count;
  doc["lifetime"] = {p.lifetimeMin, p.lifetimeMax};
  doc["emitter"] = {
      {"shape", shapes[int(p.shape)]}, {"radius", p.emitterRadius}, {"offset", vec3(p.emitterOffset)}};
  doc["velocity"] = {
      {"direction", vec3(p.direction)}, {"spread", p.spreadDegrees}, {"speed", {p.speedMin, p.speedMax}}};
  doc["gravity"] = vec3(p.gravity);
  doc["buoyancy"] = p.buoyancy;
  doc["drag"] = p.drag;
  doc["turbulence"] = {
      {"strength", p.turbulenceStrength}, {"size", p.turbulenceSize}, {"speed", p.turbulenceSpeed}};
  doc["spin"] = p.spin;
  doc["floor"] = {{"mode", floors[int(p.floor)]}, {"restitution", p.restitution}};
  doc["size"] = p.size;
  doc["sizeVariation"] = p.sizeVariation;
  doc["color"] = colors;
  doc["colorVariation"] = p.colorVariation;
  doc["opacity"] = p.opacity;
  doc["emission"] = p.emission;
  doc["scattering"] = {{"wrap", p.wrap}, {"back", p.back}, {"focus", p.focus}};
  doc["softness"] = p.softness;
  doc["additive"] = p.additive;
  return doc.dump(2) + "\n";
}

uint32_t stepsToSteadyState(const ParticlePreset& preset) {
  return uint32_t(std::ceil(double(preset.lifetimeMax) * gpu::kParticleStepsPerSecond)) + 1;
}

}  // namespace lll
