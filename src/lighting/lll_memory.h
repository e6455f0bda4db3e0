#pragma once
// Memory of the light linked list for a resolution and tile size (`lll lll-memory`): the link pool
// sized for an average list length, plus the head pointers (one per list: per tile, or per depth
// slice of a tile) and each tile's nearest and farthest depth.
#include <cstdint>

#include "render/frame.h"

namespace lll {

struct LllMemory {
  uint32_t tilesX = 0;
  uint32_t tilesY = 0;
  uint64_t links = 0;
  uint64_t poolBytes = 0;   // links * link size
  uint64_t headBytes = 0;   // one uint per list
  uint64_t depthBytes = 0;  // two floats per tile
};

inline LllMemory estimateLllMemory(uint32_t width, uint32_t height, uint32_t tile, uint32_t linksPerTile,
                                   uint32_t linkBytes, uint32_t slices) {
  LllMemory m;
  m.tilesX = divideRoundingUp(width, tile);
  m.tilesY = divideRoundingUp(height, tile);
  const uint64_t tiles = uint64_t(m.tilesX) * m.tilesY;
  m.links = tiles * linksPerTile;
  m.poolBytes = m.links * linkBytes;
  m.headBytes = tiles * slices * 4;
  m.depthBytes = tiles * 8;
  return m;
}

}  // namespace lll
