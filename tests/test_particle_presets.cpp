// Particle presets: the built-ins parse, and every field of a preset is checked: take any one away,
// give it the wrong type or an absurd value, and the error names that field.
#include <gtest/gtest.h>

#include <functional>
#include <string>
#include <vector>

#include "core/errors.h"
#include "particles/presets.h"
#include "shared/particle_types.h"
#include "test_presets_json.h"

namespace lll {
namespace {

using nlohmann::json;

// The message parseParticlePreset throws for `preset`, or "" when it parses.
std::string errorFor(const json& preset) {
  try {
    parseParticlePreset(preset.dump(), "bent.json");
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

// Every leaf field's dotted path ("velocity.speed"), the optional description left out.
void leafPaths(const json& object, const std::string& prefix, std::vector<std::string>& out) {
  for (const auto& [key, value] : object.items()) {
    if (key == "description") continue;
    const std::string path = prefix.empty() ? key : prefix + "." + key;
    if (value.is_object())
      leafPaths(value, path, out);
    else
      out.push_back(path);
  }
}

json::json_pointer pointerTo(const std::string& path) {
  std::string pointer = "/" + path;
  for (char& c : pointer)
    if (c == '.') c = '/';
  return json::json_pointer(pointer);
}

TEST(ParticlePresets, BuiltinsParse) {
  EXPECT_EQ(builtinParticlePresets(), (std::vector<std::string>{"dust", "smoke", "sparks"}));
  const ParticlePreset smoke = loadParticlePreset("smoke");
  EXPECT_EQ(smoke.source, "smoke");
  EXPECT_GT(smoke.count, 0u);
  EXPECT_GT(smoke.buoyancy, 0.0f);            // smoke rises
  EXPECT_GT(smoke.turbulenceStrength, 0.0f);  // and swirls
  EXPECT_EQ(smoke.shape, EmitterShape::Disc);
  const ParticlePreset sparks = loadParticlePreset("sparks");
  EXPECT_LT(sparks.gravity.y, 0.0f);
  EXPECT_EQ(sparks.floor, FloorMode::Bounce);
  EXPECT_EQ(sparks.additive, 1.0f);
  EXPECT_GT(sparks.emission.front(), 1.0f);
  const ParticlePreset dust = loadParticlePreset("dust");
  EXPECT_EQ(dust.shape, EmitterShape::Sphere);
  EXPECT_GT(dust.lifetimeMin, smoke.lifetimeMax);
}

TEST(ParticlePresets, TheTestPresetParses) {
  EXPECT_EQ(errorFor(test::stillPreset()), "");
  const ParticlePreset p = parseParticlePreset(test::stillPreset().dump(), "still");
  EXPECT_EQ(p.count, 64u);
  EXPECT_EQ(p.size, std::vector<float>{0.12f});
  EXPECT_EQ(stepsToSteadyState(p), 301u);  // 5 s at 60 steps a second, and one more
}

TEST(ParticlePresets, EveryMissingFieldIsNamed) {
  std::vector<std::string> paths;
  leafPaths(test::stillPreset(), "", paths);
  ASSERT_EQ(paths.size(), 28u);
  for (const std::string& path : paths) {
    json preset = test::stillPreset();
    const json::json_pointer pointer = pointerTo(path);
    preset[pointer.parent_pointer()].erase(pointer.back());
    const std::string error = errorFor(preset);
    EXPECT_NE(error.find("\"" + path + "\" is missing"), std::string::npos) << path << ": " << error;
    EXPECT_NE(error.find("bent.json"), std::string::npos) << error;
  }
}

TEST(ParticlePresets, EveryIllTypedFieldIsNamed) {
  std::vector<std::string> paths;
  leafPaths(test::stillPreset(), "", paths);
  for (const std::string& path : paths) {
    json preset = test::stillPreset();
    preset[pointerTo(path)] = json::object({{"what", "not this"}});
    const std::string error = errorFor(preset);
    EXPECT_NE(error.find("\"" + path), std::string::npos) << path << ": " << error;
  }
}

struct BadValue {
  std::string path;
  json value;
  std::string named;  // what the message must contain besides the path
};

class ParticlePresetValues : public ::testing::TestWithParam<BadValue> {};

TEST_P(ParticlePresetValues, AreRejectedByName) {
  const BadValue& bad = GetParam();
  json preset = test::stillPreset();
  preset[pointerTo(bad.path)] = bad.value;
  const std::string error = errorFor(preset);
  EXPECT_NE(error.find("\"" + bad.path), std::string::npos) << error;
  EXPECT_NE(error.find(bad.named), std::string::npos) << error;
}

INSTANTIATE_TEST_SUITE_P(
    Absurd, ParticlePresetValues,
    ::testing::Values(
        BadValue{"count", 0, "1 to 1000000"}, BadValue{"count", 2000000, "1 to 1000000"},
        BadValue{"count", -5, "1 to 1000000"}, BadValue{"count", 1.5, "whole number"},
        BadValue{"count", "many", "whole number"}, BadValue{"lifetime", json::array({5, 1}), "min <= max"},
        BadValue{"lifetime", json::array({0, 1}), "between 0.05"}, BadValue{"lifetime", 3, "[min, max]"},
        BadValue{"emitter.shape", "cube", "point, disc, sphere"}, BadValue{"emitter.radius", -1, "between 0"},
        BadValue{"velocity.direction", json::array({0, 0, 0}), "zero vector"},
        BadValue{"velocity.direction", json::array({0, 1}), "3 numbers"},
        BadValue{"velocity.spread", 270, "between 0 and 180"},
        BadValue{"velocity.speed", json::array({2, 1}), "min <= max"},
        BadValue{"floor.mode", "lava", "none, bounce, kill"},
        BadValue{"floor.restitution", 1.5, "between 0 and 1"}, BadValue{"size", json::array(), "1 to 8 keys"},
        BadValue{"size", json::array({1, 1, 1, 1, 1, 1, 1, 1, 1}), "1 to 8 keys"},
        BadValue{"size", json::array({0.1, -1}), "size[1]"},
        BadValue{"color", json::array({json::array({1, 1})}), "color[0]"},
        BadValue{"color", json::array({json::array({1, 2, 1})}), "color[0][1]"},
        BadValue{"opacity", json::array({0.5, 1.5}), "opacity[1]"},
        BadValue{"scattering.focus", 0.5, "between 1"}, BadValue{"softness", 0, "between 0.001"},
        BadValue{"additive", "yes", "must be a number"}),
    [](const auto& info) { return "case" + std::to_string(info.index); });

TEST(ParticlePresets, UnknownFieldsAreNamed) {
  json preset = test::stillPreset();
  preset["sped"] = 3;
  EXPECT_NE(errorFor(preset).find("\"sped\" is not a preset field"), std::string::npos) << errorFor(preset);
  preset = test::stillPreset();
  preset["velocity"]["sped"] = 3;
  EXPECT_NE(errorFor(preset).find("\"velocity.sped\""), std::string::npos) << errorFor(preset);
}

TEST(ParticlePresets, NotJsonOrNotAnObject) {
  EXPECT_THROW(parseParticlePreset("{ \"count\": ", "broken.json"), InputError);
  EXPECT_THROW(parseParticlePreset("[1, 2]", "array.json"), InputError);
}

TEST(ParticlePresets, UnknownNameListsTheBuiltins) {
  try {
    loadParticlePreset("fog");
    FAIL() << "no error";
  } catch (const InputError& e) {
    const std::string message = e.what();
    for (const char* name : {"fog", "smoke", "sparks", "dust"})
      EXPECT_NE(message.find(name), std::string::npos) << message;
  }
}

TEST(ParticlePresets, FilesLoadByPath) {
  json preset = test::stillPreset();
  preset["count"] = 77;
  const ParticlePreset p = loadParticlePreset(test::writePreset(preset, "by-path"));
  EXPECT_EQ(p.count, 77u);
}

}  // namespace
}  // namespace lll
