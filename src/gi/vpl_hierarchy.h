#pragma once
// A lighting grid hierarchy over the virtual point lights (--vpl-hierarchy grid), after Yuksel and
// Yuksel 2017 ("Lighting Grid Hierarchy for Self-illuminating Explosions") and Lin and Yuksel 2019
// ("Real-Time Rendering with Lighting Grid Hierarchy"): the deposits are merged on grids whose cell
// edge doubles from level to level, and each level's VPLs light only a band of distances about
// them, near ones from the fine levels and far ones from the coarse ones. Every VPL is then a light
// of bounded range, so the light lists (and every other technique) handle the hierarchy as they
// handle any light: no tree is walked per pixel.
//
// Level l has cell edge h_l = h_0 2^l and radius r_l = alpha h_l. Its VPLs weigh
//   rise_l(d) * fall_l(d),  rise_l = S((d - r_(l-1)) / r_(l-1)),  fall_l = 1 - S((d - r_l) / r_l),
// d the distance from the VPL, S the smoothstep on [0, 1]; level 0 has no rise (full weight at the
// VPL) and the top level no fall within the scene. Since r_l = 2 r_(l-1), fall_(l-1) + rise_l = 1 on
// [r_(l-1), r_l]: a deposit that its cell holds alone at every level gets weights that sum to
// exactly 1 at every distance (a partition of unity); merged deposits are stood for by their cell's
// VPL where they are far enough that the cell looks like a point (at least alpha / 2 cells away).
// A VPL of level l reaches 2 r_l: its range. Larger alpha is more accurate and puts more VPLs in
// every list (about alpha^2 as many).
//
// Each level merges the deposits as the single-grid merge does (gi/photons.h: six normal buckets per
// cell, flux summed, position and normal flux-weighted), so level 0 is exactly mergeDeposits' VPLs
// for the same cell edge. A level whose cells group the deposits as the level below does (every
// coarse cell holds one fine cell) would repeat the level below's VPLs: that level's band is given
// to the one below instead, which is exact.
#include <cstdint>
#include <vector>

#include "gi/photons.h"
#include "scene/scene.h"

namespace lll::gi {

// A level of at most this many VPLs is the top one (a cell per normal bucket is six).
inline constexpr uint32_t kHierarchyTopLights = 8;

// One grid of the hierarchy and the band of distances its VPLs light.
struct VplLevel {
  float cellEdge = 0.0f;
  float nearDistance = 0.0f;  // the 1/d^2 clamp of its VPLs
  float inner = 0.0f;         // the band rises from inner to 2 inner (0: full weight at the VPL)
  float outer = 0.0f;         // and falls from outer to 2 outer, the VPLs' range
};

struct VplHierarchy {
  std::vector<VplLevel> levels;
  std::vector<Light> lights;         // level by level
  std::vector<uint32_t> firstLight;  // where each level's lights begin; levels.size() + 1 entries
};

// Gives a VPL its level's band (Light::bandInner, bandOuter), near distance and range (2 outer).
void setVplBand(Light& vpl, const VplLevel& level);

// The hierarchy over `deposits`: grids from `origin`, level 0's cell edge `finestEdge`, bands of
// radius alpha cells. `sceneReach` is the farthest a lit point can be from a deposit (the scene's
// diagonal): the top level, the first of at most kHierarchyTopLights VPLs or whose radius reaches it,
// keeps full weight out to it. `minNearDistance` bounds every level's near distance from below.
VplHierarchy buildVplHierarchy(const std::vector<PhotonDeposit>& deposits, const glm::vec3& origin,
                               float finestEdge, float alpha, float sceneReach, float minNearDistance);

}  // namespace lll::gi
