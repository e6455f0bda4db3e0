#pragma once
// Instant radiosity that follows moving lights (issue 15): the photons of the lights that move are
// traced again, a budgeted share each frame, and the VPLs of the grid cells they leave or land in
// are rebuilt; everything else stays as traced when the scene loaded.
//
// - Stable: photon p always draws from the stream Random(seed, p) (gi/photon_walk.h), so a photon
//   traced again from a light that has not moved lands exactly where it did, and a VPL changes only
//   where a light's light really moved. Nothing flickers; a moving light's indirect light lags by
//   at most the frames one round of its photons takes (moving photons / budget).
// - The grid is fixed when the scene loads: the cell edge the merge chose then (gi/photons.h), cells
//   counted from the scene's lower corner. A cell sums its deposits' flux and flux-weighted position
//   and normal in doubles; a re-traced photon's old deposits are subtracted and its new ones added.
// - The VPLs sit in a fixed block of the scene's lights, so that the light count (and every buffer
//   and list format sized by it) does not change: the load's cells plus a quarter more (at least 64)
//   as room for the cells a moving light reaches later. A slot without a lit cell holds a dark light
//   (intensity 0, a short range where its cell was). When every slot is taken a newly lit cell gets
//   none and its light is missing until one frees; stats().droppedCells counts such cells.
// - Ranges use the cutoff irradiance of the load (gi/photons.h): a VPL's range follows its own flux
//   only, so ranges do not pulse with the scene's total.
// - With the lighting grid hierarchy (VplOptions::hierarchy, gi/vpl_hierarchy.h) every level is such
//   a grid: its levels and their bands are those the load's deposits give, fixed from then on, and
//   every deposit is added to (and taken from) its cell on each level; the slots hold every level's
//   VPLs.
#include <cstdint>
#include <memory>
#include <unordered_map>
#include <vector>

#include "gi/photons.h"
#include "gi/vpl_hierarchy.h"
#include "scene/scene.h"

namespace lll::gi {

struct MovingVplStats {
  uint64_t movingPhotons = 0;  // photons whose light moves: the ones traced again
  uint64_t retraced = 0;       // in the last update
  double retraceMs = 0.0;      // the last update's CPU time: placing, tracing, merging, writing
  double traceMs = 0.0;        // of which tracing
  double mergeMs = 0.0;        // of which the cells' sums and their VPLs
  uint32_t slots = 0;          // the VPL block's size in the scene's lights
  uint32_t litSlots = 0;       // slots holding a lit cell
  uint32_t droppedCells = 0;   // lit cells without a slot (their light is missing)
};

class MovingVpls {
 public:
  // `scene`: its lights placed where they are now, VPLs not yet added; `scene.lightAnimation` says
  // which lights move. `grids` empty lets the load's deposits choose them (the merge's edge for
  // options.vplCount, which must not be 0, and with options.hierarchy the levels above it); else
  // they are another MovingVpls' levels(). `maxSlots` caps the VPL block. `stats` (optional)
  // receives the initial trace's numbers.
  MovingVpls(const Scene& scene, const VplOptions& options, uint32_t retracePerFrame, uint32_t maxSlots,
             std::vector<VplLevel> grids = {}, PhotonStats* stats = nullptr);
  MovingVpls(const MovingVpls&);  // the ray scene shared (read-only), the rest copied
  MovingVpls& operator=(const MovingVpls&) = delete;
  ~MovingVpls();

  // The VPL block: every slot, dark ones included.
  const std::vector<Light>& vpls() const { return vpls_; }
  // The grids the deposits merge on: one, or the hierarchy's levels.
  const std::vector<VplLevel>& levels() const { return levels_; }
  const MovingVplStats& stats() const { return stats_; }

  // Moves the emitting lights to `seconds`, traces the next `retracePerFrame` of the moving lights'
  // photons again (in a fixed round) and rewrites the slots whose cells changed, in `vpls()` and in
  // `lights[first ...]`. Deterministic for a sequence of calls, whatever the thread count.
  void moveTo(float seconds, std::vector<Light>& lights, uint32_t first);

 private:
  struct Cell {
    uint64_t key = 0;  // walk::cellKey on its level's grid
    uint32_t level = 0;
    glm::dvec3 flux{0.0}, position{0.0}, normal{0.0};
    double weight = 0.0;
    uint32_t deposits = 0;
    int32_t slot = -1;
    bool dropped = false;  // lit, but no slot was free
    bool dirty = false;    // changed since its VPL was last written
    glm::vec3 lastPosition{0.0f};
  };
  uint32_t cellFor(const PhotonDeposit& d, uint32_t level);  // its cell on a level, made when new
  void add(uint32_t cell, const PhotonDeposit& d, double sign);
  void refresh(uint32_t cell);
  void refreshDirtyCells();
  Light darkVpl(const glm::vec3& position) const;

  std::shared_ptr<const RayScene> rays_;
  std::vector<Light> lights_;  // the emitters, moved here
  std::vector<DirectionalLight> suns_;
  LightAnimation animation_;
  Bounds bounds_;
  VplOptions options_;
  uint32_t retracePerFrame_ = 0;
  // The grids: one without the hierarchy (its VPLs' ranges from reach_), else its levels (their bands).
  std::vector<VplLevel> levels_;
  bool banded() const { return levels_.front().outer > 0.0f; }
  VplReach reach_;

  std::vector<uint32_t> movingPhotons_;        // photon indices, ascending
  std::vector<PhotonDeposit> movingDeposits_;  // options.bounces slots per moving photon
  std::vector<uint32_t> movingCells_;          // the cell of each of those deposits on each level
  std::vector<uint8_t> movingCounts_;
  size_t cursor_ = 0;  // the next moving photon to trace again

  std::vector<std::unordered_map<uint64_t, uint32_t>> cellOf_;  // per level
  std::vector<Cell> cells_;
  std::vector<uint32_t> dirty_;
  std::vector<uint32_t> freeSlots_;  // a min-heap: the lowest free slot is reused first
  std::vector<Light> vpls_;
  std::vector<uint32_t> changedSlots_;
  MovingVplStats stats_;
};

// A copy with its own state (the ray scene shared): MovingIndirectLight::clone.
std::shared_ptr<MovingVpls> cloneMovingVpls(const MovingVpls& vpls);

}  // namespace lll::gi
