#pragma once
// The visibility buffer's opaque triangles rasterized in compute (--raster compute): on GPUs with
// few graphics-capable units the hardware pass is fragment-bound, and a compute pass can do the
// same work on every unit (Nanite and Schütz's point/triangle rasterizers use this shape).
//
// Four steps, each in the frame graph:
//  - "visibility" (common/raster_triangles.comp): one invocation per triangle transforms, clips,
//    culls and snaps it as the hardware would, then covers a small bounding box itself with a
//    64-bit atomic max of (depth << 32 | id + 1) per pixel, or appends the triangle to a list;
//  - "visibility-bins" (common/raster_bins.comp): a workgroup per listed triangle appends its slot
//    to each 32x32-pixel bin it may cover a pixel centre of;
//  - "visibility-resolve" (common/raster_resolve.comp): one invocation per pixel tests its bin's
//    large triangles against its centre (a workgroup first drops those missing its 8x8 tile and
//    skips the edge tests of those covering all of it), keeps the nearest key, and writes the id
//    image and the depth, as an R32F image (FrameTargets::rasterDepth, which passes that only
//    sample the depth read) and as a buffer, and resets the key for the next frame (the keys are
//    cleared once, not each frame);
//  - the depth buffer is copied into the D32 depth image only if a later pass uses that image (a
//    depth test, the masked primitives, a copy: FrameGraph::produceOnFirstUse). On the H200 the
//    copy took 0.100 ms at 1080p, an image-to-image copy of the same depth 0.004.
// Coverage follows Vulkan's rules (8 sub-pixel bits, top-left edges, counter-clockwise front
// faces), so ids match the hardware pass pixel for pixel up to snapping ties. Alpha-masked
// primitives still go through the hardware pass afterwards (they need their texture).
#include <span>
#include <string>
#include <vector>

#include "gpu/pipeline.h"
#include "gpu/resources.h"
#include "render/frame.h"

namespace lll {

// What a compute rasterization of a width x height image works in (common/raster_triangle.glsl's
// bindings 22 to 25): the 64-bit key per pixel, the large-triangle list, the per-bin lists and the
// resolved depth, with the steps that clear them and copy the depth into a depth image. Shared by
// the visibility buffer's rasterizer and the sun's shadow casters' (shadows/shadow_raster.h).
class RasterWorkspace {
 public:
  static constexpr uint32_t kGroupSize = 64;  // the triangle passes' workgroup
  static constexpr uint32_t kTileSize = 8;    // the resolve passes' workgroup is kTileSize^2
  // Listed large triangles, by default; more are covered in place (by one thread each: slowly).
  static constexpr uint32_t kLargeCapacity = 65536;
  // A triangle whose bounding box has more pixels than this goes to the per-pixel pass. Chosen by
  // measurement on the H200 (bench/README.md): one thread loops over its box, so a large box keeps
  // its SIMD group waiting.
  static constexpr uint32_t kLargestOwnBox = 64;
  static constexpr uint32_t kBinCapacity = 1024;    // listed triangles per bin; a fuller bin tests them all
  static constexpr uint32_t kBinningGroups = 1024;  // the binning passes' workgroups

  // Why `context`'s device cannot rasterize `what` (e.g. "1920x1080") of width x height this way;
  // empty when it can.
  static std::string problem(const Context& context, uint32_t width, uint32_t height,
                             const std::string& what);

  RasterWorkspace() = default;
  // `largeCapacity`: how many large triangles the list holds (an atlas of many views needs more).
  // Without `depthBuffer` the resolve writes its depths elsewhere (an R32F shadow atlas). With
  // `resolveResetsKeys` the resolve clears each key it reads (the shadow casters'): the keys are
  // cleared once here and clear() leaves them alone.
  RasterWorkspace(Context& context, uint32_t width, uint32_t height, const std::string& name,
                  uint32_t largeCapacity = kLargeCapacity, bool depthBuffer = true,
                  bool resolveResetsKeys = false);

  // Bindings 22 (keys), 23 (large triangles), 24 (depth, where there is one) and 25 (bins).
  DescriptorWriter& bind(DescriptorWriter& writer) const;
  // The push constants' `large` (capacity, largest own box, bins per row, bin capacity).
  glm::uvec4 largeParams(uint32_t largestOwnBox = kLargestOwnBox) const;
  // The frame-graph step that clears the list's count, the bins' counts and the keys (unless the
  // resolve resets them).
  void clear(FrameGraph& graph) const;
  // The uses of the triangle pass, of the binning pass, of the per-pixel pass (which writes the
  // depth), and the step that copies the depth into `image` (a D32 image of the same size): all of
  // it, or only `cells`; a GPU-timed pass when `name` is given.
  std::vector<ResourceUse> triangleUses() const;
  std::vector<ResourceUse> binUses() const;
  std::vector<ResourceUse> resolveUses() const;
  void copyDepth(FrameGraph& graph, const Image& image, std::span<const VkRect2D> cells = {},
                 const std::string& name = {}) const;

 private:
  uint32_t width_ = 0;
  uint32_t height_ = 0;
  Buffer keys_;   // uint64 per pixel
  Buffer large_;  // count, then RasterTriangle entries
  Buffer bins_;   // per 32x32-pixel bin: its count of large triangles, then their slots
  Buffer depth_;  // float per pixel, copied into the depth image
  uint32_t largeCapacity_ = kLargeCapacity;
  bool resolveResetsKeys_ = false;
  uint32_t binsPerRow_ = 0;
  uint32_t binCount_ = 0;
};

class ComputeRaster {
 public:
  // Why `context`'s device cannot rasterize a width x height image this way; empty when it can.
  static std::string problem(const Context& context, uint32_t width, uint32_t height);

  ComputeRaster(Context& context, uint32_t width, uint32_t height, uint32_t maxRecords,
                uint32_t triangleBits);

  // The first triangle of each opaque record this frame, written by VisibilityBuffer::prepareFrame:
  // room for maxRecords + 1 entries.
  uint32_t* triangleStarts() const { return static_cast<uint32_t*>(starts_.mapped()); }

  // Rasterizes `triangles` triangles of `records` opaque records (the first `singleSided` of them
  // back-face culled) into frame.targets.visibility and frame.targets.depth.
  void record(FrameContext& frame, const Buffer& surfaceRecords, uint32_t records, uint32_t singleSided,
              uint32_t triangles);
  // Whether the last frame recorded copied the depth into the D32 image (a pass used it).
  bool depthCopied() const { return depthCopied_; }

 private:
  Context& context_;
  PipelineLayout layout_;
  Pipeline triangles_;
  Pipeline bins_;
  Pipeline resolve_;
  Buffer starts_;  // uint per record + 1, rewritten every frame
  RasterWorkspace work_;
  uint32_t largestOwnBox_;  // bounding boxes up to this many pixels are covered by their thread
  bool depthCopied_ = false;
};

}  // namespace lll
