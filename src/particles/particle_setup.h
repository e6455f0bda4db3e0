#pragma once
// From the render settings to the particle system they ask for: the preset (--particles), where
// its emitter sits (--particle-emitter, else the scene's smoke source), the count, seed and lighting.
#include <optional>
#include <string>

#include "particles/particle_system.h"
#include "render/settings.h"
#include "scene/scene.h"

namespace lll {

// Nothing when settings.particles is empty. Throws InputError for a bad preset, count, lighting or
// emitter, or a scene with no smoke source and no --particle-emitter. Cheap: the CLI calls it before
// starting Vulkan so bad input fails at once.
std::optional<ParticleSystemOptions> particleOptions(const Scene& scene, const RenderSettings& settings);

// The preset the settings name: their particlePresetJson when set (the viewer's editor), else the
// built-in or file `particles` names. Throws InputError as loadParticlePreset does.
ParticlePreset settingsParticlePreset(const RenderSettings& settings);

// "x,y,z" (three finite numbers); throws InputError naming --particle-emitter.
glm::vec3 parseEmitterPosition(const std::string& text);

}  // namespace lll
