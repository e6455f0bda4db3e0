#pragma once
// The light grids users ship today, as lll's peers: per-tile (tiled, Forward+) or per-cluster
// (clustered) arrays of light indices, built in compute each frame and walked by every shading
// pass through the "grid" lighting interface (shaders/lighting/grid/lighting.glsl).
// Passes: grid-clear -> bins-clear -> grid-tile-range (each tile's nearest and farthest surface)
// -> bins-count/scan/scatter (lighting/light_bins.h) -> grid-count (lights per cluster) ->
// grid-alloc (each tile's ranges) -> grid-write (the indices) -> grid-finish (checks, statistics).
// Each tile has `slices` clusters: slice 0 holds the lights in front of the tile's nearest surface
// (what glass and particles there need), slices 1.. split [nearest, farthest] exponentially.
// Tiled is 2 slices: Harada's per-tile min/max culling plus the front list; clustered is
// 1 + --cluster-slices.
#include <glm/glm.hpp>
#include <memory>
#include <vector>

#include "lighting/technique.h"

namespace lll {

// The grid of the last rendered frame, read back (for tests and tools).
struct LightGridLists {
  uint32_t tilesX = 0;
  uint32_t tilesY = 0;
  uint32_t slices = 0;
  std::vector<glm::vec2> tileRange;             // nearest, farthest linear depth per tile
  std::vector<std::vector<uint32_t>> clusters;  // per cluster (tile * slices + slice): light indices
};

// Reads the lists back from a "tiled" or "clustered" technique; throws std::invalid_argument for
// another one.
LightGridLists readLightGrid(Technique& technique);

std::unique_ptr<Technique> createLightGrid(Context& context, const GpuScene& scene,
                                           const RenderSettings& settings, const FrameTargets& targets,
                                           const VisibilityBuffer* visibility, uint32_t slices);

}  // namespace lll
