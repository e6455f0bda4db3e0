#pragma once
// Particle presets written by the tests: a complete, valid preset as JSON that each test bends
// (no motion, no forces, white, fully opaque), and a helper that writes one to a temporary file.
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>

namespace lll::test {

// Still, white, opaque particles scattered in a sphere around the source: each stays where it was
// born for its whole life, so tests can find it again.
inline nlohmann::json stillPreset() {
  return nlohmann::json::parse(R"({
    "description": "test: still white puffs in a sphere",
    "count": 64,
    "lifetime": [5.0, 5.0],
    "emitter": {"shape": "sphere", "radius": 3.0, "offset": [0, 0, 0]},
    "velocity": {"direction": [0, 1, 0], "spread": 0, "speed": [0, 0]},
    "gravity": [0, 0, 0],
    "buoyancy": 0,
    "drag": 0,
    "turbulence": {"strength": 0, "size": 1, "speed": 0},
    "spin": 0,
    "floor": {"mode": "none", "restitution": 0},
    "size": [0.12],
    "sizeVariation": 0,
    "color": [[1, 1, 1]],
    "colorVariation": 0,
    "opacity": [1],
    "emission": [0],
    "scattering": {"wrap": 0.5, "back": 0, "focus": 1},
    "softness": 0.05,
    "additive": 0
  })");
}

// Writes `preset` to a file unique to this process and returns its path.
inline std::string writePreset(const nlohmann::json& preset, const std::string& name) {
  const std::filesystem::path path = std::filesystem::temp_directory_path() /
                                     ("lll-test-" + name + "-" + std::to_string(getpid()) + ".json");
  std::ofstream(path) << preset.dump(2);
  return path.string();
}

}  // namespace lll::test
