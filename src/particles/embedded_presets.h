#pragma once
// The built-in particle presets (particles/presets/*.json), embedded at build time by
// cmake/EmbedText.cmake so `--particles smoke` works from any directory.
#include <span>
#include <string_view>

namespace lll {

struct EmbeddedText {
  std::string_view name;  // the file's name without ".json"
  std::string_view text;
};

// Defined in the generated embeddedParticlePresets.cpp.
std::span<const EmbeddedText> embeddedParticlePresets();

}  // namespace lll
