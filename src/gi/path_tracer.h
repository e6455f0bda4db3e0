#pragma once
// The path-traced reference for instant radiosity (`lll reference`): what the virtual point lights
// (gi/photons.h) approximate, computed by brute force on the CPU with Embree, to compare against.
//
// What it computes, per pixel:
// - One primary ray through the pixel's centre, the point the rasterizer shades (no jitter: a
//   jittered reference would be blurred at every edge where the renderer is not). Samples differ
//   only in what they trace beyond the camera's hit x.
// - At x, the radiance towards the eye through the renderer's BRDF (gi/brdf.h, brdf.glsl): emission
//   plus direct light from every point, spot and box light with a shadow ray (next-event
//   estimation, the renderer's attenuation exactly) unless indirectOnly; plus indirect light: a
//   cosine-distributed direction about the shading normal, weighted by brdfCosine / pdf.
// - Beyond x, light interreflects DIFFUSELY only: a hit y sends back albedo / pi times its
//   irradiance, albedo = (1 - metallic) * base colour, the irradiance being direct light (shadow
//   rays) plus, for the remaining bounces, a cosine-sampled ray's radiance times pi. This is what
//   instant radiosity computes too: its VPLs are Lambertian emitters at diffuse deposits, with no
//   metal or specular bounce. `bounces` counts those diffuse bounces (1: one-bounce indirect).
// - Blended (glass) surfaces are crossed with probability 1 - coverage, by every ray (shadow rays
//   too), as the photon tracer crosses them; alpha-masked ones as RayScene says. Emissive materials
//   light nothing (in the renderer emission is not a light source either). No constant ambient.
// - Lights: with up to kAllLightsLimit lights, every light gets a shadow ray at every shading
//   point. With more, one light per shading point is picked in proportion to its power (intensity
//   x mean colour x emission solid angle, the photon tracer's choice) and weighted by 1 / its
//   probability: unbiased, cheap for millions of lights, but noisy where many small lights each
//   light a little: raise spp.
// - Virtual point lights (LightType::Vpl) in the scene are skipped: they are what is compared.
//   Except with `vpls` (`lll reference --vpls shadowed|unshadowed`): then a sample is the scene's
//   VPLs alone summed at the camera's hit, every VPL with its attenuation and lobe as the renderer
//   lights it (brdf.glsl), without (unshadowed: what the renderer computes) or with a shadow ray
//   each (to the VPL's position lifted off its surface; glass crossed as above): how much of the
//   difference between the renderer's VPL light and the path-traced indirect light is the VPLs'
//   missing visibility. No emission, direct or path-traced light then.
// Limits: normal maps are not applied (the interpolated vertex normal shades), single-sided
// surfaces are hit from behind too (the rasterizer culls them), particles are not drawn.
//
// Deterministic for a seed whatever the thread count: each pixel draws from its own random stream.
#include <cstdint>
#include <functional>
#include <glm/glm.hpp>
#include <vector>

#include "core/enum_names.h"
#include "gi/photons.h"
#include "scene/scene.h"

namespace lll::gi {

inline constexpr uint32_t kDefaultReferenceSpp = 64;
// Past this, a reference at the largest resolution would take months on a workstation.
inline constexpr uint32_t kMaxReferenceSpp = 1u << 16;
// Next-event estimation over every light up to this many: the built-in scenes have a handful.
inline constexpr size_t kAllLightsLimit = 64;
inline constexpr uint32_t kMaxReferenceThreads = 1024;

// --vpls of `lll reference`: path tracing (off), or the scene's VPLs summed at the camera's hits,
// without or with a shadow ray to each.
enum class VplGather : uint8_t { Off, Unshadowed, Shadowed };

}  // namespace lll::gi

template <>
struct lll::EnumNames<lll::gi::VplGather> {
  static constexpr std::array<std::string_view, 3> names{"off", "unshadowed", "shadowed"};
};

namespace lll::gi {

struct ReferenceOptions {
  uint32_t spp = kDefaultReferenceSpp;  // samples per pixel, all through the pixel's centre
  uint32_t bounces = kDefaultBounces;   // diffuse bounces of indirect light, 0 to kMaxBounces
  bool indirectOnly = false;            // leave out emission and direct light at the camera's hit
  VplGather vpls = VplGather::Off;      // the scene's VPLs summed instead (above)
  uint32_t seed = 1;
  uint32_t threads = 0;  // 0: one per hardware thread
  // Called with the fraction of rows done (0..1), from the rendering threads, one call at a time.
  std::function<void(double)> progress;
};

// Linear radiance, row 0 at the top.
struct RadianceImage {
  uint32_t width = 0;
  uint32_t height = 0;
  std::vector<glm::vec3> rgb;
  const glm::vec3& at(uint32_t x, uint32_t y) const { return rgb[size_t(y) * width + x]; }
};

// The rays through pixel centres of the renderer's view and projection (renderer/renderer.cpp:
// lookAt with the camera's up, or -z when up is along the view; perspective at yfov and the image's
// aspect ratio; row 0 at the top).
class PixelRays {
 public:
  PixelRays(const Camera& camera, uint32_t width, uint32_t height);
  const glm::vec3& origin() const { return eye_; }
  // Unit direction through the centre of pixel (x, y).
  glm::vec3 direction(uint32_t x, uint32_t y) const;

 private:
  glm::vec3 eye_, forward_, right_, up_;
  float tanHalfX_, tanHalfY_;
  float invWidth_, invHeight_;
};

// Throws InputError naming the option (--spp, --bounces, --threads, --vpls) when one is out of range
// or they do not go together.
void validateReferenceOptions(const ReferenceOptions& options);

// Throws InputError for bad options (above) and std::runtime_error when Embree fails.
RadianceImage renderReference(const Scene& scene, const Camera& camera, uint32_t width, uint32_t height,
                              const ReferenceOptions& options);

}  // namespace lll::gi
