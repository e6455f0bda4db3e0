#pragma once
// The passes every technique shares, written once and compiled with each technique's lighting
// interface (render/lighting_interface.h):
//   shade-opaque   opaque surfaces, unless the technique lights them itself: in compute from the
//                  visibility buffer, in compute over the thin G-buffer (after a "gbuffer" pass),
//                  or per fragment of a geometry pass
//   glass          blended primitives at their own depth, farthest first: with --glass compute
//                  (the default) a "glass-fragments" geometry pass stores each pixel's glass
//                  fragments, "glass-groups" lists the 8x8-pixel groups that have some, and a
//                  compute pass lights and blends them there (shared/glass_types.h); where the
//                  lighting interface splits a point's lights into parts (lll's VPL classes),
//                  "glass-light" lights each part of those groups on workgroups of its own first;
//                  with --glass raster a geometry pass lights each fragment and blends it
//   vpl-filter     with --vpl-interleave K > 1, a scene with VPLs and opaque surfaces from the
//                  visibility buffer: shade-opaque evaluates a K*K-th of the VPLs per pixel and this
//                  (after "vpl-filter-rows") gathers the rest (render/interleaved_vpls.h); after it,
//                  where the interface keeps the classes apart (lll), "vpl-classes" lights the
//                  glossy metals' and the edge pixels' classes
// (particles are drawn by the particle system with the same interface: particles/particle_system.h).
// Where shade-opaque and the compute glass write the frame's last colours (writesDisplay()), they
// also write its display image (post/display.glsl), and the renderer records no tonemap pass.
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "gpu/pipeline.h"
#include "render/frame.h"
#include "render/gbuffer.h"
#include "render/interleaved_vpls.h"
#include "render/lighting_interface.h"
#include "shared/glass_types.h"

namespace lll {

class LitPasses {
 public:
  LitPasses(Context& context, const GpuScene& scene, const FrameTargets& targets,
            const VisibilityBuffer* visibility, OpaqueShading opaque, LightingInterface lighting,
            bool computeGlass, uint32_t vplInterleave = 1, bool lastShading = false);
  ~LitPasses();
  LitPasses(const LitPasses&) = delete;
  LitPasses& operator=(const LitPasses&) = delete;

  // Opaque shading (nothing for OpaqueShading::Own).
  void shadeOpaque(FrameContext& frame);
  // The blended primitives over the lit frame.
  void shadeGlass(FrameContext& frame);
  // Whether these passes write the display image (frame.targets.ldr) as well as hdr: asked for
  // with `lastShading` (no pass after them changes hdr), and possible where shade-opaque is the
  // visibility buffer's compute pass with no VPL gather after it and any glass is lit in compute.
  bool writesDisplay() const { return writesDisplay_; }
  // The lighting interface these passes were compiled with.
  const LightingInterface& lighting() const { return lighting_; }

  // Called once the frame's GPU work completed: true when the glass fragments overflowed their pool,
  // which has grown, and the frame must be drawn again.
  bool afterFrame();

  // Memory this owns and the glass fragments' counts, for --stats and the bench.
  std::vector<std::pair<std::string, double>> stats() const;

 private:
  DescriptorWriter litDescriptors(const FrameContext& frame) const;
  // The compute pass with `writer`'s bindings and hdr.
  void dispatch(FrameContext& frame, VkCommandBuffer cmd, DescriptorWriter& writer);
  // A geometry pass onto hdr (cleared first when `clearHdr`), depth-tested against the depth pass.
  void drawGeometry(FrameContext& frame, const Pipeline& pipeline, DrawFilter filter, bool clearHdr);

  Context& context_;
  OpaqueShading opaque_;
  bool writesDisplay_ = false;
  LightingInterface lighting_;
  double pixels_;
  PipelineLayout computeLayout_;
  Pipeline compute_;
  std::unique_ptr<GBuffer> gbuffer_;
  std::unique_ptr<InterleavedVpls> interleaved_;
  // vpl-classes (InterleavedVpls::classesElsewhere): the glossy metals' VPL classes.
  PipelineLayout vplClassesLayout_;
  Pipeline vplClasses_;
  VkSampler depthSampler_ = VK_NULL_HANDLE;
  PipelineLayout meshLayout_;
  Pipeline geometryOpaque_;
  Pipeline glass_;

  // --glass compute: the fragment lists and their passes.
  void allocateGlassPool(uint64_t fragments);
  void shadeGlassInCompute(FrameContext& frame);
  DescriptorWriter& bindGlassLists(DescriptorWriter& writer) const;
  bool computeGlass_ = false;
  // glass-fragments compares each fragment with the compute rasterizer's depth itself, with no
  // depth attachment (FrameTargets::rasterDepthComplete): that frame needs no D32 copy.
  bool glassTestsDepth_ = false;
  PipelineLayout glassFragmentsLayout_;
  Pipeline glassFragments_;
  PipelineLayout glassLayout_;
  Pipeline glassCompute_;
  // LightingInterface::listParts > 1: glass-light's pipeline and its light per fragment and part.
  uint32_t glassParts_ = 1;
  PipelineLayout glassLightLayout_;
  Pipeline glassLight_;
  Buffer glassPartLight_;
  Buffer glassHeads_, glassNodes_, glassNext_, glassCounters_;
  // A flag per 8x8-pixel group with glass fragments, then the list of those groups (glass-groups
  // makes it, and the glass pass's indirect dispatch, glassDispatch_, from the flags and clears
  // them). The flags and glassHeads_ are cleared whole once, then by those passes.
  Buffer glassGroups_, glassDispatch_;
  PipelineLayout glassGroupsLayout_;
  Pipeline glassGroupsPipeline_;
  bool glassListsCleared_ = false;
  uint64_t glassCapacity_ = 0;
  gpu::GlassCounters lastGlass_{};
  uint32_t glassOverflows_ = 0;
};

}  // namespace lll
