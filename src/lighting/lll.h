#pragma once
// Technique "lll": the Light Linked List (Bezrati; ThreeL). Each frame the GPU builds, for every
// screen tile, a linked list of the lights that touch it, then every surface walks its tile's list.
// Its light data passes: lll-tile-depth (which also empties the lists) -> lll-fill-{shells|ray|compute}
// (-> lll-stats on captured frames; the shells' fill first clears its depth bounds in lll-clear); the shared
// passes then walk the lists through its lighting interface (shaders/lighting/lll/lighting.glsl).
#include <cstdint>
#include <glm/vec2.hpp>
#include <memory>
#include <vector>

#include "lighting/technique.h"

namespace lll {

// lll's tile size when --tile is not given (its TechniqueInfo::defaultTile): 16 pixels, faster than 8
// on the H200 for ThreeL's lights and the atrium with 1,024 or 4,096 more, even on the atrium's own
// 110 (bench/README.md, 2026-12-03); Bezrati and ThreeL use 8.
inline constexpr uint32_t kLllDefaultTile = 16;

struct LightLinkRecord {
  uint32_t light;
  float minDepth;
  float maxDepth;
};

// The lists of the last rendered frame, decoded on the CPU (for tests and tools).
struct TileLightLists {
  uint32_t tilesX = 0;
  uint32_t tilesY = 0;
  uint32_t slices = 1;               // lists per tile: 1, or its depth slices (--lll-slices)
  std::vector<glm::vec2> tileRange;  // nearest and farthest linear depth of each tile's opaque surfaces
  std::vector<std::vector<LightLinkRecord>> lists;  // list tile * slices + slice, head first
};

// Reads the lists back from an "lll" technique; throws std::invalid_argument for another one.
TileLightLists readTileLightLists(Technique& technique);

std::unique_ptr<Technique> createLightLinkedList(Context& context, const GpuScene& scene,
                                                 const RenderSettings& settings, const FrameTargets& targets,
                                                 const VisibilityBuffer* visibility);

}  // namespace lll
