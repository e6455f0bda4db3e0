#pragma once
// --vpl-interleave K: interleaved sampling of the virtual point lights (Keller and Heidrich 2001,
// "Interleaved sampling"; Segovia et al. 2006, "Non-interleaved deferred shading of interleaved
// sample patterns"). The VPLs are split into K*K classes by their ordinal among the VPLs
// (GpuLight's spotParams.y); the opaque pass (lit/shade_visibility_interleaved) lets each pixel
// of a K x K block evaluate one class, writing the lights other than VPLs to hdr as usual and its
// class's VPL light to images of their own: the diffuse lobe divided by the surface's albedo key,
// the specular lobe as it is (it scales with f0, not the albedo); the "vpl-filter" pass
// (gi/vpl_filter.comp) then sums, for each pixel, every class's mean over the neighbours within
// K-1 pixels that lie on the same surface and adds the diffuse sum times the pixel's albedo key and
// the specular sum ("vpl-filter-rows" first sums each pixel's row of 2K-1 where it lies on one
// surface, which the filter adds up down a column instead of gathering where the column does too).
// Each pixel evaluates a K*K-th of the VPLs; the light is smoothed over at most 2K-1 pixels and
// does not cross depth or normal edges. Only the opaque shading from the visibility buffer takes
// part: glass and particles still evaluate every VPL. Glossy metals evaluate every class
// (gi/vpl_interleave_data.glsl): where the lighting interface keeps the classes apart
// (`classesElsewhere`, lll's class lists) shade-opaque gives each such pixel a slot and the
// "vpl-classes" pass lights its classes on a workgroup each (shared/every_class_types.h); else
// the pixel walks them all itself.
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "gpu/pipeline.h"
#include "gpu/resources.h"
#include "render/frame.h"
#include "render/lighting_interface.h"
#include "shared/every_class_types.h"

namespace lll {

// The pattern side a frame of `scene` whose opaque surfaces are shaded by `opaque` uses for
// --vpl-interleave `requested`: `requested` where the scene has VPLs at the end of its light array
// (as --gi appends them: their index gives their class) and the shading is the visibility-buffer
// pass; 1 otherwise. LitPasses and lll's class lists both follow it. Throws InputError unless
// 1 <= requested <= kMaxVplInterleave.
uint32_t vplInterleaveIn(const GpuScene& scene, OpaqueShading opaque, uint32_t requested);

class InterleavedVpls {
 public:
  InterleavedVpls(Context& context, const FrameTargets& targets, uint32_t side, bool classesElsewhere);
  ~InterleavedVpls();
  InterleavedVpls(const InterleavedVpls&) = delete;
  InterleavedVpls& operator=(const InterleavedVpls&) = delete;

  uint32_t side() const { return side_; }
  bool classesElsewhere() const { return classesElsewhere_; }
  // The pattern's side and whether vpl-classes runs, for the shading passes and the filter
  // (constant_id 33, 62).
  SpecializationConstants constants() const { return {{33, side_}, {62, classesElsewhere_ ? 1u : 0u}}; }
  // The opaque pass's writes to the per-pixel images and the slots (bindings 38, 39, 48, 44, 45).
  std::vector<ResourceUse> shadingWrites() const;
  // Empties the slots (before the opaque pass), with classesElsewhere().
  void resetSlots(FrameContext& frame);
  // What vpl-classes reads and writes besides the light data, its bindings (44 to 46) and its
  // indirect dispatch.
  std::vector<ResourceUse> classesUses() const;
  DescriptorWriter& bindSlots(DescriptorWriter& writer) const;
  void dispatchClasses(VkCommandBuffer cmd) const;
  DescriptorWriter& bindImages(DescriptorWriter& writer) const;
  // The shading pass's grid: each 8x8 workgroup shades pixels of one class
  // (gi/interleaved_vpls.glsl's interleavedPixel).
  void dispatch(VkCommandBuffer cmd, const FrameTargets& targets) const;
  // The "vpl-filter-rows" and "vpl-filter" passes: the VPL light, gathered (by rows and columns
  // where the pattern lies on one surface), added to hdr; with classesElsewhere() vpl-filter gives
  // the pixels that lack a class slots after the glossy metals', for vpl-classes to light them.
  void filter(FrameContext& frame);

  std::vector<std::pair<std::string, double>> stats() const;

 private:
  Context& context_;
  uint32_t side_;
  Image indirect_;   // RGBA16F: the class's VPL diffuse light over the albedo key, w view depth (-1: none)
  Image key_;        // RGBA32UI: x the view-space normal (octahedral, snorm16 x 2), y z the class's VPL
                     // specular light over f0 (halves), w 0, 1 for a pixel that evaluated every
                     // class, 2 + its slot for vpl-classes' (what the gather reads of a neighbour)
  Image albedoKey_;  // RGBA32UI: base colour and metallic as halves, roughness (read for the pixel itself)
  Image rowSums_;    // RGBA32UI: vpl-filter-rows' sums (gi/vpl_filter_rows.comp)
  bool classesElsewhere_ = false;
  // Pixels vpl-classes can take, the glossy metals' and then the edge pixels' (vpl-filter); the
  // metals beyond evaluate every class in place, the edge pixels beyond stand the classes they found
  // for the others. One without
  // classesElsewhere(): the shading and filter shaders declare the slots' buffers either way.
  uint32_t slots_ = 1;
  Buffer header_;                       // gpu::EveryClassHeader: vpl-classes' dispatch, the slots taken
  Buffer surfaces_;                     // gpu::EveryClassSurface per slot
  Buffer light_;                        // per slot and class, rgb as halves
  VkSampler nearest_ = VK_NULL_HANDLE;  // vpl-filter's texel fetches
  PipelineLayout rowsLayout_;
  Pipeline rows_;
  PipelineLayout layout_;
  Pipeline filter_;
};

}  // namespace lll
