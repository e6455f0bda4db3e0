#include "gi/vpl_hierarchy.h"

#include <algorithm>

#include "gi/photon_walk.h"

namespace lll::gi {

namespace {

// More levels than a 20-bit grid key can tell apart cannot be asked for.
constexpr uint32_t kMaxLevels = 24;

}  // namespace

void setVplBand(Light& vpl, const VplLevel& level) {
  vpl.nearDistance = level.nearDistance;
  vpl.bandInner = level.inner;
  vpl.bandOuter = level.outer;
  vpl.range = 2.0f * level.outer;
}

VplHierarchy buildVplHierarchy(const std::vector<PhotonDeposit>& deposits, const glm::vec3& origin,
                               float finestEdge, float alpha, float sceneReach, float minNearDistance) {
  VplHierarchy h;
  if (deposits.empty()) {
    h.firstLight.push_back(0);
    return h;
  }
  std::vector<std::vector<Light>> perLevel;
  float edge = finestEdge;
  for (uint32_t l = 0; l < kMaxLevels; ++l, edge *= 2.0f) {  // doubling is exact: the grids nest
    const float radius = alpha * edge;
    // Near distance and range are the level's (setVplBand, below).
    std::vector<Light> lights = walk::mergeOnGrid(deposits, origin, edge, 0.0f, VplReach{0.0f, 1.0f});
    if (!perLevel.empty() && lights.size() == perLevel.back().size()) {
      // Every cell holds what one cell of the level below holds: the same VPLs, so the level below
      // takes this level's band (its fall moves out to this level's).
      h.levels.back().outer = radius;
    } else {
      h.levels.push_back(
          {edge, std::max(0.5f * edge, minNearDistance), l == 0 ? 0.0f : 0.5f * radius, radius});
      perLevel.push_back(std::move(lights));
    }
    if (perLevel.back().size() <= kHierarchyTopLights || radius >= sceneReach) break;
  }
  h.levels.back().outer = std::max(h.levels.back().outer, sceneReach);
  for (size_t l = 0; l < h.levels.size(); ++l) {
    h.firstLight.push_back(uint32_t(h.lights.size()));
    for (Light& vpl : perLevel[l]) {
      setVplBand(vpl, h.levels[l]);
      h.lights.push_back(vpl);
    }
  }
  h.firstLight.push_back(uint32_t(h.lights.size()));
  return h;
}

}  // namespace lll::gi
