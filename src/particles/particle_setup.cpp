#include "particles/particle_setup.h"

#include <fmt/format.h>

#include <cmath>
#include <sstream>

#include "core/errors.h"

namespace lll {

glm::vec3 parseEmitterPosition(const std::string& text) {
  std::istringstream in(text);
  glm::vec3 p{0.0f};
  char comma1 = 0, comma2 = 0;
  if (!(in >> p.x >> comma1 >> p.y >> comma2 >> p.z) || comma1 != ',' || comma2 != ',' ||
      !(in >> std::ws).eof() || !std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z))
    throw InputError(fmt::format("--particle-emitter {}: expected three numbers \"x,y,z\"", text));
  return p;
}

ParticlePreset settingsParticlePreset(const RenderSettings& settings) {
  return settings.particlePresetJson.empty()
             ? loadParticlePreset(settings.particles)
             : parseParticlePreset(settings.particlePresetJson, settings.particles);
}

std::optional<ParticleSystemOptions> particleOptions(const Scene& scene, const RenderSettings& settings) {
  if (settings.particles.empty()) return std::nullopt;
  ParticleSystemOptions options;
  options.preset = settingsParticlePreset(settings);
  options.lighting = settings.particleLighting;
  options.render = settings.particleRender;
  options.resolutionScale = particleResolutionScale(settings.particleResolution);
  options.tileGroups = settings.particleTileGroups;
  if (options.resolutionScale > 1 && options.render == ParticleRender::Raster)
    throw InputError(
        fmt::format("--particle-resolution {}: only --particle-render compute (or auto) draws "
                    "particles below full resolution",
                    settings.particleResolution));
  if (settings.particleTileGroups > gpu::kParticleMaxGroups)
    throw InputError(fmt::format("--particle-tile-groups {}: a particle tile goes to 1 to {} workgroups",
                                 settings.particleTileGroups, gpu::kParticleMaxGroups));
  if (settings.particleTileGroups != 0 && options.render == ParticleRender::Raster)
    throw InputError(
        fmt::format("--particle-tile-groups {}: only --particle-render compute (or auto) "
                    "shares particle tiles out to workgroups",
                    settings.particleTileGroups));
  if (settings.particleCount > gpu::kMaxParticles)
    throw InputError(fmt::format("--particle-count {}: a particle system holds 1 to {} particles",
                                 settings.particleCount, gpu::kMaxParticles));
  options.count = settings.particleCount;
  options.seed = settings.seed;
  if (!settings.particleEmitter.empty())
    options.source = parseEmitterPosition(settings.particleEmitter);
  else if (scene.smokeSource)
    options.source = *scene.smokeSource;
  else
    throw InputError(
        fmt::format("--particles {}: the scene {} has no smoke source; place the emitter with "
                    "--particle-emitter x,y,z",
                    settings.particles, scene.name));
  return options;
}

}  // namespace lll
