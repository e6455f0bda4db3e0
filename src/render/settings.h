#pragma once
// Everything a user can set about a rendered frame. The CLI fills it; techniques read the fields
// that concern them.
#include <algorithm>
#include <cstdint>
#include <string>

namespace lll {

struct RenderSettings {
  uint32_t width = 1280;
  uint32_t height = 720;
  std::string technique = "forward";
  std::string camera;  // a camera name, "eye,target" as six numbers, or empty for the scene's first
  uint32_t frames = 1;
  // --animate: the moving lights advance kAnimationFrameSeconds each frame (scene/light_animation.h).
  bool animateLights = false;
  // Where moving lights are placed each frame (Renderer::moveLightsTo): gpu (a pass writes their
  // positions: render/moving_lights.h) | cpu (placed in the scene's lights, the array uploaded
  // again) | auto (the GPU unless something reads their positions on the CPU: deferred's and the
  // pre-pass's light volumes, local shadows, VPLs that follow the lights).
  std::string lightMotion = "auto";
  float exposure = 1.0f;
  float ambient = 0.02f;  // constant ambient radiance, so unlit corners are not pitch black
  // Light Linked List options (technique "lll").
  std::string lllFill = "compute";   // shells | ray | compute
  std::string lllLink = "auto";      // compact | wide | auto
  std::string lllShade = "compute";  // compute (thin G-buffer + compute pass) | fragment
  // Where opaque surfaces come from: visibility (one raster pass of ids, surfaces rebuilt in
  // compute; falls back to gbuffer, with a warning, where the scene or device cannot) | gbuffer
  // (the depth prepass, then geometry passes: G-buffer or fragment shading).
  std::string surfaces = "visibility";
  // How glass is lit: compute (its fragments stored per pixel by a geometry pass, then lit and
  // blended in compute) | raster (lit and blended by the geometry pass's fragment shader).
  std::string glass = "compute";
  // Who rasterizes the visibility buffer's opaque triangles: hardware | compute
  // (render/compute_raster.h) | auto (compute where it was measured faster: a discrete GPU).
  std::string raster = "auto";
  // Interleaved sampling of the virtual point lights (render/interleaved_vpls.h): each pixel of a
  // K x K block evaluates a K*K-th of them and a filter gathers the rest from its neighbours on the
  // same surface; 1 (off) to kMaxVplInterleave. Opaque shading from the visibility buffer only.
  uint32_t vplInterleave = 1;
  // Light-list tile size in pixels; 0: the technique's own default (TechniqueInfo::defaultTile).
  uint32_t tileSize = 0;
  uint32_t linksPerTile = 32;  // initial link pool: tiles * this, grown on overflow
  // Tests only (no option): the most links a compact pool may hold before --lll-link auto moves to
  // wide links (0: what 24-bit links address, kCompactLinkEnd - 1).
  uint64_t lllCompactLinkLimit = 0;
  // Workgroups sharing each cell's lights in lll's compute fill (1 to 64); 0: by light count.
  uint32_t lllFillSplits = 0;
  // Lists per tile of lll, one per depth slice (Ortegren's clustered linked lists; shared/depth_slices.h
  // says how a tile's depth is split); 1 (or 0): one list per tile, as Bezrati's. Default 2: one list
  // in front of the tile's nearest surface, one over its surfaces (bench/README.md, the slices suite).
  uint32_t lllSlices = 2;
  std::string debugView = "none";  // none | heatmap | bounds | tiles
  // Clustered shading (technique "clustered"): depth slices per tile behind its front slice.
  uint32_t clusterSlices = 16;
  // Deferred shading options (technique "deferred").
  std::string deferredTranslucent = "forward";  // unlit | forward
  std::string antiAliasing = "none";            // none | edge
  // Particles: a preset name or JSON path; empty for none.
  std::string particles;
  // Non-empty: the preset's JSON text itself, read instead of loading `particles` (which then only
  // names it in messages): the viewer's preset editor hands its edits over this way.
  std::string particlePresetJson;
  std::string particleLighting = "pixel";   // pixel | atlas | vertex
  std::string particleRender = "auto";      // auto | raster | compute
  std::string particleResolution = "full";  // full | half | quarter
  uint32_t particleTileGroups = 0;  // workgroups a particle tile's slabs go to; 0: the renderer's choice
  uint32_t particleCount = 0;       // 0: the preset's own count
  std::string particleEmitter;      // "x,y,z": where the emitter sits; empty: the scene's smoke source
  uint32_t seed = 1;                // simulation seed (the CLI's --seed)
  // Shadows: sun (shadows/sun_shadows.h) | all (the sun and the --shadow-lights most important
  // local lights, shadows/local_shadows.h) | none; cascades, texels along a cascade's side, pcf | none
  // (one texel, nearest) for both.
  std::string shadows = "sun";
  uint32_t shadowLights = 16;            // K with --shadows all
  uint32_t shadowLightResolution = 512;  // texels along a local light's view's side
  uint32_t cascades = 4;
  uint32_t shadowResolution = 2048;
  std::string shadowFilter = "pcf";
  // Who draws the shadow casters: hardware | compute (shadows/shadow_raster.h) | auto (compute on a
  // GPU where it fits, hardware on a CPU device).
  std::string shadowRaster = "auto";
  bool operator==(const RenderSettings&) const = default;
};

// Lists per tile of lll's light lists (--lll-slices; 0 means 1).
inline uint32_t lllListsPerTile(const RenderSettings& settings) {
  return std::max(settings.lllSlices, 1u);
}

}  // namespace lll
