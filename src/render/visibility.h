#pragma once
// The visibility buffer (--surfaces visibility): one raster pass writes depth and, per pixel, a
// 32-bit id of the triangle seen there; compute passes then rebuild the surface from the id
// (shaders/common/visibility_surface.glsl: the triangle's vertices, barycentrics from the pixel's
// ray, the material sampled with explicit gradients). The raster pass has a trivial fragment shader
// and reads positions alone; all opaque draws go in one indirect multi-draw per cull mode, and only
// alpha-masked primitives are drawn one by one (they need their material's texture).
//
// Ids: a surface record is one (primitive, visible instance) pair of this frame (gpu::SurfaceRecord);
// a pixel's id is record << triangleBits | triangle, triangleBits enough for the largest primitive.
// A scene whose records and triangles do not fit in 32 bits cannot use it (problem() says so).
//
// The opaque triangles are drawn by the hardware (--raster hardware) or by compute passes that
// follow the same rules (--raster compute, render/compute_raster.h); alpha-masked ones always by
// the hardware.
#include <memory>
#include <string>
#include <vector>

#include "gpu/pipeline.h"
#include "gpu/resources.h"
#include "render/compute_raster.h"
#include "render/frame.h"

namespace lll {

class VisibilityBuffer {
 public:
  // Why `scene` cannot use the visibility buffer on `context`'s device; empty when it can.
  static std::string problem(const Context& context, const GpuScene& scene);

  // With `computeRaster`, opaque triangles are rasterized in compute into a width x height image
  // (ComputeRaster::problem must be empty).
  VisibilityBuffer(Context& context, const GpuScene& scene, bool computeRaster = false, uint32_t width = 0,
                   uint32_t height = 0);
  ~VisibilityBuffer();

  // After GpuScene::prepareFrame: this frame's surface records, draw commands and record bases.
  void prepareFrame(const GpuScene& scene);
  // The "visibility" pass: clears and writes frame.targets.depth and frame.targets.visibility.
  void record(FrameContext& frame) const;

  // What common/visibility_surface.glsl reads, at its bindings (16 to 20).
  void bindSurfaceData(DescriptorWriter& writer, const FrameContext& frame) const;
  // Its specialization constants (the id layout, the texture table's length, whether the scene's
  // vertices have TEXCOORD_1 that a material reads and colours).
  SpecializationConstants surfaceConstants(const GpuScene& scene) const;
  // The variant of `shader` (a name ending in ".comp" that includes visibility_surface.glsl) this
  // device runs: "<name>_nonuniform.comp" where it indexes the texture table non-uniformly, which
  // saves the workgroup's loop over its materials.
  std::string surfaceShader(const std::string& shader) const;
  uint32_t triangleBits() const { return triangleBits_; }
  uint32_t recordCount() const { return recordCount_; }
  bool computeRaster() const { return compute_ != nullptr; }
  // With the compute rasterizer: whether the last frame needed its depth copied into the D32 image.
  bool rasterDepthCopied() const { return compute_ && compute_->depthCopied(); }
  // Whether the scene has opaque alpha-masked draws: with the compute rasterizer they are drawn by
  // the hardware into the D32 depth afterwards, so its R32F depth misses them.
  bool hasMaskedDraws() const { return hasMaskedDraws_; }

 private:
  struct MaskedDraw {
    uint32_t draw;  // index into GpuScene::draws()
    uint32_t recordBase;
  };

  // The alpha-masked draws, one by one, into the bound attachments.
  void drawMasked(VkCommandBuffer cmd, const FrameContext& frame) const;

  Context& context_;
  bool hasMaskedDraws_ = false;
  uint32_t triangleBits_ = 0;
  PipelineLayout layout_;
  PipelineLayout maskedLayout_;
  Pipeline opaque_;
  Pipeline masked_;
  Buffer records_;   // gpu::SurfaceRecord, rewritten every frame
  Buffer commands_;  // VkDrawIndexedIndirectCommand: single-sided draws, then double-sided ones
  Buffer bases_;     // each command's first record
  uint32_t singleSided_ = 0;
  uint32_t doubleSided_ = 0;
  std::vector<MaskedDraw> maskedDraws_;
  uint32_t recordCount_ = 0;
  uint32_t singleSidedRecords_ = 0;  // records of single-sided opaque primitives come first,
  uint32_t opaqueRecords_ = 0;       // then double-sided ones, then masked ones
  uint32_t triangleCount_ = 0;       // opaque triangles this frame (the compute rasterizer's work)  // opaque
                                     // triangles this frame (the compute rasterizer's work)
  std::unique_ptr<ComputeRaster> compute_;
};

}  // namespace lll
