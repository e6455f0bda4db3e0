#pragma once
// Shared by the particle tests: rendering with particles after a number of fixed steps (reading
// the system's buffers back), and the small scenes they light.
#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <string>
#include <vector>

#include "particles/particle_system.h"
#include "scene/mesh_builder.h"
#include "test_support.h"

namespace lll::test {

// Steps of the smoke tests: 5 s, when the first puffs (4 to 6 s lives) have died.
inline constexpr uint32_t kSmokeSteps = 300;

// What a drawn frame left in the particle system, besides the images.
struct ParticleFrame {
  Rendered image;
  std::vector<gpu::Particle> particles;
  std::vector<glm::uvec2> order;
  gpu::ParticleCounters counters{};
  gpu::FrameUniforms uniforms{};
};

// Simulates `steps` fixed steps, the last in a drawn frame, as `lll render --frames steps` does;
// fails the test on any validation message.
inline ParticleFrame renderParticles(const Scene& scene, const RenderSettings& settings, uint32_t steps) {
  Context& context = gpuContext();
  const size_t before = context.validationMessages().size();
  ParticleFrame out;
  {
    Renderer renderer(context, scene, settings);
    renderer.advanceParticles(steps - 1);
    out.image.frame = renderer.renderFrame(true);
    out.image.hdr = renderer.hdrImage();
    out.image.ldr = renderer.ldrImage();
    out.image.stats = renderer.stats();
    out.uniforms = renderer.uniforms();
    if (ParticleSystem* particles = renderer.particles()) {
      out.particles = particles->readParticles();
      out.order = particles->readDrawOrder();
      out.counters = particles->readCounters();
    }
  }
  const auto messages = context.validationMessages();
  for (size_t i = before; i < messages.size(); ++i) ADD_FAILURE() << messages[i];
  return out;
}

// A preset curve at life fraction t, as shaders/particles/particle_data.glsl evaluates it.
inline float curveAt(const std::vector<float>& keys, float t) {
  if (keys.size() == 1) return keys[0];
  const float x = std::clamp(t, 0.0f, 1.0f) * float(keys.size() - 1);
  const size_t i = std::min(size_t(x), keys.size() - 2);
  return glm::mix(keys[i], keys[i + 1], x - float(i));
}

inline bool alive(const gpu::Particle& p) {
  return p.positionAge.w >= 0.0f && p.positionAge.w < p.velocityLifetime.w;
}

// Settled smoke (1,024 particles, 128x72) in `scene`, lit per pixel and once per particle, by lll
// against forward's reference (test_support.h) within kSmokeBound; `settings` carries the rest
// (suns, shadows), `label` names the comparison.
inline void expectSmokeLitAsForward(const Scene& scene, RenderSettings settings, const std::string& label) {
  settings.width = 128;
  settings.height = 72;
  settings.particles = "smoke";
  settings.particleCount = 1024;
  for (const ParticleLighting lighting : {ParticleLighting::Pixel, ParticleLighting::Vertex}) {
    settings.particleLighting = lighting;
    const ParticleFrame forward = renderParticles(scene, reference(settings), kSmokeSteps);
    settings.technique = "lll";
    const ParticleFrame lll = renderParticles(scene, settings, kSmokeSteps);
    expectWithinBound(lll.image.ldr, forward.image.ldr, kSmokeBound,
                      fmt::format("{} {}-lit", label, lighting));
  }
}

inline Material greyMaterial(const char* name, float grey) {
  Material m;
  m.name = name;
  m.baseColorFactor = glm::vec4(grey, grey, grey, 1.0f);
  m.metallic = 0.0f;
  m.roughness = 1.0f;
  return m;
}

// A quad of `size` facing +z, centred at `center`, of `material`.
inline void addWall(Scene& scene, uint32_t material, glm::vec3 center, glm::vec2 size) {
  MeshBuilder quad("wall");
  quad.setMaterial(material);
  quad.addQuad(glm::translate(glm::mat4(1.0f), center) * glm::rotate(glm::mat4(1.0f), kPi / 2, {1, 0, 0}),
               size);
  addInstance(scene, quad.addTo(scene));
}

inline Light pointLight(glm::vec3 position, glm::vec3 color, float intensity, float range) {
  Light l;
  l.position = position;
  l.color = color;
  l.intensity = intensity;
  l.range = range;
  return l;
}

// A grey wall 6 m behind the origin, seen from 6 m in front of it.
inline Scene wallScene() {
  Scene scene;
  scene.name = "particle-wall";
  scene.materials.push_back(greyMaterial("wall", 0.5f));
  addWall(scene, 0, {0, 0, -6}, {30, 30});
  scene.cameras.push_back(Camera{"front", {0, 0, 6}, {0, 0, 0}, {0, 1, 0}, glm::radians(60.0f)});
  return scene;
}

inline RenderSettings settingsFor(const std::string& technique, uint32_t width, uint32_t height) {
  RenderSettings s;
  s.technique = technique;
  s.width = width;
  s.height = height;
  return s;
}

// Pixel of world point `p` (row 0 at the top), and the view depth.
inline glm::vec3 project(const gpu::FrameUniforms& u, glm::vec3 p) {
  const glm::vec4 clip = u.viewProj * glm::vec4(p, 1.0f);
  const glm::vec2 ndc = glm::vec2(clip) / clip.w;
  return {(ndc.x * 0.5f + 0.5f) * u.viewport.x, (ndc.y * 0.5f + 0.5f) * u.viewport.y, clip.w};
}

}  // namespace lll::test
