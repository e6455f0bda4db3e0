#pragma once
// The frame: upload the scene once, then per frame a short list of named, GPU-timed passes:
//   (lights moved on the GPU: lights-move) -> depth-prepass -> (particles: simulate, sort, indirect) -> the
//   technique's passes (drawing the particles after its glass) -> tonemap (-> readback when captured).
#include <algorithm>
#include <memory>
#include <optional>
#include <vector>

#include "gpu/pass_timer.h"
#include "lighting/technique.h"
#include "particles/particle_system.h"
#include "render/frame.h"
#include "render/gpu_scene.h"
#include "render/images.h"
#include "render/moving_lights.h"
#include "render/settings.h"
#include "scene/camera.h"
#include "shadows/local_shadows.h"
#include "shadows/sun_shadows.h"

namespace lll {

class Context;
class VisibilityBuffer;
class LitPasses;

class Renderer {
 public:
  Renderer(Context& context, const Scene& scene, const RenderSettings& settings);
  ~Renderer();

  // Renders one frame; with `capture` the HDR and display images are read back afterwards. With
  // particles, each frame advances the simulation one fixed step (1 / kParticleStepsPerSecond).
  FrameResult renderFrame(bool capture);
  // The scene's lights moved (their positions changed between frames, scene/light_animation.h):
  // writes the light array again, as the scene's lights are now (a time moveLightsTo gave the GPU
  // is dropped); every technique rebuilds its light data each frame anyway.
  void updateLights();
  // Moves `scene`'s animated lights (the scene this renderer draws) to `seconds` for the next
  // frames; nothing when none move. With --light-motion gpu (auto's choice unless the CPU reads
  // their positions: settings.h) the next frames' first pass places them and `scene` is not
  // touched; otherwise they are placed in `scene`, its VPLs follow them (a share of their photons
  // traced again, on the CPU: gi/moving_vpls.h) and the light array is uploaded again.
  void moveLightsTo(Scene& scene, float seconds);
  // Whether moving lights are placed on the GPU (--light-motion).
  bool lightsMoveOnGpu() const { return movingLights_ != nullptr; }
  // Advances the particle simulation `steps` fixed steps without drawing (no-op without particles):
  // `lll render --frames N` simulates N - 1 steps this way, then draws the N-th frame.
  void advanceParticles(uint32_t steps);
  HdrImage hdrImage() const;
  LdrImage ldrImage() const;

  const Camera& camera() const { return camera_; }
  // Draws the next frames from `camera` (an interactive camera); the far plane still comes from
  // the scene's bounds. renderFrame throws InputError when the projection would not be finite.
  void setCamera(const Camera& camera) { camera_ = camera; }
  // Exposure and ambient for the next frames: the only settings that need no new renderer.
  void setExposure(float exposure, float ambient) {
    settings_.exposure = exposure;
    settings_.ambient = ambient;
  }
  // The display image (kLdrFormat, sRGB-encoded) of the last frame, for a window to copy to its
  // swapchain: after renderFrame() it is in displayLayout(), last written by a compute shader
  // (GENERAL) or, after a captured frame, last read by a copy (TRANSFER_SRC_OPTIMAL).
  const Image& displayImage() const { return targets_.ldr; }
  VkImageLayout displayLayout() const {
    return lastCaptured_ ? VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL : VK_IMAGE_LAYOUT_GENERAL;
  }
  const gpu::FrameUniforms& uniforms() const { return uniforms_; }
  Technique& technique() { return *technique_; }
  GpuScene& gpuScene() { return *gpuScene_; }
  const SunShadows& shadows() const { return *shadows_; }
  const LocalShadows& lightShadows() const { return *lightShadows_; }
  ParticleSystem* particles() { return particles_.get(); }
  // The visibility buffer the frame is drawn with, or null (--surfaces gbuffer, or the fallback).
  const VisibilityBuffer* visibility() const { return visibility_.get(); }
  // The technique's numbers for --stats, the scene's instances (all, and inside the frustum in the
  // last frame), then the particle system's.
  std::vector<std::pair<std::string, double>> stats() const;

 private:
  void chooseSurfaces();
  void chooseLightMotion();
  void createTargets();
  // The shared lit passes, compiled with the technique's lighting interface as it is now.
  void createLitPasses();
  void updateUniforms();
  void recordFrame(VkCommandBuffer cmd, bool capture, bool advanceParticles);
  void depthPrepass(FrameContext& frame);
  void glassDepth(FrameContext& frame);
  void tonemap(FrameContext& frame);
  void captureImages(FrameGraph& graph);

  Context& context_;
  const Scene& scene_;
  RenderSettings settings_;
  Camera camera_;
  Bounds sceneBounds_;  // static geometry: computed once, sets the far plane every frame
  gpu::FrameUniforms uniforms_{};
  std::unique_ptr<GpuScene> gpuScene_;
  FrameTargets targets_;
  Buffer uniformBuffer_;
  Buffer hdrReadback_;
  Buffer ldrReadback_;
  PassTimer timer_;
  PipelineLayout depthLayout_;
  Pipeline depthOpaque_;
  Pipeline depthMask_;
  PipelineLayout tonemapLayout_;
  Pipeline tonemap_;
  std::unique_ptr<SunShadows> shadows_;
  std::unique_ptr<LocalShadows> lightShadows_;
  std::unique_ptr<ParticleSystem> particles_;
  std::unique_ptr<VisibilityBuffer> visibility_;  // null with --surfaces gbuffer
  std::string surfacesFallback_;                  // why --surfaces visibility fell back to gbuffer, if it did
  std::unique_ptr<Technique> technique_;
  std::unique_ptr<LitPasses> lit_;              // the shared passes, with the technique's lighting interface
  std::unique_ptr<MovingLights> movingLights_;  // --light-motion gpu; null otherwise
  std::optional<float> gpuLightTime_;           // where movingLights_ places the lights, once moved
  bool lastCaptured_ = false;                   // the last frame was read back (displayLayout())
};

}  // namespace lll
