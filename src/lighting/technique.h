#pragma once
// A lighting technique: what turns the visibility (or depth) pass and the scene into lit HDR
// radiance. One technique = one .cpp file in src/lighting/ plus its shaders (at least its lighting
// interface, shaders/lighting/<name>/lighting.glsl), registered in registry.cpp.
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "render/frame.h"
#include "render/lighting_interface.h"

namespace lll {

// The frame every technique shares (renderer/renderer.h): visibility (or depth) pass -> the
// technique's light data passes -> opaque shading (its own, or the shared pass through its lighting
// interface) -> glass -> particles -> tonemap. A technique is the parts that are its own.
class Technique {
 public:
  virtual ~Technique() = default;

  // The passes that build this frame's light data (lll: its lists), recorded after the visibility
  // or depth pass: frame.targets.depth is DEPTH_READ_ONLY_OPTIMAL.
  virtual void buildLightData(FrameContext& frame) { (void)frame; }

  // How opaque surfaces are lit; for OpaqueShading::Own the technique's shadeOpaque records it.
  virtual OpaqueShading opaqueShading() const = 0;
  // Own opaque shading: on entry hdr is COLOR_ATTACHMENT_OPTIMAL with undefined contents; on exit
  // it holds the lit opaque frame, still COLOR_ATTACHMENT_OPTIMAL.
  virtual void shadeOpaque(FrameContext& frame) { (void)frame; }

  // The lighting interface the shared passes (opaque shading unless Own, glass, particles) use.
  virtual LightingInterface lighting() const = 0;

  // Called once the frame's GPU work completed. Returning true asks the renderer to record the
  // same frame again (the light linked list grows its pool on overflow and says so here).
  virtual bool afterFrame() { return false; }

  // Technique-specific numbers for --stats (links used, pool bytes, G-buffer bytes, ...).
  virtual std::vector<std::pair<std::string, double>> stats() const { return {}; }
};

struct TechniqueInfo {
  std::string name;
  std::string description;
  // `visibility` is the frame's visibility buffer, null with --surfaces gbuffer.
  std::unique_ptr<Technique> (*create)(Context& context, const GpuScene& scene,
                                       const RenderSettings& settings, const FrameTargets& targets,
                                       const VisibilityBuffer* visibility);
  // Whether, with these settings, the technique draws opaque geometry again with an EQUAL depth
  // test against the visibility pass (a G-buffer, the pre-pass's normals, fragment shading): that
  // needs the hardware's depth bit for bit, so --raster auto keeps the hardware pass for it.
  bool (*redrawsOpaque)(const RenderSettings& settings) = nullptr;
  // The tile size (pixels) when --tile is not given, each technique's fastest measured on the H200
  // (bench/README.md, 2026-12-03): lll 16, tiled and clustered 8.
  uint32_t defaultTile = 8;
  // Whether the technique reads the lights' positions on the CPU each frame (deferred's and the
  // pre-pass's light volumes): moving lights are then placed on the CPU (Renderer::moveLightsTo).
  bool readsLightsOnCpu = false;
};

const std::vector<TechniqueInfo>& techniques();
// Throws InputError naming the known techniques when `name` is not one of them.
const TechniqueInfo& findTechnique(const std::string& name);
// The tile size `settings` render with: --tile, or its technique's default (0 asks for that).
uint32_t tileSizeFor(const RenderSettings& settings);

}  // namespace lll
