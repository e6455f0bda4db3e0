#pragma once
// --vpl-interleave K: interleaved sampling of the virtual point lights (Keller and Heidrich 2001,
// "Interleaved sampling"; Segovia et al. 2006, "Non-interleaved deferred shading of interleaved
// sample patterns"). The VPLs are split into K*K classes by their ordinal among the VPLs
// (GpuLight's spotParams.y); the opaque pass (lit/shade_visibility_interleaved) lets each pixel
// of a K x K block evaluate one class, writing the lights other than VPLs to hdr as usual and its
// class's VPL light, divided by the surface's albedo key, to an image of its own; the "vpl-filter"
// pass (gi/vpl_filter.comp) then sums, for each pixel, every class's mean over the neighbours
// within K-1 pixels that lie on the same surface and adds the sum times the pixel's albedo key.
// Each pixel evaluates a K*K-th of the VPLs; the light is smoothed over at most 2K-1 pixels and
// does not cross depth or normal edges. Only the opaque shading from the visibility buffer takes
// part: glass and particles still evaluate every VPL.
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "gpu/pipeline.h"
#include "gpu/resources.h"
#include "render/frame.h"
#include "render/lighting_interface.h"

namespace lll {

// The pattern side a frame of `scene` whose opaque surfaces are shaded by `opaque` uses for
// --vpl-interleave `requested`: `requested` where the scene has VPLs at the end of its light array
// (as --gi appends them: their index gives their class) and the shading is the visibility-buffer
// pass; 1 otherwise. LitPasses and lll's class lists both follow it. Throws InputError unless
// 1 <= requested <= kMaxVplInterleave.
uint32_t vplInterleaveIn(const GpuScene& scene, OpaqueShading opaque, uint32_t requested);

class InterleavedVpls {
 public:
  InterleavedVpls(Context& context, const FrameTargets& targets, uint32_t side);

  uint32_t side() const { return side_; }
  // The pattern's side, for the shading pass and the filter (constant_id 33).
  SpecializationConstants constants() const { return {{33, side_}}; }
  // The opaque pass's writes to the per-pixel images (bindings 38 and 39).
  std::vector<ResourceUse> shadingWrites() const;
  DescriptorWriter& bindImages(DescriptorWriter& writer) const;
  // The shading pass's grid: each 8x8 workgroup shades pixels of one class
  // (gi/interleaved_vpls.glsl's interleavedPixel).
  void dispatch(VkCommandBuffer cmd, const FrameTargets& targets) const;
  // The "vpl-filter" pass: the VPL light, gathered, added to hdr.
  void filter(FrameContext& frame);

  std::vector<std::pair<std::string, double>> stats() const;

 private:
  Context& context_;
  uint32_t side_;
  Image indirect_;  // RGBA16F: the class's VPL light over the albedo key, w view depth (-1: none)
  Image key_;       // RGBA32UI: x the view-space normal (octahedral, snorm16 x 2), y z the albedo key
  PipelineLayout layout_;
  Pipeline filter_;
};

}  // namespace lll
