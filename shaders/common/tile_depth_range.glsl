// The nearest and farthest linear depth of each screen tile's opaque surfaces (Harada's tiled
// culling bounds; Bezrati 1.5.1 reduces to the farthest, so a tile never misses a light that touches
// its farthest pixel). Edge tiles read only the pixels that exist. Shared by lll's and the grid's
// tile-depth passes: a workgroup of kCellThreads invocations reduces one cell of kTileGroupSize^2
// tiles (a cell of the light bins, common/light_bins.glsl) and writes each tile's range into
// `tileRange` and the cell's farthest depth into `binCells`, which the binning tests lights against.
//
// The invocations read the cell's rows 64 neighbouring pixels at a time, four rows of tiles at once,
// and meet in shared memory. On the H200 (lll-tile-depth, ms, 1080p tile 8 / tile 16 / 4K tile 8):
// one invocation looping over its own tile's pixels 0.015 / 0.026 / 0.042; 64 invocations a cell,
// a row of tiles each, 0.015 / 0.036 / 0.020; these 256, 0.009 / 0.014 / 0.017.
#ifndef LLL_TILE_DEPTH_RANGE_GLSL
#define LLL_TILE_DEPTH_RANGE_GLSL
#include "common/frame.glsl"

const uint kCellTiles = kTileGroupSize * kTileGroupSize;
const uint kCellThreads = 256u;  // the workgroup: 64 columns of pixels x 4 rows of tiles
// Stored (reverse-Z) depths of each tile, as bits: non-negative floats order like their bits.
shared uint tileNearestBits[kCellTiles];   // the largest stored depth
shared uint tileFarthestBits[kCellTiles];  // the smallest
shared uint cellFarBits;

// Every invocation of the workgroup (kCellThreads of them) must call this.
void reduceCellTileDepths(sampler2D sceneDepth) {
  uint index = gl_LocalInvocationIndex;
  if (index < kCellTiles) {
    tileNearestBits[index] = floatBitsToUint(0.0);
    tileFarthestBits[index] = floatBitsToUint(1.0);
  }
  if (index == 0u) cellFarBits = 0u;
  barrier();
  uint size = frame.counts.y;
  uint span = kTileGroupSize * size;  // the cell's pixels across
  uvec2 origin = gl_WorkGroupID.xy * span;
  uvec2 viewport = uvec2(frame.viewport.xy);
  const uint kColumns = 64u, kPhases = kCellThreads / kColumns;
  for (uint x0 = 0u; x0 < span; x0 += kColumns) {
    uint x = x0 + index % kColumns;  // this invocation's column of the cell
    if (x >= span || origin.x + x >= viewport.x) break;
    for (uint ty = index / kColumns; ty < kTileGroupSize; ty += kPhases) {
      uint y0 = origin.y + ty * size, y1 = min(y0 + size, viewport.y);
      if (y0 >= y1) break;
      float nearest = 0.0, farthest = 1.0;
      for (uint y = y0; y < y1; ++y) {
        float d = texelFetch(sceneDepth, ivec2(origin.x + x, y), 0).r;
        nearest = max(nearest, d);
        farthest = min(farthest, d);
      }
      uint t = ty * kTileGroupSize + x / size;
      atomicMax(tileNearestBits[t], floatBitsToUint(nearest));
      atomicMin(tileFarthestBits[t], floatBitsToUint(farthest));
    }
  }
  barrier();
  uvec2 tile = gl_WorkGroupID.xy * kTileGroupSize + uvec2(index % kTileGroupSize, index / kTileGroupSize);
  if (index < kCellTiles && tile.x < frame.counts.z && tile.y < frame.counts.w) {
    vec2 range = vec2(linearizeDepth(uintBitsToFloat(tileNearestBits[index])),
                      linearizeDepth(uintBitsToFloat(tileFarthestBits[index])));
    tileRange[tile.y * frame.counts.z + tile.x] = range;
    atomicMax(cellFarBits, floatBitsToUint(range.y));
  }
  barrier();
  if (index == 0u) binCells[gl_WorkGroupID.y * gl_NumWorkGroups.x + gl_WorkGroupID.x].farBits = cellFarBits;
}

#endif
