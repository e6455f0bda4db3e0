#pragma once
// The photon tracer's pieces, shared by the one-off trace (gi/photons.cpp) and the re-trace of
// moving lights' photons (gi/moving_vpls.cpp). Photon p of a trace always draws from the stream
// Random(seed, p): its light first, then its path, so the same p, seed and lights give the same walk.
#include <algorithm>
#include <chrono>
#include <cstdint>
#include <vector>

#include "gi/photons.h"
#include "gi/random.h"

namespace lll::gi::walk {

// A photon source: a punctual light, or a directional one shining through a disk that covers the
// scene's bounding sphere (radius R), so that its flux is illuminance x pi R^2.
struct Emitter {
  const Light* light = nullptr;
  const DirectionalLight* sun = nullptr;
};

struct Emitters {
  std::vector<Emitter> sources;
  std::vector<float> cdf;  // cumulative selection probability, by power
  std::vector<float> probability;
  glm::vec3 sceneCenter{0.0f};
  float sceneRadius = 0.0f;
};

// The lights that emit photons, chosen in proportion to their power (which moving them does not
// change). The emitters point into `lights` and `suns`.
Emitters chooseEmitters(const std::vector<Light>& lights, const std::vector<DirectionalLight>& suns,
                        const Bounds& sceneBounds);

// The photon's light: its stream's first draw.
size_t pickEmitter(const Emitters& emitters, Random& random);

// One photon's walk (its stream fresh: the light is picked first); appends its deposits to `out`
// and returns the flux it left its light with.
glm::vec3 tracePhoton(const RayScene& rays, const Emitters& emitters, uint32_t photonCount, uint32_t bounces,
                      Random& random, std::vector<PhotonDeposit>& out);

// The merge grid's cell of a deposit: 20 bits per cell coordinate (cells from `origin`, clamped),
// 3 for the way its normal leans (normalBucket: dominant axis x 2 + its sign, 0..5).
uint64_t normalBucket(const glm::vec3& normal);
uint64_t cellKey(const glm::vec3& position, const glm::vec3& normal, const glm::vec3& origin, float cell);
inline constexpr float kCellSteps = float(1u << 20) - 2.0f;

// The CPU time the photon work took, for PhotonStats and MovingVplStats.
inline double millisecondsSince(std::chrono::steady_clock::time_point begin) {
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - begin).count();
}

// How much a deposit pulls its merged VPL's position and normal: its flux's luminance.
inline float depositWeight(const glm::vec3& flux) {
  return std::max(0.2126f * flux.r + 0.7152f * flux.g + 0.0722f * flux.b, 1e-30f);
}

// The box the deposits' positions span, and its diagonal (at least 1e-6: never a zero cell).
Bounds depositBounds(const std::vector<PhotonDeposit>& deposits);
inline float boundsDiagonal(const Bounds& bounds) {
  return std::max(glm::length(bounds.extent()), 1e-6f);
}

// The deposits merged on the grid of edge `cell` from `origin` (cellKey's cells): one VPL per cell
// that holds any, its flux the cell's sum, its position and normal flux-weighted (depositWeight),
// in key order.
std::vector<Light> mergeOnGrid(const std::vector<PhotonDeposit>& deposits, const glm::vec3& origin,
                               float cell, float nearDistance, const VplReach& reach);

// The finest grid's edge for `target` VPLs: mergeCellEdge's, or about one cell per deposit when
// there are no more deposits than that.
float finestCellEdge(const std::vector<PhotonDeposit>& deposits, uint32_t target, const glm::vec3& origin,
                     float diagonal);

// The smallest cell edge (within 1%) at which the deposits, keyed from `origin`, fill at most
// `target` cells; `diagonal` is the extent they span.
float mergeCellEdge(const std::vector<PhotonDeposit>& deposits, uint32_t target, const glm::vec3& origin,
                    float diagonal);

}  // namespace lll::gi::walk
