#pragma once
// Coarse light bins: the first level of a two-level light culling (shared/light_bins_types.h).
// Every frame, after the technique's tile-depth pass has written each cell's farthest depth:
//   bins-count   one thread per light counts it in every cell its bounding sphere covers on screen
//                and reaches in depth (bins-count-large: 64 threads per light covering many cells);
//   bins-scan    prefix sum of the counts into each cell's first entry;
//   bins-scatter the same visit appends each light's index to those cells.
// A list build (lll's compute fill, the tiled and clustered grids) then gives each workgroup of
// kTileGroupSize x kTileGroupSize tiles its cell's lights instead of every light, so the build
// costs about what the lights cover, not tiles x lights. The entry array grows on overflow and the
// frame is drawn again (afterFrame), as lll's link pool does: no light is ever dropped.
// With at most kUnbinnedLights lights no bins are built: the header says so (written once, at
// construction), and a build group reads every light, as many as a bin of a full-screen light
// would hold.
#include <algorithm>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "gpu/context.h"
#include "gpu/pipeline.h"
#include "gpu/resources.h"
#include "render/frame.h"
#include "render/frame_graph.h"
#include "shared/light_bins_types.h"

namespace lll {

// Workgroups that share one cell's binned lights in a list build (each takes a part): one per 1,024
// lights, at most kMaxCellSplits. Down a long view a few cells hold most of the lights; with one
// workgroup each they hold up the frame (H200, 1,048,576 lights: lll's fill 31.3 ms with 1,
// 10.2 with 16, 6.1 with 64).
// On a CPU device every cell is split kMaxCellSplits ways whatever the light count: Mesa's
// llvmpipe ends every loop of a shader invocation once its loops have run 65,535 iterations in all
// (LP_MAX_TGSI_LOOP_ITERATIONS, one counter shared by every loop), and a build over a few thousand
// large lights in one cell went past it and dropped lights. Smaller parts keep each invocation
// well under it.
inline constexpr uint32_t kMaxCellSplits = 64;

// The most lights a frame lights without bins. A build group tests 64 lights against its cell's
// volume per step, and ThreeL's 16 and 256 lights reach every cell anyway: there the five passes
// (clear, count, count-large, scan, scatter: 0.035 ms on the H200 at 1080p, each a short dispatch)
// sort nothing out.
inline constexpr uint32_t kUnbinnedLights = 256;
inline uint32_t cellSplitsFor(const Context& context, uint32_t lights) {
  if (context.isCpuDevice()) return kMaxCellSplits;
  return std::clamp<uint32_t>((lights + 1023) / 1024, 1, kMaxCellSplits);
}
// lll's compute fill: a quarter as many workgroups a cell as there are lights, from 4 to 64. With one
// a cell, 1080p at tile 16 is 135 workgroups of 64 invocations, each testing all its cell's lights
// against its tiles in turn: far too few to fill an H200. Measured there at tile 16, 1080p
// (bench/README.md, 2026-12-03), fill ms at 16 / 32 / 64 splits: the atrium's 110 lights 0.027 /
// 0.028 / 0.036; + 1,024 lights 0.100 / 0.069 / 0.061; + 4,096 small ones 0.183 / 0.126 / 0.094;
// + 131,072 tiny ones 1.52 / 0.83 / 0.59; ThreeL's 256 0.173 / 0.164 / 0.097; the atrium's 7,489
// VPLs (K = 3) 1.43 / 1.26 / 1.19. One a cell, 4 and 8 were slower still (the atrium + 1,024: 0.345,
// 0.209, 0.137). Few lights take fewer: each part pushes its own links, so a list is as many runs of
// consecutive links as parts, and ThreeL's 16 lights walk 16 scattered links at 16 parts, one run
// of 4 at 4: shade-opaque 0.243 -> 0.239 ms (4K 0.935 -> 0.913), the fill 0.019 -> 0.022 (4K 0.044
// -> 0.039); at 1 part the fill costs more than that saves (0.042).
inline uint32_t lllFillSplitsFor(const Context& context, uint32_t lights) {
  if (context.isCpuDevice()) return kMaxCellSplits;
  return std::clamp<uint32_t>(lights / 4, 4, kMaxCellSplits);
}

class LightBins {
 public:
  LightBins() = default;
  LightBins(Context& context, uint32_t tilesX, uint32_t tilesY, uint32_t tileSize, uint32_t lightCount);

  // Bindings 11 (header), 12 (cells), 13 (entries) of common/light_bins.glsl.
  void bind(DescriptorWriter& writer) const;
  // What a tile-depth pass writing the cells' farthest depths (binCells[].farBits) declares.
  ResourceUse farDepthWrite(VkPipelineStageFlags2 stages) const;
  // What a list build reading the bins in `stages` declares.
  std::vector<ResourceUse> reads(VkPipelineStageFlags2 stages) const;

  // Pass "bins-clear": zeroes the cells and writes the header. Before the tile-depth pass.
  void clear(FrameContext& frame);
  // Passes bins-count, bins-scan, bins-scatter. After the tile-depth pass.
  void build(FrameContext& frame);
  // Once the frame completed: true when the entries did not fit, with a larger array allocated
  // (throws InputError where no storage buffer of this device could hold them).
  bool afterFrame();

  uint32_t cellsX() const { return header_.cellsX; }
  uint32_t cellsY() const { return header_.cellsY; }
  bool unbinned() const { return header_.unbinned != 0; }  // at most kUnbinnedLights lights
  std::vector<std::pair<std::string, double>> stats() const;

 private:
  void allocate(uint64_t entries);

  Context* context_ = nullptr;
  gpu::LightBinHeader header_{};
  uint64_t maxEntries_ = 0;
  uint32_t lastRequested_ = 0;
  uint32_t overflows_ = 0;
  Buffer headerBuffer_;
  Buffer cells_;
  Buffer entries_;
  Buffer largeLights_;
  PipelineLayout layout_;
  Pipeline count_;
  Pipeline countLarge_;
  Pipeline scan_;
  Pipeline scatter_;
};

}  // namespace lll
