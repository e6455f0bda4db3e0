// Coarse light bins, shared by C++ and GLSL: the first level of the two-level light culling that
// every tiled technique's list build starts from (lll's compute fill, tiled, clustered).
// The screen is cut into cells of kTileGroupSize x kTileGroupSize tiles (one workgroup of a list
// build); each light is appended to the cells its projected bounding sphere covers, so a build
// group tests the lights of its cell instead of every light: the build costs about what it emits.
#ifndef LLL_LIGHT_BINS_TYPES_H
#define LLL_LIGHT_BINS_TYPES_H
#include "shared/gpu_types.h"

LLL_NAMESPACE_BEGIN

// Written by the bins' clear pass each frame; `requested` counted by the scan, read back.
struct LightBinHeader {
  uint requested;  // entries the scatter asked for, also past `capacity`: the size binLights needs
  uint capacity;   // entries binLights holds
  uint cellsX;     // cells across and down the screen
  uint cellsY;
  uint cellPixels;  // side of a cell in pixels
  uint lightCount;
  uint largeCount;  // lights covering too many cells for one thread, listed by the count pass
  uint unbinned;    // 1: no bins built (few lights, LightBins): every cell holds every light
};
LLL_CHECK_SIZE(LightBinHeader, 32);

// One per cell: x first entry in binLights, y entry count, z scatter cursor, w the farthest linear
// depth (float bits) of the cell's tiles, written by the tile-depth pass of the technique.
struct LightBinCell {
  uint first;
  uint count;
  uint cursor;
  uint farBits;
};
LLL_CHECK_SIZE(LightBinCell, 16);

LLL_NAMESPACE_END
#endif
