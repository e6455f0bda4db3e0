#pragma once
// Everything a user can set about a rendered frame. The CLI fills it; techniques read the fields
// that concern them. Options that name one of a few choices are enums, their names written once
// beside them (core/enum_names.h): parsed when the CLI reads them, never compared as strings.
#include <algorithm>
#include <array>
#include <cstdint>
#include <string>
#include <string_view>

#include "core/enum_names.h"

namespace lll {

// Where moving lights are placed each frame (Renderer::moveLightsTo): gpu (a pass writes their
// positions: render/moving_lights.h) | cpu (placed in the scene's lights, the array uploaded
// again) | auto (the GPU unless something reads their positions on the CPU: deferred's and the
// pre-pass's light volumes, local shadows, VPLs that follow the lights).
enum class LightPlacement : uint8_t { Auto, Gpu, Cpu };
template <>
struct EnumNames<LightPlacement> {
  static constexpr std::array<std::string_view, 3> names{"auto", "gpu", "cpu"};
};

// How lll fills its lists (lighting/lll.h): rasterized light shells, a ray per tile against the
// lights' bounds, or the lights binned to cells in compute.
enum class LllFill : uint8_t { Shells, Ray, Compute };
template <>
struct EnumNames<LllFill> {
  static constexpr std::array<std::string_view, 3> names{"shells", "ray", "compute"};
};

// lll's links: compact (8 bytes, 24-bit next, at most kCompactLinkMaxLights lights) | wide (16
// bytes) | auto (compact while the lights and the pool fit, else wide).
enum class LllLink : uint8_t { Compact, Wide, Auto };
template <>
struct EnumNames<LllLink> {
  static constexpr std::array<std::string_view, 3> names{"compact", "wide", "auto"};
};

// Where lll's opaque shading from the visibility buffer (the default surfaces) reads the records of
// the lights its lists name: storage (the light buffer) | uniform (the same records through a
// uniform block: a GPU's constant cache, which serves a workgroup walking one list in a single read;
// at most kUniformLightRecords lights) | auto (uniform on a GPU while the lights fit; lavapipe folds
// uniform blocks' values into new shader variants, see common/frame.glsl).
enum class LllRecords : uint8_t { Storage, Uniform, Auto };
template <>
struct EnumNames<LllRecords> {
  static constexpr std::array<std::string_view, 3> names{"storage", "uniform", "auto"};
};

// Where lll lights opaque surfaces with the G-buffer path: a compute pass over a thin G-buffer, or
// the fragment shader of a second geometry pass (the chapter's forward shading).
enum class LllShade : uint8_t { Compute, Fragment };
template <>
struct EnumNames<LllShade> {
  static constexpr std::array<std::string_view, 2> names{"compute", "fragment"};
};

// Where opaque surfaces come from: visibility (one raster pass of ids, surfaces rebuilt in
// compute; falls back to gbuffer, with a warning, where the scene or device cannot) | gbuffer
// (the depth prepass, then geometry passes: G-buffer or fragment shading).
enum class SurfaceSource : uint8_t { Visibility, Gbuffer };
template <>
struct EnumNames<SurfaceSource> {
  static constexpr std::array<std::string_view, 2> names{"visibility", "gbuffer"};
};

// How glass is lit: compute (its fragments stored per pixel by a geometry pass, then lit and
// blended in compute) | raster (lit and blended by the geometry pass's fragment shader).
enum class GlassLighting : uint8_t { Compute, Raster };
template <>
struct EnumNames<GlassLighting> {
  static constexpr std::array<std::string_view, 2> names{"compute", "raster"};
};

// Who rasterizes triangles that could go either way (the visibility buffer, the shadow casters):
// the hardware | a compute pass (render/compute_raster.h) | auto (the renderer's measured choice).
enum class RasterChoice : uint8_t { Hardware, Compute, Auto };
template <>
struct EnumNames<RasterChoice> {
  static constexpr std::array<std::string_view, 3> names{"hardware", "compute", "auto"};
};

// --debug-view: the lit image, or lights per pixel as a heat map, lll's light bounds, or tiles
// coloured by their light count. Each technique says which it shows.
enum class DebugView : uint8_t { None, Heatmap, Bounds, Tiles };
template <>
struct EnumNames<DebugView> {
  static constexpr std::array<std::string_view, 4> names{"none", "heatmap", "bounds", "tiles"};
};

// Deferred shading's glass and smoke: left unlit (the seeds' Figure 1.1) or lit by a forward pass.
enum class TranslucentLighting : uint8_t { Unlit, Forward };
template <>
struct EnumNames<TranslucentLighting> {
  static constexpr std::array<std::string_view, 2> names{"unlit", "forward"};
};

// Deferred shading's anti-aliasing: none, or edge detection over the G-buffer.
enum class AntiAliasing : uint8_t { None, Edge };
template <>
struct EnumNames<AntiAliasing> {
  static constexpr std::array<std::string_view, 2> names{"none", "edge"};
};

// Where particles are lit (--particle-lighting).
enum class ParticleLighting : uint8_t {
  Pixel,   // every covered pixel, with a sphere-like normal across the quad
  Atlas,   // on a few texels per particle in compute (particles-light), interpolated per pixel
  Vertex,  // once per particle at its centre, in compute (particles-light), facing the camera
};
template <>
struct EnumNames<ParticleLighting> {
  static constexpr std::array<std::string_view, 3> names{"pixel", "atlas", "vertex"};
};

// How the particles reach the frame (--particle-render).
enum class ParticleRender : uint8_t {
  Auto,     // compute on a GPU, raster on a CPU device (see ParticleSystem's constructor)
  Raster,   // camera-facing quads blended back to front by the rasterizer (particle_draw.cpp)
  Compute,  // tiles of a compute pass blending each pixel front to back (particle_tiles.cpp)
};
template <>
struct EnumNames<ParticleRender> {
  static constexpr std::array<std::string_view, 3> names{"auto", "raster", "compute"};
};

// The resolution particles are blended at by the compute renderer, upsampled with the depth.
enum class ParticleResolution : uint8_t { Full, Half, Quarter };
template <>
struct EnumNames<ParticleResolution> {
  static constexpr std::array<std::string_view, 3> names{"full", "half", "quarter"};
};
// Frame pixels per particle pixel along each axis: 1, 2 or 4.
constexpr uint32_t particleResolutionScale(ParticleResolution resolution) {
  return 1u << static_cast<uint32_t>(resolution);
}

// Shadows: sun (shadows/sun_shadows.h) | all (the sun and the --shadow-lights most important local
// lights, shadows/local_shadows.h) | none.
enum class ShadowMode : uint8_t { Sun, All, None };
template <>
struct EnumNames<ShadowMode> {
  static constexpr std::array<std::string_view, 3> names{"sun", "all", "none"};
};

// Shadow map filtering: pcf (3x3 bilinear comparisons) | none (one texel, nearest).
enum class ShadowFilter : uint8_t { Pcf, None };
template <>
struct EnumNames<ShadowFilter> {
  static constexpr std::array<std::string_view, 2> names{"pcf", "none"};
};

struct RenderSettings {
  uint32_t width = 1280;
  uint32_t height = 720;
  std::string technique = "forward";
  std::string camera;  // a camera name, "eye,target" as six numbers, or empty for the scene's first
  uint32_t frames = 1;
  // --animate: the moving lights advance kAnimationFrameSeconds each frame (scene/light_animation.h).
  bool animateLights = false;
  LightPlacement lightMotion = LightPlacement::Auto;
  float exposure = 1.0f;
  float ambient = 0.02f;  // constant ambient radiance, so unlit corners are not pitch black
  // Light Linked List options (technique "lll").
  LllFill lllFill = LllFill::Compute;
  LllLink lllLink = LllLink::Auto;
  LllRecords lllRecords = LllRecords::Auto;
  LllShade lllShade = LllShade::Compute;
  SurfaceSource surfaces = SurfaceSource::Visibility;
  GlassLighting glass = GlassLighting::Compute;
  // Who rasterizes the visibility buffer's opaque triangles; auto: compute where it was measured
  // faster, a discrete GPU.
  RasterChoice raster = RasterChoice::Auto;
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
  DebugView debugView = DebugView::None;
  // Clustered shading (technique "clustered"): depth slices per tile behind its front slice.
  uint32_t clusterSlices = 16;
  // Deferred shading options (technique "deferred").
  TranslucentLighting deferredTranslucent = TranslucentLighting::Forward;
  AntiAliasing antiAliasing = AntiAliasing::None;
  // Particles: a preset name or JSON path; empty for none.
  std::string particles;
  // Non-empty: the preset's JSON text itself, read instead of loading `particles` (which then only
  // names it in messages): the viewer's preset editor hands its edits over this way.
  std::string particlePresetJson;
  ParticleLighting particleLighting = ParticleLighting::Pixel;
  ParticleRender particleRender = ParticleRender::Auto;
  ParticleResolution particleResolution = ParticleResolution::Full;
  uint32_t particleTileGroups = 0;  // workgroups a particle tile's slabs go to; 0: the renderer's choice
  uint32_t particleCount = 0;       // 0: the preset's own count
  std::string particleEmitter;      // "x,y,z": where the emitter sits; empty: the scene's smoke source
  uint32_t seed = 1;                // simulation seed (the CLI's --seed)
  // Shadows; cascades and texels along a cascade's side of the sun's; the filter of both.
  ShadowMode shadows = ShadowMode::Sun;
  uint32_t shadowLights = 16;            // K with --shadows all
  uint32_t shadowLightResolution = 512;  // texels along a local light's view's side
  uint32_t cascades = 4;
  uint32_t shadowResolution = 2048;
  ShadowFilter shadowFilter = ShadowFilter::Pcf;
  // Who draws the shadow casters (shadows/shadow_raster.h); auto: compute on a GPU where it fits,
  // hardware on a CPU device.
  RasterChoice shadowRaster = RasterChoice::Auto;
  bool operator==(const RenderSettings&) const = default;
};

// Lists per tile of lll's light lists (--lll-slices; 0 means 1).
inline uint32_t lllListsPerTile(const RenderSettings& settings) {
  return std::max(settings.lllSlices, 1u);
}

}  // namespace lll
