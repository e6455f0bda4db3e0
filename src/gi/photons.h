#pragma once
// Instant radiosity as Infinity lit its hangar (seeds/infinity-deferred-instant-radiosity.txt):
// photons traced from every light through the scene, a deposit where each one lands, deposits in one
// grid cell merged into one virtual point light (VPL). The VPLs are ordinary lights to every
// technique (LightType::Vpl): this is the workload the light lists exist for.
//
// Physics, kept consistent with how the renderer lights a surface directly:
// - A light's photons carry its flux: 4 pi I for a point or box light, I times the cone's solid
//   angle for a spot (weighted by KHR's angular falloff), split over the photons by each light's
//   share. Where a photon lands, the light's own window applies (KHR's range window, a box's
//   face window), so that a wall receives what the direct lighting puts on it.
// - A photon landing on a surface of diffuse albedo rho deposits rho times its flux: the flux the
//   surface reflects, which the VPL re-emits as a Lambertian (cosine) hemisphere about the surface
//   normal, I(theta) = flux / pi * cos(theta). It then survives with probability
//   q = min(1, max(rho)) (Russian roulette) carrying flux * rho / q, in a cosine-distributed
//   direction, for at most `bounces` deposits.
// - Blended (glass) surfaces are crossed with probability 1 - alpha; masked ones where the mask
//   says so (RayScene). Metals and specular lobes do not bounce photons: the VPLs are diffuse.
// - As in Infinity, VPLs cast no shadows: light reaches through walls from a VPL in front of them
//   only where the wall's side faces the VPL's hemisphere.
#include <cstdint>
#include <functional>
#include <glm/glm.hpp>
#include <vector>

#include "scene/scene.h"

namespace lll::gi {

class RayScene;

// Infinity's densest table row: 5,144 ambient point lights at 30 fps on an 8800 GTX.
inline constexpr uint32_t kDefaultVplCount = 5144;
inline constexpr uint32_t kDefaultPhotons = 100000;
inline constexpr uint32_t kDefaultBounces = 2;
inline constexpr uint32_t kMaxBounces = 16;
inline constexpr uint32_t kMaxPhotons = 100000000;
// Where a VPL's range ends (--vpl-cutoff): where its irradiance falls to this fraction of the
// scene's mean indirect irradiance (the VPLs' total flux over the scene's surface area). Smaller
// reaches further: every VPL then touches more pixels, and the light lists grow with it. The
// truncation it costs is measured against the path-traced reference (bench/README.md).
inline constexpr float kDefaultVplCutoff = 1e-3f;

// The lighting grid hierarchy's accuracy alpha (--vpl-alpha; gi/vpl_hierarchy.h): the radius of a
// level's band, in its cells.
inline constexpr float kDefaultHierarchyAlpha = 1.5f;
inline constexpr float kMinHierarchyAlpha = 0.5f, kMaxHierarchyAlpha = 8.0f;

// Photons of the moving lights traced again per frame by default (--vpl-retrace,
// gi/moving_vpls.h).
inline constexpr uint32_t kDefaultRetracePhotons = 8192;

struct VplOptions {
  uint32_t photons = kDefaultPhotons;
  uint32_t bounces = kDefaultBounces;    // deposits per photon at most (1: one-bounce indirect light)
  uint32_t vplCount = kDefaultVplCount;  // merge target; 0 keeps every deposit as its own VPL
  float cutoff = kDefaultVplCutoff;
  // When positive, every VPL's range in metres instead of the cutoff's (at least twice its near
  // distance): a range that does not shrink as the count grows, so more VPLs cost more but err less.
  float range = 0.0f;
  // The lighting grid hierarchy (gi/vpl_hierarchy.h) over the VPLs: vplCount is then its finest
  // level's target, and the levels' bands replace cutoff and range.
  bool hierarchy = false;
  float alpha = kDefaultHierarchyAlpha;
  uint32_t seed = 1;
  uint32_t threads = 0;  // 0: one per hardware thread
  // Called with the fraction of photons traced so far (0..1), from the tracing threads, one call at
  // a time.
  std::function<void(double)> progress;
};

// Where a photon landed and the flux its surface sends back (rgb, in the lights' units x sr).
struct PhotonDeposit {
  glm::vec3 position{0.0f};
  glm::vec3 normal{0.0f, 0.0f, 1.0f};  // facing the side the photon came from
  glm::vec3 flux{0.0f};
};

struct PhotonStats {
  uint64_t photons = 0;
  uint64_t deposits = 0;
  glm::vec3 emittedFlux{0.0f};    // what the photons left the lights with, after the spot falloff
  glm::vec3 depositedFlux{0.0f};  // sum of every deposit
  double traceMs = 0.0;
  double mergeMs = 0.0;
  float cellSize = 0.0f;  // the merge grid's cell edge (0 when not merged); the hierarchy's finest
  uint32_t levels = 0;    // the hierarchy's levels (0 without one)
  uint64_t vpls = 0;
};

// Traces options.photons photons from the scene's point, spot, box and directional lights (its VPLs
// do not emit). A directional light shines through a disk as wide as the scene's bounding sphere,
// from outside it: its flux is illuminance x pi R^2. Deterministic for a seed, whatever the thread
// count.
// `owners` (optional) receives the photon each deposit came from, ascending with the deposits.
std::vector<PhotonDeposit> tracePhotons(const RayScene& rays, const Scene& scene, const VplOptions& options,
                                        PhotonStats* stats = nullptr,
                                        std::vector<uint32_t>* owners = nullptr);

// The irradiance at which a VPL is cut off: `cutoff` times the deposits' total flux over the scene's
// surface area, `surfaceArea` (RayScene::surfaceArea), both sides of every triangle counted: light
// reaches either.
float vplCutoffIrradiance(double surfaceArea, const std::vector<PhotonDeposit>& deposits, float cutoff);

// How far a VPL reaches: `range` metres when positive (--vpl-range), else where its brightest
// channel's irradiance falls to `cutoffIrradiance`; at least twice its near distance either way.
struct VplReach {
  float cutoffIrradiance = 0.0f;
  float range = 0.0f;
};

// Merges deposits on a regular grid (cells of one edge, deposits also split by the axis their
// normal leans to, so the two sides of a thin wall stay apart) into at most `target` VPLs: flux
// summed, position and normal flux-weighted. The cell edge is the smallest (within 1%) that meets
// the target. Each VPL's near distance (the 1/d^2 clamp) is half the cell edge: closer than that
// the point stands for a patch, not a point. target 0 keeps every deposit.
std::vector<Light> mergeDeposits(const std::vector<PhotonDeposit>& deposits, uint32_t target,
                                 float unmergedNearDistance, const VplReach& reach,
                                 PhotonStats* stats = nullptr);

// The light a deposit or a merged cell becomes: intensity flux / pi along the normal, colour
// normalised to its brightest channel, range from `reach`.
Light makeVpl(const glm::vec3& position, const glm::vec3& normal, const glm::vec3& flux, float nearDistance,
              const VplReach& reach);

// tracePhotons then mergeDeposits over the scene's own lights, or with options.hierarchy the
// lighting grid hierarchy (gi/vpl_hierarchy.h) whose finest level has options.vplCount VPLs at most.
std::vector<Light> makeVirtualPointLights(const Scene& scene, const VplOptions& options,
                                          PhotonStats* stats = nullptr);

}  // namespace lll::gi
